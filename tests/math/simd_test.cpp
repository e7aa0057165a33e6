// The AVX2 and baseline copies of the hot loops (math/simd.hpp) give the same bits: scenes
// sampled with the cpu sampler end in the same state either way.
#include "math/simd.hpp"

#include <gtest/gtest.h>

#include <string>

#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// The state hash after `steps` steps of a repository scene, with the copies `baseline` picks.
uint64_t hashAfter(const std::string& file, int steps, bool baseline) {
  simd::forceBaseline(baseline);
  const auto world = instantiate(loadScene(test::sourcePath("scenes/" + file)));
  for (int i = 0; i < steps; ++i) world->step();
  simd::forceBaseline(false);
  return world->stateHash();
}

TEST(Simd, ForcingTheBaselineTurnsTheAvx2CopiesOff) {
  simd::forceBaseline(true);
  EXPECT_FALSE(simd::avx2());
  simd::forceBaseline(false);
}

TEST(Simd, Avx2AndBaselineCopiesGiveTheSameBits) {
  if (!simd::avx2()) GTEST_SKIP() << "no AVX2 copies on this build or processor";
  // Sliding boxes (every step sampled: shading, sums, rasterisation) and a resting stack.
  for (const char* file : {"boxes_on_materials.json", "stacking.json"}) {
    EXPECT_EQ(hashAfter(file, 100, true), hashAfter(file, 100, false)) << file;
  }
}

}  // namespace
}  // namespace asperity
