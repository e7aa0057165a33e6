// The world's data handed to the middle stages of a step: collision, contact frames, friction
// coefficients and the constraint solve (sub-steps included).
#include <algorithm>
#include <chrono>

#include "asperity/error.hpp"
#include "asperity/world/world.hpp"
#include "collision/bullet_shapes.hpp"
#include "collision/collision_detector.hpp"
#include "dynamics/integrate.hpp"
#include "frames/contact_frames.hpp"
#include "parallel/thread_pool.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

double World::automaticSlop() const {
  // 0.2 % of the smallest dynamic shape: 0.4 mm for 0.2 m cubes, 8 um for an M4 nut.
  double smallest = 0.0;
  for (const Body& b : bodies_) {
    if (!b.isDynamic()) continue;
    for (const Shape& s : b.shapes) {
      const double e = collision_detail::shapeSize(s);
      if (e > 0.0 && (smallest == 0.0 || e < smallest)) smallest = e;
    }
  }
  return 0.002 * smallest;
}

double World::prepare() {
  // Collision objects are rebuilt only when bodies or ignored pairs changed.
  if (!bodies_changed_) return 0.0;
  const auto start = std::chrono::steady_clock::now();
  collision_->setBodies(bodies_, CollisionSettings{settings_.contact_margin});
  slop_ = automaticSlop();
  bodies_changed_ = false;
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void World::collide() {
  prepare();
  collision_->setSpeculativeTime(settings_.dt);
  collision_->detect(bodies_, contacts_, pool_.get());
}

FrameInputs World::frameInputs() {
  FrameInputs in;
  in.bodies = bodies_;
  in.world_axis = settings_.world_axis;
  in.fallback_axis = settings_.fallback_axis;
  if (frame_callback_) in.callback = [this](const Contact& c) { return frame_callback_(*this, c); };
  in.frictionless_solve = [this](std::span<const Contact> contacts) -> const ContactSolver& {
    beginSolve(time_, settings_.dt);
    solver_->setContacts(contacts, false);
    solver_->iterate(settings_.auto_frame_iterations);
    return *solver_;
  };
  in.sliding_speed = settings_.auto_frame_speed;
  return in;
}

void World::computeFriction() {
  contact_rows_ready_ = false;
  if (contacts_.empty()) return;
  provider_->startCoefficients(bodies_, contacts_, settings_.friction);
  // While a provider on another device (the gl sampler's GPU) works, the solver sets up the
  // contact rows, which need no coefficients (one solve per step only: sub-steps move the
  // contacts between solves).
  if (provider_->runsAsynchronously() && settings_.substeps == 1) {
    beginSolve(time_, settings_.dt);
    solver_->setContactRows(contacts_);
    contact_rows_ready_ = true;
  }
  provider_->finishCoefficients();
}

SolverSettings World::solverSettings() const {
  SolverSettings s;
  s.dt = substepDt();
  s.limit_surface = settings_.limit_surface;
  s.coulomb_mu = settings_.friction.mu0;  // SPEC 4: Coulomb uses mu0 alone
  s.baumgarte = settings_.baumgarte;
  s.slop = settings_.linear_slop > 0.0 ? settings_.linear_slop : slop_;
  s.max_correction_speed = settings_.max_correction_speed;
  s.warm_starting = settings_.warm_starting;
  return s;
}

std::span<const SolverJoint> World::solverJoints(double t, double dt) {
  // Anchors and axes move from the descriptions' body frames to the centre-of-mass frames.
  solver_joints_.resize(joints_.size());
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
    // Distance: the length at t and its rate over the solve's dt (the worm's muscles).
    s.length = distanceJointLength(j, t);
    s.length_rate = (distanceJointLength(j, t + dt) - s.length) / dt;
  }
  return solver_joints_;
}

void World::beginSolve(double t, double h) {
  solver_->begin(bodies_, solverSettings());
  solver_->setJoints(solverJoints(t, h));
}

