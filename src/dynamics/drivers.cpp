// Stage 1 of a step: gravity, springs and loads (dynamics/drivers.hpp).
#include "dynamics/drivers.hpp"

#include <Eigen/LU>

namespace asperity {

namespace {

// Torque-free rotation over dt with the gyroscopic term w x I w taken implicitly (one Newton
// step in the body frame, as Bullet and Box2D do): stable at large spin rates.
Vec3 gyroscopicStep(const Body& body, const Vec3& w_world, double dt) {
  const Vec3 inertia = body.inverse_inertia_local.cwiseInverse();
  const Quat& q = body.pose.rotation;
  const Vec3 w = q.conjugate() * w_world;
  const Vec3 iw = inertia.cwiseProduct(w);
  const Vec3 f = dt * w.cross(iw);
  const Mat3 jacobian =
      Mat3(inertia.asDiagonal()) + dt * (skew(w) * inertia.asDiagonal() - skew(iw));
  return q * (w - jacobian.partialPivLu().solve(f));
}

// Whether time t0 <= start < t0 + dt (half-open, so an impulse fires exactly once).
bool firesThisStep(double start, double t0, double dt) {
  const double eps = 1e-9 * dt;
  return start >= t0 - eps && start < t0 + dt - eps;
}

// Adds a force at a world point to the body's accumulators.
void addForce(Body& body, const Vec3& force, const Vec3& point) {
  body.force += force;
  body.torque += (point - body.pose.position).cross(force);
}

}  // namespace

void applyDrivers(std::span<Body> bodies, std::span<const SpringDesc> springs,
                  std::span<const LoadDesc> loads, const Vec3& gravity, double time, double dt) {
  for (Body& b : bodies) {
    b.force.setZero();
    b.torque.setZero();
  }
  // Springs: f = k (target(t) - p) - c (v_p - v_target) at the attachment point.
  for (const SpringDesc& s : springs) {
    Body& b = bodies[s.body];
    const Vec3 p = b.descriptionPose().apply(s.local_point);
    const Vec3 f = s.stiffness * (springTarget(s, time) - p) -
                   s.damping * (b.pointVelocity(p) - s.target_velocity);
    addForce(b, f, p);
  }
  // Loads: forces and torques while active; impulses once, straight into the velocities.
  for (const LoadDesc& l : loads) {
    Body& b = bodies[l.body];
    if (!b.isDynamic()) continue;
    const Vec3 p = b.descriptionPose().apply(l.local_point);
    const bool active = time >= l.start - 1e-9 * dt && time < l.end - 1e-9 * dt;
    switch (l.kind) {
      case LoadDesc::Kind::Force:
        if (active) addForce(b, l.value, p);
        break;
      case LoadDesc::Kind::Torque:
        if (active) b.torque += l.value;
        break;
      case LoadDesc::Kind::Impulse:
        if (!firesThisStep(l.start, time, dt)) break;
        b.linear_velocity += b.inverse_mass * l.value;
        b.angular_velocity += b.inverseInertiaWorld() * (p - b.pose.position).cross(l.value);
        break;
      case LoadDesc::Kind::AngularImpulse:
        if (firesThisStep(l.start, time, dt)) {
          b.angular_velocity += b.inverseInertiaWorld() * l.value;
        }
        break;
    }
  }
  // v += dt (g + F/m); w += dt I^-1 tau, then the implicit gyroscopic step.
  for (Body& b : bodies) {
    if (!b.isDynamic()) continue;
    b.linear_velocity += dt * (gravity + b.inverse_mass * b.force);
    b.angular_velocity += dt * (b.inverseInertiaWorld() * b.torque);
    // Isotropic inertia (cubes, spheres) has no gyroscopic torque.
    const Vec3& inv_i = b.inverse_inertia_local;
    if (inv_i.maxCoeff() - inv_i.minCoeff() > 1e-12 * inv_i.maxCoeff()) {
      b.angular_velocity = gyroscopicStep(b, b.angular_velocity, dt);
    }
  }
}

}  // namespace asperity
