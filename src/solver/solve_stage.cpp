// The solve stage (solver/solve_stage.hpp): one solve in its parts, timed, and the sub-steps.
#include "solver/solve_stage.hpp"

#include <vector>

#include "asperity/error.hpp"
#include "dynamics/integrate.hpp"
#include "math/stopwatch.hpp"

namespace asperity {

namespace {

// One part of a solve, timed: `times[part] += ms`.
template <class Work>
void timed(SolveStageTimes& times, SolveStage part, Stopwatch& clock, const Work& work) {
  work();
  times[static_cast<size_t>(part)] += clock.lap();
}

// The solver settings of one solve of length h.
SolverSettings settingsOver(const SolveInputs& in, double h) {
  SolverSettings s = in.settings;
  s.dt = h;
  return s;
}

// One solve of length h starting at time t, its parts in SolveStage order. `await` is the
// provider to wait for after the rows are built (null: none).
void solveOnce(ContactSolver& solver, const SolveInputs& in, double t, double h,
               FrictionProvider* await, SolveStageTimes& times) {
  Stopwatch clock;
  timed(times, SolveStage::PrepareJoints, clock, [&] {
    solver.begin(in.bodies, settingsOver(in, h));
    solver.setJoints(in.joints, in.joint_rest_rotations, t, h);
  });
  timed(times, SolveStage::PrepareRows, clock, [&] { solver.setContactRows(in.contacts, true); });
  // While a provider on another device (the gl sampler's GPU) worked, the rows were built.
  timed(times, SolveStage::AwaitFriction, clock, [&] {
    if (await) await->finishCoefficients();
  });
  timed(times, SolveStage::SetLimits, clock, [&] { solver.setContactLimits(in.contacts); });
  timed(times, SolveStage::WarmStart, clock, [&] { solver.warmStart(in.contacts); });
  timed(times, SolveStage::Iterate, clock, [&] { solver.iterate(in.iterations); });
  timed(times, SolveStage::StoreImpulses, clock, [&] { solver.finish(in.bodies, in.contacts); });
}

// Each contact's witness point rides on both bodies (rigidly from the poses at collision);
// the depth changes by their relative motion along the fixed normal (n from B to A).
void moveContacts(const SolveInputs& in, std::span<const Contact> base,
                  std::span<const Transform> start) {
  for (size_t i = 0; i < base.size(); ++i) {
    const Contact& c0 = base[i];
    auto carried = [&](BodyId id) {
      const Transform& s = start[id];
      const Transform& now = in.bodies[id].pose;
      return Vec3(now.position + now.rotation * (s.rotation.conjugate() * (c0.point - s.position)));
    };
    const Vec3 pa = carried(c0.body_a), pb = carried(c0.body_b);
    Contact& c = in.contacts[i];
    c.point = 0.5 * (pa + pb);
    c.phi = c0.phi - c0.normal.dot(pa - pb);
  }
}

// The velocity change of one sub-step's share of the drivers' acceleration.
struct SubstepShare {
  std::vector<Vec3> dv, dw;
};

// The drivers gave the whole step's acceleration; each sub-step gets its share (impulses and
// the gyroscopic step stay in the first), so all but the first share are taken back here.
SubstepShare takeBackLaterShares(const SolveInputs& in, double h) {
  const size_t n = in.bodies.size();
  SubstepShare share{std::vector<Vec3>(n, Vec3::Zero()), std::vector<Vec3>(n, Vec3::Zero())};
  for (size_t i = 0; i < n; ++i) {
    Body& b = in.bodies[i];
    if (!b.isDynamic()) continue;
    share.dv[i] = h * (in.gravity + b.inverse_mass * b.force);
    share.dw[i] = h * (b.inverseInertiaWorld() * b.torque);
    b.linear_velocity -= (in.substeps - 1) * share.dv[i];
    b.angular_velocity -= (in.substeps - 1) * share.dw[i];
  }
  return share;
}

// Sub-stepping: `substeps` solves of h = dt / substeps on the one set of contacts, positions
// integrated between them (the last by the integrate stage). Smaller steps leave PGS less to
// converge per solve: light links between heavy ends stop creeping (tests/world/
// chain_rod_test.cpp).
void solveSubsteps(ContactSolver& solver, const SolveInputs& in, SolveStageTimes& times) {
  const double h = in.settings.dt / in.substeps;
  std::vector<Transform> start(in.bodies.size());
  for (size_t i = 0; i < in.bodies.size(); ++i) start[i] = in.bodies[i].pose;
  const SubstepShare share = takeBackLaterShares(in, h);
  const std::vector<Contact> base(in.contacts.begin(), in.contacts.end());
  // (lambda_n, lambda_t, lambda_b) summed over the sub-steps.
  std::vector<Vec3> impulse(in.contacts.size(), Vec3::Zero());
  for (int k = 0; k < in.substeps; ++k) {
    // Later sub-steps: the poses moved, their share of the acceleration, the contacts carried.
    if (k > 0) {
      integratePoses(in.bodies, solver.pseudoLinearVelocities(), solver.pseudoAngularVelocities(),
                     h, solver.threadPool());
      for (size_t i = 0; i < in.bodies.size(); ++i) {
        if (!in.bodies[i].isDynamic()) continue;
        in.bodies[i].linear_velocity += share.dv[i];
        in.bodies[i].angular_velocity += share.dw[i];
      }
      moveContacts(in, base, start);
    }
    solveOnce(solver, in, in.time + k * h, h, k == 0 ? in.friction : nullptr, times);
    for (size_t i = 0; i < in.contacts.size(); ++i) {
      const Contact& c = in.contacts[i];
      impulse[i] += Vec3(c.lambda_n, c.lambda_t, c.lambda_b);
    }
  }
  // Contacts report the collision's geometry and the step's impulses.
  for (size_t i = 0; i < in.contacts.size(); ++i) {
    Contact& c = in.contacts[i];
    c.point = base[i].point;
    c.phi = base[i].phi;
    c.lambda_n = impulse[i].x();
    c.lambda_t = impulse[i].y();
    c.lambda_b = impulse[i].z();
  }
}

}  // namespace

const char* solveStageName(SolveStage stage) {
  static constexpr const char* kNames[kSolveStageCount] = {
      "prepare_joints", "prepare_rows", "await_friction", "set_limits",
      "warm_start",     "iterate",      "store_impulses"};
  return kNames[static_cast<size_t>(stage)];
}

void runSolveStage(ContactSolver& solver, const SolveInputs& in, SolveStageTimes& times) {
  if (in.substeps < 1) throw Error("world settings: substeps must be >= 1");
  if (in.substeps == 1) {
    solveOnce(solver, in, in.time, in.settings.dt, in.friction, times);
  } else {
    solveSubsteps(solver, in, times);
  }
}

PredictedVelocities predictFrictionless(ContactSolver& solver, const SolveInputs& in,
                                        std::span<const Contact> contacts, int iterations) {
  // Joints as at the start of the whole step, over the whole step (as the first solve sees
  // them when there are no sub-steps).
  solver.begin(in.bodies, settingsOver(in, in.settings.dt / in.substeps));
  solver.setJoints(in.joints, in.joint_rest_rotations, in.time, in.settings.dt);
  solver.setContacts(contacts, false);
  solver.iterate(iterations);
  return {solver.linearVelocities(), solver.angularVelocities()};
}

}  // namespace asperity