void World::solveOnce(double t, double h) {
  if (contact_rows_ready_) {
    contact_rows_ready_ = false;
    solver_->setContactLimits(contacts_);
  } else {
    beginSolve(t, h);
    solver_->setContacts(contacts_, true);
  }
  solver_->iterate(settings_.iterations);
  solver_->finish(bodies_, contacts_);
}

void World::solve() {
  if (settings_.substeps < 1) throw Error("world settings: substeps must be >= 1");
  if (settings_.substeps == 1) {
    solveOnce(time_, settings_.dt);
  } else {
    solveSubsteps();
  }
}

void World::moveContacts(std::span<const Contact> base, std::span<const Transform> start) {
  // Each contact's witness point rides on both bodies (rigidly from the poses at collision);
  // the depth changes by their relative motion along the fixed normal (n from B to A).
  for (size_t i = 0; i < base.size(); ++i) {
    const Contact& c0 = base[i];
    auto carried = [&](BodyId id) {
      const Transform& s = start[id];
      const Transform& now = bodies_[id].pose;
      return Vec3(now.position + now.rotation * (s.rotation.conjugate() * (c0.point - s.position)));
    };
    const Vec3 pa = carried(c0.body_a), pb = carried(c0.body_b);
    Contact& c = contacts_[i];
    c.point = 0.5 * (pa + pb);
    c.phi = c0.phi - c0.normal.dot(pa - pb);
  }
}

void World::solveSubsteps() {
  // Sub-stepping: `substeps` solves of h = dt / substeps on the one set of contacts, positions
  // integrated between them (the last by the integrate stage). Smaller steps leave PGS less to
  // converge per solve: light links between heavy ends stop creeping (tests/world/
  // chain_rod_test.cpp). The drivers gave the whole step's acceleration; each sub-step gets
  // its share (impulses and the gyroscopic step stay in the first).
  const int n = settings_.substeps;
  const double h = substepDt();
  std::vector<Vec3> dv(bodies_.size(), Vec3::Zero()), dw(bodies_.size(), Vec3::Zero());
  std::vector<Transform> start(bodies_.size());
  for (size_t i = 0; i < bodies_.size(); ++i) {
    Body& b = bodies_[i];
    start[i] = b.pose;
    if (!b.isDynamic()) continue;
    dv[i] = h * (settings_.gravity + b.inverse_mass * b.force);
    dw[i] = h * (b.inverseInertiaWorld() * b.torque);
    b.linear_velocity -= (n - 1) * dv[i];
    b.angular_velocity -= (n - 1) * dw[i];
  }
  const std::vector<Contact> base = contacts_;
  // (lambda_n, lambda_t, lambda_b) summed over the sub-steps.
  std::vector<Vec3> impulse(contacts_.size(), Vec3::Zero());
  for (int k = 0; k < n; ++k) {
    // Later sub-steps: their share of the acceleration, the contacts carried along.
    if (k > 0) {
      integratePoses(bodies_, *solver_, h, *pool_);
      for (size_t i = 0; i < bodies_.size(); ++i) {
        if (!bodies_[i].isDynamic()) continue;
        bodies_[i].linear_velocity += dv[i];
        bodies_[i].angular_velocity += dw[i];
      }
      moveContacts(base, start);
    }
    solveOnce(time_ + k * h, h);
    for (size_t i = 0; i < contacts_.size(); ++i) {
      impulse[i] += Vec3(contacts_[i].lambda_n, contacts_[i].lambda_t, contacts_[i].lambda_b);
    }
  }
  // Contacts report the collision's geometry and the step's impulses.
  for (size_t i = 0; i < contacts_.size(); ++i) {
    contacts_[i].point = base[i].point;
    contacts_[i].phi = base[i].phi;
    contacts_[i].lambda_n = impulse[i].x();
    contacts_[i].lambda_t = impulse[i].y();
    contacts_[i].lambda_b = impulse[i].z();
  }
}

}  // namespace asperity
