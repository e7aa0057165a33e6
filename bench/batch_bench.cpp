// A Batch of 64 worlds of scenes/boxes_on_materials.json against one World of the same scene:
// each iteration steps 200 times (2 s: the boxes slide and stop) from the scene's start, which
// is rebuilt untimed. Counters: per_world_step (wall time over worlds x steps) and the state
// hash of world 0 in the label, the same for the World and every thread count.
//   build/bin/asperity_batch_bench   (World, Batch on 1 and 2 threads)
//   build/bin/asperity_batch_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "asperity/batch/batch.hpp"
#include "asperity/scene/scene.hpp"

namespace {

using namespace asperity;

constexpr int kSteps = 200, kWorlds = 64;
const std::string kScene = std::string(ASPERITY_SOURCE_DIR) + "/scenes/boxes_on_materials.json";

nlohmann::json sceneJson() {
  std::ifstream in(kScene);
  return nlohmann::json::parse(in);
}

std::string hashLabel(uint64_t hash) {
  char text[32];
  std::snprintf(text, sizeof(text), "hash %016llx", static_cast<unsigned long long>(hash));
  return text;
}

// Time per world step (s): wall time over every world's steps.
void countWorldSteps(benchmark::State& state, int worlds) {
  state.counters["per_world_step"] = benchmark::Counter(
      worlds * kSteps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// One World, as `asperity run` builds it (one thread), stepped alone. As in a batch, its
// textures are made once and kept, and its collision objects are built (World::prepare)
// before the clock starts: both step the same warm worlds.
void BM_World(benchmark::State& state) {
  const SceneDesc scene = loadScene(kScene);
  InstantiateOptions options;
  options.resources = std::make_shared<SceneResources>();
  uint64_t hash = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::unique_ptr<World> world = instantiate(scene, options);
    world->prepare();
    state.ResumeTiming();
    for (int i = 0; i < kSteps; ++i) world->step();
    hash = world->stateHash();
  }
  countWorldSteps(state, 1);
  state.SetLabel(hashLabel(hash));
}
BENCHMARK(BM_World)->Unit(benchmark::kMillisecond)->UseRealTime();

// 64 worlds of the scene on a pool of `threads`, reset to the start (and prepared) between
// iterations.
void BM_Batch(benchmark::State& state) {
  BatchDesc desc;
  desc.scene_json = sceneJson().dump();
  desc.scene_file = kScene;
  desc.worlds = kWorlds;
  desc.threads = static_cast<int>(state.range(0));
  Batch batch(desc);
  for (auto _ : state) {
    state.PauseTiming();
    batch.reset();
    state.ResumeTiming();
    batch.step(kSteps);
  }
  countWorldSteps(state, kWorlds);
  state.SetLabel(hashLabel(batch.stateHashes()[0]));
}
BENCHMARK(BM_Batch)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
