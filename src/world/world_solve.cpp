// The world's data handed to the stages of a step: collision, contact frames, friction
// coefficients, the solve stage (src/solver/solve_stage.hpp) and integration.
#include <chrono>

#include "asperity/error.hpp"
#include "asperity/world/state_check.hpp"
#include "asperity/world/world.hpp"
#include "collision/bullet_shapes.hpp"
#include "collision/collision_detector.hpp"
#include "dynamics/integrate.hpp"
#include "parallel/thread_pool.hpp"
#include "solver/solve_stage.hpp"

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
  collision_->setMaxPairs(settings_.max_pairs);
  try {
    collision_->detect(bodies_, contacts_, pool_.get());
  } catch (const TooManyPairsError& e) {
    // The step being taken (counted as checkWorldState counts it), the bodies by name.
    std::string names;
    for (const BodyId id : e.bodies())
      names += (names.empty() ? "\"" : ", \"") + bodies_[id].name + "\"";
    throw StepError("step " + std::to_string(steps_ + 1) + ": " + e.what() + " in " + names +
                        "; likely cause: bodies placed in one another (raise max_pairs if the "
                        "scene means it)",
                    e.bodies().empty() ? kNoBody : e.bodies().front(), steps_ + 1);
  }
}

FrameInputs World::frameInputs() {
  FrameInputs in;
  in.bodies = bodies_;
  in.world_axis = settings_.frame.world_axis;
  in.fallback_axis = settings_.frame.fallback_axis;
  if (frame_callback_) in.callback = [this](const Contact& c) { return frame_callback_(*this, c); };
  // Frame mode Auto predicts the sliding with the solver's frictionless iterations.
  in.predict_velocities = [this](std::span<const Contact> contacts) {
    return predictFrictionless(*solver_, solveInputs(), contacts, settings_.auto_frame_iterations);
  };
  in.sliding_speed = settings_.frame.sliding_speed;
  return in;
}

void World::computeFriction() {
  // Only started here: the solve stage builds its rows, then awaits the coefficients (a GPU
  // provider works meanwhile). A load-dependent model (the contact-area one) reads each
  // contact's last normal impulse; others are spared the search.
  if (contacts_.empty()) return;
  if (provider_->readsNormalLoads()) solver_->previousNormalImpulses(contacts_);
  provider_->startCoefficients(bodies_, contacts_, settings_.friction);
}

SolveInputs World::solveInputs() {
  SolveInputs in;
  in.bodies = bodies_;
  in.contacts = contacts_;
  in.joints = joints_;
  in.joint_rest_rotations = joint_rest_rotation_;
  SolverSettings& s = in.settings;
  s.dt = settings_.dt;
  s.limit_surface = settings_.limit_surface;
  s.coulomb_mu = settings_.friction.mu0;  // SPEC 4: Coulomb uses mu0 alone
  s.baumgarte = settings_.baumgarte;
  s.slop = settings_.linear_slop > 0.0 ? settings_.linear_slop : slop_;
  s.max_correction_speed = settings_.max_correction_speed;
  s.warm_starting = settings_.warm_starting;
  in.iterations = settings_.iterations;
  in.substeps = settings_.substeps;
  in.gravity = settings_.gravity;
  in.time = time_;
  in.friction = contacts_.empty() ? nullptr : provider_.get();
  return in;
}

void World::solve(StepProfile& profile) {
  runSolveStage(*solver_, solveInputs(), profile.solve_ms);
}

void World::integrate() {
  integratePoses(bodies_, solver_->pseudoLinearVelocities(), solver_->pseudoAngularVelocities(),
                 settings_.dt / settings_.substeps, pool_.get());
}

}  // namespace asperity
