// Frame mode World (SPEC 5): t is the world axis projected on the contact plane.
#include "frames/frame_modes.hpp"

namespace asperity {

Vec3 worldFrameTangent(const FrameInputs& in, const Contact& /*c*/) {
  return in.world_axis;
}

}  // namespace asperity
