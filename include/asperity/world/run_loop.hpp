// The loop every front end runs a scene with (`asperity run`, the experiments, bench, sweep and
// the Python module): how many steps a simulated time takes, and stepping a world while
// summing its profile.
#pragma once

#include <cstdint>
#include <functional>

#include "asperity/world/world.hpp"

namespace asperity {

// Most steps one call runs (the CLI's --steps, Python's World.step and Batch.step).
inline constexpr int64_t kMaxSteps = 1'000'000'000;

// Steps that cover `seconds` at `dt`: ceil(seconds / dt), a hair under a whole step counting as
// whole. Throws asperity::Error (naming `what`, e.g. "--seconds") for a negative or
// non-finite time or more than 1e9 steps.
int64_t stepsFor(double seconds, double dt, const char* what = "seconds");

// Steps `world` `steps` times, adding each step's profile to `sums` when given and calling
// `after_step(i)` after step i = 1..steps. World::prepare runs first, its time in
// sums->prepare_ms rather than in a step's. Returns the wall-clock seconds of it all.
// Exceptions from World::step (StepError) pass through.
double runSteps(World& world, int64_t steps, ProfileSums* sums = nullptr,
                const std::function<void(int64_t)>& after_step = {});

}  // namespace asperity
