// Collision stage timings: CollisionDetector::detect on resting scenes (persistent manifolds
// warm, as in a running simulation). Counters: contacts per call.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "asperity/geometry/mesh_io.hpp"
#include "collision/collision_detector.hpp"
#include "collision/collision_test_scenes.hpp"

namespace asperity {
namespace {

using collision_test::boxBody;
using collision_test::groundPlane;

// Three stacks of ten 0.2 m cubes (the paper's stacking scene), each resting 1 mm deep.
std::vector<Body> threeStacks() {
  std::vector<Body> bodies = {groundPlane()};
  for (int s = 0; s < 3; ++s) {
    for (int level = 0; level < 10; ++level) {
      const Vec3 at(0.5 * s, 0.0, 0.1 - 0.001 + level * 0.199);
      bodies.push_back(boxBody(Vec3::Constant(0.1), at, 0.05 * level));
    }
  }
  return bodies;
}

// A pile of 1000 cubes: 10 x 10 columns of 10 resting cubes (1 mm deep), each cube jittered
// sideways and turned about z, neighbouring columns a few millimetres apart.
std::vector<Body> pile() {
  std::vector<Body> bodies = {groundPlane()};
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> jitter(-0.005, 0.005), angle(-0.05, 0.05);
  for (int j = 0; j < 10; ++j) {
    for (int i = 0; i < 10; ++i) {
      for (int level = 0; level < 10; ++level) {
        const Vec3 at(0.23 * i + jitter(rng), 0.23 * j + jitter(rng), 0.099 + 0.199 * level);
        bodies.push_back(boxBody(Vec3::Constant(0.1), at, angle(rng)));
      }
    }
  }
  return bodies;
}

// The nut leaning on a static cylinder bolt (signed-distance path).
std::vector<Body> nutOnBolt() {
  // A closed square nut, 7 mm across, 4 mm bore, 3.2 mm high.
  const auto nut = collision_test::squareNutMesh(0.0035, 0.002, 0.0016);
  return {
      collision_test::cylinderBody(0.0018, 0.01, Vec3::Zero(), Quat::Identity(), BodyType::Static),
      collision_test::meshBody(nut, BodyType::Dynamic, Vec3(0.00025, 0, 0.002))};
}

// The Stanford bunny (glmark2-data, scaled to 0.2 m, simplified to 2000 triangles, closed)
// resting 1 mm deep on a static box: the signed-distance path on a real mesh.
std::vector<Body> bunnyOnBox() {
  auto bunny = simplifyMesh(*loadObjMesh("/usr/share/glmark2/models/bunny.obj", 0.1), 2000);
  double lowest = 1e300;
  for (const Vec3& v : bunny->vertices) lowest = std::min(lowest, v.z());
  return {boxBody(Vec3(1, 1, 0.1), Vec3(0, 0, -0.1), 0.0, BodyType::Static),
          collision_test::meshBody(bunny, BodyType::Dynamic, Vec3(0, 0, -lowest - 0.001))};
}

void runDetect(benchmark::State& state, const std::vector<Body>& bodies) {
  CollisionDetector detector;
  detector.setBodies(bodies, {});
  detector.detect(bodies);  // warm the persistent manifolds
  size_t contacts = 0;
  for (auto _ : state) {
    contacts = detector.detect(bodies).size();
    benchmark::DoNotOptimize(contacts);
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["bodies"] = static_cast<double>(bodies.size());
}

void BM_DetectThreeStacks(benchmark::State& state) {
  runDetect(state, threeStacks());
}
BENCHMARK(BM_DetectThreeStacks)->Unit(benchmark::kMicrosecond);

void BM_DetectPile1000(benchmark::State& state) {
  runDetect(state, pile());
}
BENCHMARK(BM_DetectPile1000)->Unit(benchmark::kMillisecond);

void BM_DetectNutOnBolt(benchmark::State& state) {
  runDetect(state, nutOnBolt());
}
BENCHMARK(BM_DetectNutOnBolt)->Unit(benchmark::kMicrosecond);

void BM_DetectBunnyOnBox(benchmark::State& state) {
  if (!std::filesystem::exists("/usr/share/glmark2/models/bunny.obj")) {
    state.SkipWithError("glmark2-data is not installed");
    return;
  }
  runDetect(state, bunnyOnBox());
}
BENCHMARK(BM_DetectBunnyOnBox)->Unit(benchmark::kMicrosecond);

// Rebuilding every collision object (what adding or removing a body costs).
void BM_SetBodiesPile1000(benchmark::State& state) {
  const std::vector<Body> bodies = pile();
  CollisionDetector detector;
  for (auto _ : state) detector.setBodies(bodies, {});
  state.counters["bodies"] = static_cast<double>(bodies.size());
}
BENCHMARK(BM_SetBodiesPile1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace asperity
BENCHMARK_MAIN();
