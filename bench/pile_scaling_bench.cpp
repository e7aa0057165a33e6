// How the step cost grows with the number of bodies: piles of 100 and 1000 0.2 m cubes on a
// plane (dt = 10 ms, 20 iterations, Coulomb mu = 0.5, as the Bullet comparison). Each pile
// first settles for 1.5 s (the cubes fall into a heap), then its steps are timed; counters
// give the median step time, the contact count and the cost per body and per contact.
//
// Like with like ("same settings"): both piles have the same height and spread, the 1000-cube
// pile covering ten times the footprint of the 100-cube one. Layers are 4 x 4 cubes (100
// cubes) and 16 x 10 cubes (1000 cubes): 6.25 layers each at the same spacing. A wider pile
// has more cubes inside it, each resting on four below, so it has more contacts per cube
// (about 5.5 against 4.1); the solver and the collision stage work per contact, so
// BM_PileScaling reports the raw ratio of the median step costs and the ratio at equal
// contacts per cube (the raw ratio scaled by ten times the small pile's contacts over the
// large pile's). Linear scaling gives 10 for the latter; the target is at most 12. Times are
// thread CPU time so that other processes on a busy machine do not count.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"

namespace {

using namespace asperity;
using Clock = std::chrono::steady_clock;

constexpr int kSettleSteps = 150;

// addCubePile's layout (1.5 cube spacing, odd layers half a cube off, 1.1 cube layer pitch)
// with rectangular layers of columns x rows cubes.
void addCubeLayers(World& world, int count, double size, int columns, int rows) {
  const double spacing = 1.5 * size;
  const int per_layer = columns * rows;
  for (int i = 0; i < count; ++i) {
    const int layer = i / per_layer;
    const int cell = i % per_layer;
    const double shift = (layer % 2) * 0.5 * size;
    const Vec3 p(-0.5 * spacing * (columns - 1) + spacing * (cell % columns) + shift,
                 -0.5 * spacing * (rows - 1) + spacing * (cell / columns) + shift,
                 0.5 * size + 0.01 * size + layer * 1.1 * size);
    world.createBody(
        boxDesc("cube" + std::to_string(i), Vec3::Constant(0.5 * size), {p, Quat::Identity()}));
  }
}

std::unique_ptr<World> makePile(int count) {
  WorldSettings s;
  s.dt = 0.01;
  s.iterations = 20;
  s.limit_surface = LimitSurfaceKind::Coulomb;
  s.friction.mu0 = 0.5;
  auto world = std::make_unique<World>(s);
  world->createBody(groundPlaneDesc());
  // Layers of count / 6.25 cubes: 4 x 4 for 100 cubes, 16 x 10 for 1000 (ten times the area).
  const int columns = count >= 1000 ? 16 : 4;
  const int rows = count >= 1000 ? 10 : 4;
  addCubeLayers(*world, count, 0.2, columns, rows);
  for (int i = 0; i < kSettleSteps; ++i) world->step();
  return world;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// CPU time of the calling thread (s).
double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Median thread CPU time of `steps` steps of `world` (s).
double medianStep(World& world, int steps) {
  std::vector<double> times;
  for (int i = 0; i < steps; ++i) {
    const double start = threadSeconds();
    world.step();
    times.push_back(threadSeconds() - start);
  }
  return median(times);
}

void BM_Pile(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  auto world = makePile(count);
  std::vector<double> times;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    world->step();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    state.SetIterationTime(seconds);
    times.push_back(seconds);
  }
  state.counters["median_us"] = median(times) * 1e6;
  state.counters["contacts"] = world->profile().contacts;
  state.counters["us_per_body"] = median(times) * 1e6 / count;
  state.counters["ns_per_contact"] = median(times) * 1e9 / world->profile().contacts;
}
BENCHMARK(BM_Pile)->Arg(100)->Arg(1000)->UseManualTime()->Iterations(100)->Unit(
    benchmark::kMicrosecond);

// Both piles, their median step times, contacts and ratios (target <= 12 at equal contacts
// per cube).
void BM_PileScaling(benchmark::State& state) {
  auto small = makePile(100);
  auto large = makePile(1000);
  double t_small = 0.0, t_large = 0.0;
  for (auto _ : state) {
    t_small = medianStep(*small, 100);
    t_large = medianStep(*large, 100);
    state.SetIterationTime(t_small + t_large);
  }
  const double c_small = small->profile().contacts;
  const double c_large = large->profile().contacts;
  const double ratio = t_large / t_small;
  const double per_contact = ratio * 10.0 * c_small / c_large;
  state.counters["pile100_us"] = t_small * 1e6;
  state.counters["pile1000_us"] = t_large * 1e6;
  state.counters["contacts100"] = c_small;
  state.counters["contacts1000"] = c_large;
  state.counters["ratio"] = ratio;
  state.counters["ratio_equal_contacts"] = per_contact;
  std::printf(
      "pile of 100: %.1f us (%.0f contacts), pile of 1000: %.1f us (%.0f contacts), ratio %.2f, "
      "at equal contacts per cube %.2f (target <= 12)\n",
      t_small * 1e6, c_small, t_large * 1e6, c_large, ratio, per_contact);
  if (per_contact > 12.0) {
    state.SkipWithError("step cost grows faster than 12x for 10x bodies");
  }
}
BENCHMARK(BM_PileScaling)->UseManualTime()->Iterations(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
