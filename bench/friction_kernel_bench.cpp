// Throughput of the friction kernels: texel-directions per second of the directional kernel
// on a 16 x 16 patch (the default R = 16), and the whole-texture cone on two 1024^2 maps.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "asperity/friction/fragment_model.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/friction/patch_cone.hpp"

namespace {

using namespace asperity;

// Random ploughing vectors of `count` fragments (SoA), fixed seed.
void randomFragments(size_t count, std::vector<float>& gx, std::vector<float>& gy) {
  std::mt19937 rng(17);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  gx.resize(count);
  gy.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const Vec2f g = ploughingVector(Vec3f(normal(rng), normal(rng), 3.0f).normalized(), Side::B);
    gx[i] = g.x();
    gy[i] = g.y();
  }
}

// accumulateDirectionalSums over one 16 x 16 patch; items = texels x directions.
void BM_DirectionalKernel16x16(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<float> gx, gy;
  randomFragments(16 * 16, gx, gy);
  const std::vector<Vec2> dirs = sampleDirections(n);
  std::vector<double> sums(dirs.size(), 0.0);
  for (auto _ : state) {
    accumulateDirectionalSums(gx, gy, dirs, sums);
    benchmark::DoNotOptimize(sums.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(gx.size()) * n);
}
BENCHMARK(BM_DirectionalKernel16x16)->Arg(4)->Arg(16)->Arg(64);

// A Gaussian-slope normal map of size x size, fixed seed.
NormalMap gaussianMap(int size, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  NormalMap map(size, size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      map.at(i, j) = Vec3f(-normal(rng), -normal(rng), 1.0f).normalized();
    }
  }
  return map;
}

// flatPatchCone on two 1024 x 1024 maps with 16 directions (`asperity cone`).
void BM_FlatPatchCone1024(benchmark::State& state) {
  const NormalMap a = gaussianMap(1024, 1), b = gaussianMap(1024, 2);
  PatchConeOptions opt;
  opt.directions = 16;
  for (auto _ : state) {
    DirectionalMu mu = flatPatchCone(&a, b, opt);
    benchmark::DoNotOptimize(mu);
  }
  state.SetItemsProcessed(state.iterations() * 2 * 1024 * 1024 * 16);
}
BENCHMARK(BM_FlatPatchCone1024)->Unit(benchmark::kMillisecond);

// One polygon projection of a point outside (the PGS inner loop), N = 16.
void BM_PolygonProject16(benchmark::State& state) {
  PolygonLimit poly{DirectionalMu::uniform(16, 0.4f)};
  for (int k = 0; k < 16; k += 2) poly.mu.mu[static_cast<size_t>(k)] = 0.7f;
  Vec2 x(1.0, 0.3);
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    Vec2 y = poly.project(x, 1.0);
    benchmark::DoNotOptimize(y);
  }
}
BENCHMARK(BM_PolygonProject16);

// One polygon projection of a point inside (the O(1) wedge test alone), N = 16.
void BM_PolygonInside16(benchmark::State& state) {
  const PolygonLimit poly{DirectionalMu::uniform(16, 0.4f)};
  Vec2 x(0.1, 0.05);
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    Vec2 y = poly.project(x, 1.0);
    benchmark::DoNotOptimize(y);
  }
}
BENCHMARK(BM_PolygonInside16);

}  // namespace

BENCHMARK_MAIN();
