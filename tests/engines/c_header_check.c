/* The C header compiles as C (not only as C++) and its defaults fill every field. */
#include "asperity/c/contact_friction.h"

int asperity_c_header_check(void) {
  asperity_friction_settings settings;
  asperity_shape shape;
  asperity_friction_default_settings(&settings);
  asperity_friction_default_shape(&shape);
  return settings.directions == 4 && shape.type == ASPERITY_SHAPE_BOX ? 1 : 0;
}
