// Frame mode Texture (SPEC 5): t follows the texture of the surface the contact lies on.
#include "dynamics/texture_axis.hpp"
#include "frames/frame_modes.hpp"

namespace asperity {

Vec3 textureFrameTangent(const FrameInputs& in, const Contact& c) {
  // +u of B's surface (the surface facing +n); the world frame where it has no mapping.
  const auto u = textureAxisWorld(in.bodies[c.body_b], c.shape_b, c.feature_b, c.witness_b);
  return u ? *u : in.world_axis;
}

}  // namespace asperity
