// The AVX2 and baseline copies of the hot loops (math/simd.hpp) give the same bits: scenes
// sampled with the cpu sampler (and cones summed by the cone provider) end in the same state
// whichever copy their providers were made with. The copy is each provider's option, so both
// worlds can be built and run side by side.
#include "math/simd.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// The built-in providers with the loops' copy `copy`.
FrictionProviders providersWith(SimdCopy copy) {
  FrictionProviders providers = FrictionProviders::builtIn();
  providers.add("cpu", [copy] {
    CpuSamplerOptions options;
    options.simd = copy;
    return std::make_unique<CpuPatchSampler>(options);
  });
  providers.add("cone", [copy] { return std::make_unique<ConeProvider>(copy); });
  return providers;
}

// The state hash after `steps` steps of a repository scene, with the copies `copy` picks.
uint64_t hashAfter(const std::string& file, int steps, SimdCopy copy) {
  const auto world =
      instantiate(loadScene(test::sourcePath("scenes/" + file)), {providersWith(copy)});
  for (int i = 0; i < steps; ++i) world->step();
  return world->stateHash();
}

TEST(Simd, TheBaselineOptionTurnsTheAvx2CopiesOff) {
  EXPECT_FALSE(simd::avx2(SimdCopy::Baseline));
  EXPECT_EQ(simd::avx2(SimdCopy::Auto), simd::avx2Available());
}

TEST(Simd, Avx2AndBaselineCopiesGiveTheSameBits) {
  if (!simd::avx2Available()) GTEST_SKIP() << "no AVX2 copies on this build or processor";
  // Sliding boxes (every step sampled: shading, sums, rasterisation) and a resting stack.
  for (const char* file : {"boxes_on_materials.json", "stacking.json"}) {
    EXPECT_EQ(hashAfter(file, 100, SimdCopy::Baseline), hashAfter(file, 100, SimdCopy::Auto))
        << file;
  }
}

TEST(Simd, TheKernelsCopiesSumAlike) {
  if (!simd::avx2Available()) GTEST_SKIP() << "no AVX2 copies on this build or processor";
  // Ploughing vectors of mixed signs over 16 directions, a length that is no multiple of 8.
  std::vector<float> gx(1003), gy(1003);
  for (size_t i = 0; i < gx.size(); ++i) {
    gx[i] = static_cast<float>(std::sin(0.37 * static_cast<double>(i)));
    gy[i] = static_cast<float>(std::cos(0.91 * static_cast<double>(i)));
  }
  const std::vector<Vec2> dirs = sampleDirections(16);
  std::vector<double> baseline(dirs.size(), 0.0), avx2(dirs.size(), 0.0);
  accumulateDirectionalSums(gx, gy, dirs, baseline, SimdCopy::Baseline);
  accumulateDirectionalSums(gx, gy, dirs, avx2, SimdCopy::Auto);
  EXPECT_EQ(baseline, avx2);
}

}  // namespace
}  // namespace asperity
