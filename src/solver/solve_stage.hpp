// Stage 5 of a step (docs/step.md, SPEC 4): the whole solve over the data a world hands it,
// its parts in SolveStage order (asperity/solver/solve_stage.hpp), sub-steps included; and
// the frictionless prediction of frame mode Auto. The ContactSolver keeps what one step
// leaves for the next (warm-start impulses).
#pragma once

#include <span>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/dynamics/joint.hpp"
#include "asperity/frames/contact_frames.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/solver/solve_stage.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

// What one step's solve reads and writes.
struct SolveInputs {
  std::span<Body> bodies;       // velocities in (after the drivers) and out
  std::span<Contact> contacts;  // with frames; mu filled by `friction` at the latest
  std::span<const JointDesc> joints;
  std::span<const Quat> joint_rest_rotations;  // per joint: q_a^-1 q_b at creation (fixed)
  SolverSettings settings;                     // settings.dt: the whole step's dt
  int iterations = 20;                         // PGS sweeps per solve
  int substeps = 1;                            // solves per step, each over dt / substeps
  Vec3 gravity = Vec3::Zero();                 // m/s^2, shared out over the sub-steps
  double time = 0.0;                           // s, at the start of the step
  // The provider whose startCoefficients the friction stage called; its finishCoefficients
  // is awaited after the rows are built. Null: the contacts carry their mu already.
  FrictionProvider* friction = nullptr;
};

// The solve stage: `substeps` solves of dt / substeps, the poses moved between them (the last
// move is the integrate stage's). Adds each part's wall-clock ms to `times`.
void runSolveStage(ContactSolver& solver, const SolveInputs& in, SolveStageTimes& times);

// Frame mode Auto's prediction: `iterations` frictionless PGS sweeps (normal rows and joints)
// over `contacts` from the bodies' current velocities. The spans point into `solver` and stay
// valid until its next use.
PredictedVelocities predictFrictionless(ContactSolver& solver, const SolveInputs& in,
                                        std::span<const Contact> contacts, int iterations);

}  // namespace asperity
