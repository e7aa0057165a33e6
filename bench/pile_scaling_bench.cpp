// How the step cost grows with the number of bodies: piles of 100 and 1000 0.2 m cubes on a
// plane (dt = 10 ms, 20 iterations, Coulomb mu = 0.5, as the Bullet comparison). Each pile
// first settles for 1.5 s (the cubes fall into a heap), then its steps are timed; counters
// give the median step time, the contact count and the cost per body. BM_PileScaling runs
// both sizes and reports the ratio of their median step costs (linear scaling gives 10; the
// target is at most 12), measured in thread CPU time so that other processes on a busy
// machine do not count.
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

std::unique_ptr<World> makePile(int count) {
  WorldSettings s;
  s.dt = 0.01;
  s.iterations = 20;
  s.limit_surface = LimitSurfaceKind::Coulomb;
  s.friction.mu0 = 0.5;
  auto world = std::make_unique<World>(s);
  world->createBody(groundPlaneDesc());
  // Square layers of about count / 10 cubes each: ten layers for both sizes.
  const int per_layer = count >= 1000 ? 10 : 4;
  addCubePile(*world, count, 0.2, per_layer);
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
}
BENCHMARK(BM_Pile)->Arg(100)->Arg(1000)->UseManualTime()->Iterations(100)->Unit(
    benchmark::kMicrosecond);

// Both piles, their median step times and the ratio (target <= 12).
void BM_PileScaling(benchmark::State& state) {
  auto small = makePile(100);
  auto large = makePile(1000);
  double t_small = 0.0, t_large = 0.0;
  for (auto _ : state) {
    t_small = medianStep(*small, 100);
    t_large = medianStep(*large, 100);
    state.SetIterationTime(t_small + t_large);
  }
  state.counters["pile100_us"] = t_small * 1e6;
  state.counters["pile1000_us"] = t_large * 1e6;
  state.counters["ratio"] = t_large / t_small;
  std::printf("pile of 100: %.1f us, pile of 1000: %.1f us, ratio %.2f (target <= 12)\n",
              t_small * 1e6, t_large * 1e6, t_large / t_small);
  if (t_large > 12.0 * t_small) {
    state.SkipWithError("step cost grows faster than 12x for 10x bodies");
  }
}
BENCHMARK(BM_PileScaling)->UseManualTime()->Iterations(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
