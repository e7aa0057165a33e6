// Frame mode Auto (SPEC 5): t along the sliding velocity that a few frictionless PGS iterations
// predict, so the friction coefficients are sampled where the contact is about to slide.
#include "frames/frame_modes.hpp"

namespace asperity {

void alignFramesWithSliding(const FrameInputs& in, std::span<Contact> contacts) {
  // Without a prediction (an engine's contacts handed in alone) the world frames stay.
  if (!in.predict_velocities) return;
  const PredictedVelocities predicted = in.predict_velocities(contacts);
  auto pointVelocity = [&](BodyId id, const Vec3& p) {
    return Vec3(predicted.linear[id] +
                predicted.angular[id].cross(p - in.bodies[id].pose.position));
  };
  for (Contact& c : contacts) {
    const Vec3 v = pointVelocity(c.body_a, c.point) - pointVelocity(c.body_b, c.point);
    const Vec3 sliding = v - v.dot(c.normal) * c.normal;
    // t along A's sliding relative to B; slow contacts keep the world frame.
    if (sliding.norm() > in.sliding_speed) setContactFrame(c, sliding, in.fallback_axis);
  }
}

}  // namespace asperity
