// The OpenGL patch sampler per contact (SPEC 3) on this machine's OpenGL (llvmpipe without a
// GPU): boxes resting on a textured plane, four corner contacts each, N = 4 and 16, R = 16, a
// 1024 x 1024 RGBA8 atlas (2048 contacts per pass). Counters: time per contact, and the
// provider's own split into patch (collect, render, sum on the GPU, read back) and averaging
// (the sums finished on the CPU). threads: the pool that collects the triangles and finishes
// the sums (0 = every core; 1 = the calling thread).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "asperity/sampler/gl_patch_sampler.hpp"
#include "parallel/thread_pool.hpp"
#include "sampler_bench_scene.hpp"

namespace asperity {
namespace {

void BM_GlBoxOnPlane(benchmark::State& state) {
  bench::SamplerScene scene = bench::boxesOnPlane(static_cast<int>(state.range(1)));
  GlPatchSampler sampler;
  const ThreadPool pool(static_cast<int>(state.range(2)));
  sampler.setThreadPool(&pool);
  FrictionSettings settings;
  settings.directions = static_cast<int>(state.range(0));
  sampler.computeCoefficients(scene.bodies, scene.contacts, settings);  // uploads textures
  double patch = 0.0, averaging = 0.0;
  for (auto _ : state) {
    sampler.computeCoefficients(scene.bodies, scene.contacts, settings);
    patch += sampler.lastStats().patch_ms;
    averaging += sampler.lastStats().averaging_ms;
  }
  const auto contacts = static_cast<double>(scene.contacts.size());
  const auto iterations = static_cast<double>(state.iterations());
  state.counters["per_contact"] = benchmark::Counter(
      contacts, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["patch_ms"] = patch / iterations;
  state.counters["averaging_ms"] = averaging / iterations;
  state.SetLabel(sampler.renderer());
}
BENCHMARK(BM_GlBoxOnPlane)
    ->ArgNames({"N", "contacts", "threads"})
    ->Args({4, 100, 1})
    ->Args({4, 1000, 1})
    ->Args({16, 1000, 1})
    ->Args({4, 4000, 1})
    ->Args({4, 1000, 0})
    ->Args({16, 1000, 0})
    ->Args({4, 4000, 0})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace asperity

BENCHMARK_MAIN();
