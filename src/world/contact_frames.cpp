// The contact-frame stage (SPEC 5): world, body, auto and texture frame modes.
#include "world/contact_frames.hpp"

#include <cmath>

#include "asperity/world/world.hpp"
#include "dynamics/texture_axis.hpp"
#include "parallel/thread_pool.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

Vec3 projectedTangent(const Vec3& n, const Vec3& axis, const Vec3& fallback) {
  // Remove the normal component; a vanishing projection falls back to the next axis.
  const Vec3 t = axis - axis.dot(n) * n;
  if (t.norm() > 1e-6 * axis.norm() && t.norm() > 0.0) return t.normalized();
  const Vec3 f = fallback - fallback.dot(n) * n;
  if (f.norm() > 1e-6 * fallback.norm() && f.norm() > 0.0) return f.normalized();
  // Last resort: any perpendicular (n has a component below 0.6 on some axis).
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  return n.cross(helper).cross(n).normalized();
}

void setContactFrame(Contact& c, const Vec3& desired_t, const Vec3& fallback) {
  c.t = projectedTangent(c.normal, desired_t, fallback);
  c.b = c.normal.cross(c.t);  // SPEC 1: right-handed (t, b, n)
}

void World::computeFrames() {
  const Vec3& axis = settings_.world_axis;
  const Vec3& fallback = settings_.fallback_axis;
  // Each contact's frame alone, so threads may share the contacts; a user's frame callback
  // is only ever called from this thread.
  const bool user_code = settings_.frame_mode == FrameMode::Body && frame_callback_;
  const size_t grain = user_code ? contacts_.size() : 64;
  pool_->forEach(contacts_.size(), grain, [&](size_t i) {
    Contact& c = contacts_[i];
    Vec3 desired = axis;
    switch (settings_.frame_mode) {
      case FrameMode::World:
      case FrameMode::Auto:  // refined below from the sliding velocities
        break;
      case FrameMode::Body: {
        // A's body-local axis, else B's, else the world's callback, else the world axis.
        const Body& a = bodies_[c.body_a];
        const Body& b = bodies_[c.body_b];
        if (a.frame_axis.squaredNorm() > 0.0) {
          desired = a.pose.rotation * a.frame_axis;
        } else if (b.frame_axis.squaredNorm() > 0.0) {
          desired = b.pose.rotation * b.frame_axis;
        } else if (frame_callback_) {
          desired = frame_callback_(*this, c);
        }
        break;
      }
      case FrameMode::Texture: {
        // +u of B's surface (the surface facing +n); world frame where it has no mapping.
        const auto u = textureAxisWorld(bodies_[c.body_b], c.shape_b, c.feature_b, c.witness_b);
        if (u) desired = *u;
        break;
      }
    }
    setContactFrame(c, desired, fallback);
  });
  if (settings_.frame_mode == FrameMode::Auto) alignFramesWithSliding();
}

void World::alignFramesWithSliding() {
  // A few frictionless PGS iterations predict each contact's sliding velocity (SPEC 5, auto).
  solver_->begin(bodies_, solverSettings());
  solver_->setJoints(solverJoints(time_, settings_.dt));
  solver_->setContacts(contacts_, false);
  solver_->iterate(settings_.auto_frame_iterations);
  for (Contact& c : contacts_) {
    const Vec3 va =
        solver_->linearVelocity(c.body_a) +
        solver_->angularVelocity(c.body_a).cross(c.point - bodies_[c.body_a].pose.position);
    const Vec3 vb =
        solver_->linearVelocity(c.body_b) +
        solver_->angularVelocity(c.body_b).cross(c.point - bodies_[c.body_b].pose.position);
    const Vec3 v = va - vb;
    const Vec3 sliding = v - v.dot(c.normal) * c.normal;
    // t along A's sliding relative to B; slow contacts keep the world frame.
    if (sliding.norm() > settings_.auto_frame_speed) {
      setContactFrame(c, sliding, settings_.fallback_axis);
    }
  }
}

}  // namespace asperity
