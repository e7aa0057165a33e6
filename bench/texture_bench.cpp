// Texture stage costs: bilinear sampling (per fragment in the CPU sampler), PNG load and save,
// and generating maps.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "asperity/texture/generators.hpp"
#include "asperity/texture/png_io.hpp"

namespace {

using asperity::GeneratorSpec;
using asperity::NormalMap;

NormalMap gaussianMap(int size) {
  GeneratorSpec spec;
  spec.name = "gaussian";
  spec.size = size;
  return asperity::generateNormalMap(spec);
}

std::string tempPng(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("asperity_texture_bench_" + name)).string();
}

// One bilinear sample at scattered coordinates (Repeat).
void BM_Sample(benchmark::State& state) {
  const NormalMap map = gaussianMap(512);
  float u = 0.123f;
  float v = 0.456f;
  for (auto _ : state) {
    benchmark::DoNotOptimize(map.sample(u, v));
    u += 0.0137f;
    v += 0.0291f;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Sample);

// Save then load a size x size map at 8 or 16 bits.
void BM_PngSave(benchmark::State& state) {
  const NormalMap map = gaussianMap(static_cast<int>(state.range(0)));
  const std::string path = tempPng("save.png");
  const asperity::PngWriteOptions options{static_cast<int>(state.range(1)), false,
                                          asperity::GreenConvention::OpenGL};
  for (auto _ : state) asperity::saveNormalMapPng(map, path, options);
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
  std::remove(path.c_str());
}
BENCHMARK(BM_PngSave)->Args({1024, 8})->Args({1024, 16})->Unit(benchmark::kMillisecond);

void BM_PngLoad(benchmark::State& state) {
  const std::string path = tempPng("load.png");
  asperity::saveNormalMapPng(
      gaussianMap(static_cast<int>(state.range(0))), path,
      {static_cast<int>(state.range(1)), false, asperity::GreenConvention::OpenGL});
  for (auto _ : state) benchmark::DoNotOptimize(asperity::loadNormalMapPng(path));
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
  std::remove(path.c_str());
}
BENCHMARK(BM_PngLoad)->Args({1024, 8})->Args({1024, 16})->Unit(benchmark::kMillisecond);

// Generating a 512 x 512 map with each generator's defaults.
void BM_Generate(benchmark::State& state, const std::string& name) {
  GeneratorSpec spec;
  spec.name = name;
  spec.size = 512;
  for (auto _ : state) benchmark::DoNotOptimize(asperity::generateNormalMap(spec));
  state.SetItemsProcessed(state.iterations() * 512 * 512);
}
BENCHMARK_CAPTURE(BM_Generate, gaussian, std::string("gaussian"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Generate, roughness, std::string("roughness"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Generate, sawtooth, std::string("sawtooth"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Generate, emboss, std::string("emboss"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Generate, stone, std::string("stone"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Generate, oak, std::string("oak"))->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
