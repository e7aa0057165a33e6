// Frame mode Body (SPEC 5): a body-local axis carried by the body, or the user's callback.
#include "frames/frame_modes.hpp"

namespace asperity {

Vec3 bodyFrameTangent(const FrameInputs& in, const Contact& c) {
  // A's body-local axis, else B's, else the world's callback, else the world axis.
  const Body& a = in.bodies[c.body_a];
  const Body& b = in.bodies[c.body_b];
  if (a.frame_axis.squaredNorm() > 0.0) return a.pose.rotation * a.frame_axis;
  if (b.frame_axis.squaredNorm() > 0.0) return b.pose.rotation * b.frame_axis;
  if (in.callback) return in.callback(c);
  return in.world_axis;
}

}  // namespace asperity
