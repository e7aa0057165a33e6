// The shared run loop (asperity/world/run_loop.hpp).
#include "asperity/world/run_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

int64_t stepsFor(double seconds, double dt, const char* what) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds))
    throw Error(std::string(what) + ": must be a finite number >= 0");
  const double n = std::ceil(seconds / dt - 1e-9);
  if (!(n <= 1e9))
    throw Error(std::string(what) + ": more than 1e9 steps of " + std::to_string(dt) + " s");
  return static_cast<int64_t>(std::max(n, 0.0));
}

double runSteps(World& world, int64_t steps, ProfileSums* sums,
                const std::function<void(int64_t)>& after_step) {
  const auto start = std::chrono::steady_clock::now();
  // The collision set-up apart from the steps' means (run --stats, bench).
  const double prepare_ms = steps > 0 ? world.prepare() : 0.0;
  if (sums) sums->prepare_ms += prepare_ms;
  for (int64_t i = 1; i <= steps; ++i) {
    world.step();
    if (sums) sums->add(world.profile());
    if (after_step) after_step(i);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace asperity
