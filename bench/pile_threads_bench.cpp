// The 1000-cube pile of ../shared/peers (scene B: a 10 x 10 x 10 grid of 0.2 m, 1 kg cubes,
// 0.05 m gaps, the lowest layer 0.05 m above the ground, dropped; dt = 10 ms, 20 iterations,
// Coulomb mu = 0.5) on 1 and on N worker threads. Steps 0..299 let it fall and settle
// untimed; steps 300..499 are timed, as `bench_bullet pile` times them. Counters: the median
// and mean step time (ms), each stage's mean (ms), the columns whose top cube is still on top (of
// 100), and the label carries the state hash, which must be the same for every thread count.
//   build/bin/asperity_pile_threads_bench   (Bullet beside it: bench_bullet pile tuned)
//   build/bin/asperity_pile_threads_bench --threads=1,2,4,8,16   (the scaling curve)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pile_world.hpp"

namespace {

using namespace asperity;
using Clock = std::chrono::steady_clock;

using bench::gridCentres;
using bench::kEdge;
using bench::kGrid;
using bench::pileWorld;
constexpr int kSettle = 300, kTimed = 200;

// Columns whose top cube sits on top of its column (within 2 cm), as the peers count them.
int intactColumns(const World& world, const std::vector<Vec3>& init) {
  int intact = 0;
  const size_t top0 = static_cast<size_t>((kGrid - 1) * kGrid * kGrid);
  for (size_t i = top0; i < init.size(); ++i) {
    const Vec3 p = world.body(static_cast<BodyId>(i + 1)).pose.position;
    if (std::abs(p.x() - init[i].x()) < 0.02 && std::abs(p.y() - init[i].y()) < 0.02 &&
        std::abs(p.z() - (0.5 * kEdge + (kGrid - 1) * kEdge)) < 0.02)
      ++intact;
  }
  return intact;
}

void BM_Pile1000(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const std::vector<Vec3> init = gridCentres();
  for (auto _ : state) {
    auto world = pileWorld(threads);
    for (int i = 0; i < kSettle; ++i) world->step();
    std::vector<double> ms;
    ProfileSums sums;
    for (int i = 0; i < kTimed; ++i) {
      const auto t0 = Clock::now();
      world->step();
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
      sums.add(world->profile());
    }
    for (int k = 0; k < kStageCount; ++k)
      state.counters[stageName(static_cast<Stage>(k))] = sums.meanMs(static_cast<Stage>(k));
    double sum = 0.0;
    for (double m : ms) sum += m;
    std::sort(ms.begin(), ms.end());
    state.SetIterationTime(sum / 1e3);
    state.counters["median_ms"] = ms[ms.size() / 2];
    state.counters["mean_ms"] = sum / kTimed;
    state.counters["intact_columns"] = intactColumns(*world, init);
    state.counters["contacts"] = static_cast<double>(world->contacts().size());
    char hash[17];
    std::snprintf(hash, sizeof(hash), "%016llx",
                  static_cast<unsigned long long>(world->stateHash()));
    state.SetLabel(std::string("hash ") + hash);
  }
}
// The thread counts of --threads=N,N,... (0 = every core); removes the flag from argv so that
// Google Benchmark sees only its own. Default: 1, 2 and every core.
std::vector<int> takeThreadCounts(int& argc, char** argv) {
  std::vector<int> counts;
  const std::string flag = "--threads=";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind(flag, 0) != 0) continue;
    std::stringstream list(arg.substr(flag.size()));
    for (std::string item; std::getline(list, item, ',');) {
      char* end = nullptr;
      const long n = std::strtol(item.c_str(), &end, 10);
      if (item.empty() || *end != '\0' || n < 0 || n > 1024)
        throw std::invalid_argument("--threads: '" + item + "' is not a thread count (0..1024)");
      counts.push_back(static_cast<int>(n));
    }
    std::copy(argv + i + 1, argv + argc, argv + i);
    --argc, --i;
  }
  return counts.empty() ? std::vector<int>{1, 2, 0} : counts;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    auto* bench = benchmark::RegisterBenchmark("BM_Pile1000", BM_Pile1000);
    for (int n : takeThreadCounts(argc, argv)) bench->Arg(n);
    bench->UseManualTime()->Iterations(1)->Unit(benchmark::kMillisecond);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "asperity_pile_threads_bench: %s\n", e.what());
    return 2;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
