// The parts of the solve stage (stage 5 of a step, docs/step.md), in the order they run. Each
// is timed into StepProfile::solve_ms; with sub-steps, a part's times are summed over them.
#pragma once

#include <array>

namespace asperity {

enum class SolveStage {
  PrepareJoints,  // velocities and masses copied in, joint rows built
  PrepareRows,    // every contact's row (Jacobians, effective masses), no coefficients needed
  AwaitFriction,  // the friction provider's coefficients, when it works on another device
  SetLimits,      // each contact's limit surface from its coefficients (SPEC 4)
  WarmStart,      // islands, and the last step's impulses applied again
  Iterate,        // the PGS sweeps
  StoreImpulses   // velocities and impulses written back, kept for the next warm start
};
inline constexpr int kSolveStageCount = 7;

// "prepare_joints", "prepare_rows", "await_friction", "set_limits", "warm_start", "iterate",
// "store_impulses".
const char* solveStageName(SolveStage stage);

// Milliseconds of each part of the solve stage, indexed by SolveStage.
using SolveStageTimes = std::array<double, kSolveStageCount>;

}  // namespace asperity
