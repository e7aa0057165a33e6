// The real-area model's own cost (docs/contact-area.md): the 16 x 16 patch a contact rasterises
// (R = 16) solved for its load, as the contact-area friction model would add it to each contact
// on top of the paper's raster (BM_BoxOnPlane in cpu_sampler_bench.cpp gives that per contact),
// and `asperity contact-area`'s 256 x 256 pair. Counter `per_contact` is the time per solve.
#include <benchmark/benchmark.h>

#include "asperity/contact_area/contact_area.hpp"
#include "contact_area/gaussian_surface.hpp"

namespace asperity {
namespace {

// A pair of rough surfaces (rms slope 0.1) over `n` x `n` texels of a `size` metre patch,
// solved at a load that touches about 1 % of it.
void solvePair(benchmark::State& state, int n, double size, double shortest, double longest,
               int modes) {
  const HeightMap a = test::gaussianSurface(n, size, 0.1, 1, shortest, longest, modes);
  const HeightMap b = test::gaussianSurface(n, size, 0.1, 2, shortest, longest, modes);
  const ContactMaterial material{1e11, 2e9};
  const double load = 0.01 * material.modulus * 0.1 / 2.0 * size * size;
  for (auto _ : state) {
    const SummitSet set = findSummits(b, &a, size);
    benchmark::DoNotOptimize(solveContact(set, material, load).real_area);
  }
  state.counters["per_contact"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate |
                                  benchmark::Counter::kInvert);
}

void BM_PatchOf16(benchmark::State& state) {
  solvePair(state, 16, 0.02, 2.0, 8.0, 24);
}
BENCHMARK(BM_PatchOf16);

void BM_PairOf256(benchmark::State& state) {
  solvePair(state, 256, 1e-3, 4.0, 32.0, 80);
}
BENCHMARK(BM_PairOf256)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace asperity

BENCHMARK_MAIN();
