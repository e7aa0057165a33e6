// The last stage of a step: poses from velocities (dynamics/integrate.hpp).
#include "dynamics/integrate.hpp"

#include <cmath>

#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

// q' = exp(w dt / 2) q, normalised.
Quat rotate(const Quat& q, const Vec3& w, double dt) {
  const double angle = w.norm() * dt;
  if (!(angle > 1e-15)) return q;
  return (Quat(Eigen::AngleAxisd(angle, w.normalized())) * q).normalized();
}

}  // namespace

void integratePoses(std::span<Body> bodies, std::span<const Vec3> pseudo_linear,
                    std::span<const Vec3> pseudo_angular, double dt, const ThreadPool* pool) {
  // Each body moves alone: any split over threads gives the same poses.
  forEachOn(pool, bodies.size(), 256, [&](size_t i) {
    Body& b = bodies[i];
    if (b.type == BodyType::Static) return;
    // Dynamic bodies also move by the split-impulse pseudo-velocities (then forgotten).
    Vec3 v = b.linear_velocity;
    Vec3 w = b.angular_velocity;
    if (b.isDynamic()) {
      v += pseudo_linear[i];
      w += pseudo_angular[i];
    }
    b.pose.position += dt * v;
    b.pose.rotation = rotate(b.pose.rotation, w, dt);
  });
}

}  // namespace asperity
