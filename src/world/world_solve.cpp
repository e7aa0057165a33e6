// The middle stages of a step: collision, friction coefficients and the constraint solve.
#include <algorithm>

#include "asperity/collision/collision_detector.hpp"
#include "asperity/world/world.hpp"

namespace asperity {

namespace {

// The smallest extent of a shape (m), the scale its contact tolerances follow.
double shapeExtent(const Shape& s) {
  switch (s.type) {
    case ShapeType::Box:
      return 2.0 * s.half_extents.minCoeff();
    case ShapeType::Sphere:
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
      return 2.0 * s.radius;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh: {
      if (!s.mesh || s.mesh->vertices.empty()) return 0.0;
      Vec3 lo = s.mesh->vertices.front(), hi = lo;
      for (const Vec3& v : s.mesh->vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      return (hi - lo).minCoeff();
    }
    case ShapeType::Plane:
      break;
  }
  return 0.0;
}

}  // namespace

double World::automaticSlop() const {
  // 0.2 % of the smallest dynamic shape: 0.4 mm for 0.2 m cubes, 8 um for an M4 nut.
  double smallest = 0.0;
  for (const Body& b : bodies_) {
    if (!b.isDynamic()) continue;
    for (const Shape& s : b.shapes) {
      const double e = shapeExtent(s);
      if (e > 0.0 && (smallest == 0.0 || e < smallest)) smallest = e;
    }
  }
  return 0.002 * smallest;
}

void World::collide() {
  // Collision objects are rebuilt only when bodies or ignored pairs changed.
  if (bodies_changed_) {
    collision_->setBodies(bodies_, CollisionSettings{settings_.contact_margin});
    slop_ = automaticSlop();
    bodies_changed_ = false;
  }
  collision_->setSpeculativeTime(settings_.dt);
  collision_->detect(bodies_, contacts_);
}

void World::computeFriction() {
  if (contacts_.empty()) return;
  provider_->computeCoefficients(bodies_, contacts_, settings_.friction);
}

SolverSettings World::solverSettings() const {
  SolverSettings s;
  s.dt = settings_.dt;
  s.limit_surface = settings_.limit_surface;
  s.coulomb_mu = settings_.friction.mu0;  // SPEC 4: Coulomb uses mu0 alone
  s.baumgarte = settings_.baumgarte;
  s.slop = settings_.linear_slop > 0.0 ? settings_.linear_slop : slop_;
  s.max_correction_speed = settings_.max_correction_speed;
  s.warm_starting = settings_.warm_starting;
  return s;
}

std::span<const SolverJoint> World::solverJoints() {
  // Anchors and axes move from the descriptions' body frames to the centre-of-mass frames.
  solver_joints_.resize(joints_.size());
  const double dt = settings_.dt;
  for (size_t i = 0; i < joints_.size(); ++i) {
    const JointDesc& j = joints_[i];
    const Body& a = bodies_[j.body_a];
    const Body& b = bodies_[j.body_b];
    SolverJoint& s = solver_joints_[i];
    s.type = j.type;
    s.body_a = j.body_a;
    s.body_b = j.body_b;
    s.anchor_a = a.com_offset.applyInverse(j.anchor_a);
    s.anchor_b = b.com_offset.applyInverse(j.anchor_b);
    s.axis_a = a.com_offset.rotation.conjugate() * j.axis_a;
    s.axis_b = b.com_offset.rotation.conjugate() * j.axis_b;
    s.rest_rotation = joint_rest_rotation_[i];
    // Distance: the length now and its rate over this step (the worm's muscles).
    s.length = distanceJointLength(j, time_);
    s.length_rate = (distanceJointLength(j, time_ + dt) - s.length) / dt;
  }
  return solver_joints_;
}

void World::solve() {
  solver_->begin(bodies_, solverSettings());
  solver_->setJoints(solverJoints());
  solver_->setContacts(contacts_, true);
  solver_->iterate(settings_.iterations);
  solver_->finish(bodies_, contacts_);
}

}  // namespace asperity
