// Private: the random height field behind the `roughness` generator, exposed for its tests.
#pragma once

#include <cstdint>

#include "texture/height_field.hpp"

namespace asperity::texgen {

// Heights in mm, i.i.d. Gaussian per texel with mean absolute deviation ra_mm
// (Ra = sigma * sqrt(2 / pi), Sec. 5.1).
Field roughnessHeightsMm(double ra_mm, int size, uint64_t seed);

}  // namespace asperity::texgen
