// Checkpoints of the 1000-cube pile (pile_world.hpp), after 300 steps of falling and settling:
// writing the state file (World::saveState and the atomic write, fsync included) and loading
// it into a new world of the same bodies (its collision world built afresh by World::prepare,
// then the saved persistence put in). The label carries the file's size and whether the loaded
// world's next 20 steps give the saved world's hash.
//   build/bin/asperity_checkpoint_bench [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "asperity/world/state_file.hpp"
#include "pile_world.hpp"

namespace {

using namespace asperity;
using Clock = std::chrono::steady_clock;

constexpr int kSettle = 300;
constexpr uint64_t kSceneId = 1000;  // the pile is built in code: any fixed id names it

std::string statePath() {
  return (std::filesystem::temp_directory_path() / "asperity_pile_checkpoint.state").string();
}

// The settled pile, made once for both benchmarks.
World& settledPile() {
  static const std::unique_ptr<World> world = [] {
    auto w = bench::pileWorld(1);
    for (int i = 0; i < kSettle; ++i) w->step();
    return w;
  }();
  return *world;
}

void BM_SavePile(benchmark::State& state) {
  World& world = settledPile();
  for (auto _ : state) {
    const auto t0 = Clock::now();
    saveStateFile(world, statePath(), kSceneId);
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  state.SetLabel(std::to_string(std::filesystem::file_size(statePath()) / 1024) + " kB");
}

void BM_LoadPile(benchmark::State& state) {
  World& saved = settledPile();
  saveStateFile(saved, statePath(), kSceneId);
  bool same = true;
  for (auto _ : state) {
    state.PauseTiming();
    auto world = bench::pileWorld(1);
    state.ResumeTiming();
    const auto t0 = Clock::now();
    loadStateFile(*world, statePath(), kSceneId);
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - t0).count());
    state.PauseTiming();
    // Not timed: the loaded world goes on as the saved one would (checked on a copy of the
    // saved state, so the saved world itself stays as it is for the next iterations).
    auto check = bench::pileWorld(1);
    loadStateFile(*check, statePath(), kSceneId);
    for (int i = 0; i < 20; ++i) world->step(), check->step();
    same = same && world->stateHash() == check->stateHash();
    state.ResumeTiming();
  }
  state.SetLabel(same ? "continues bit for bit" : "DIVERGED");
}

// What a load starts with, for comparison: the collision world built for new bodies.
void BM_PreparePile(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    auto world = bench::pileWorld(1);
    state.ResumeTiming();
    const auto t0 = Clock::now();
    world->prepare();
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - t0).count());
  }
}

BENCHMARK(BM_PreparePile)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_SavePile)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK(BM_LoadPile)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
