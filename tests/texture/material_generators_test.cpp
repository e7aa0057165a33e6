// Material look-alikes: the roughness orderings the experiments rely on (Sec. 5) and the
// anisotropy of the grained and brushed ones.
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

using test::generate;
using test::meanPloughing;
using test::muAlong;

TEST(MaterialGenerators, StackingOrderAcrylicOakCutPvc) {
  // Fig. 14: acrylic shoots out, cut PVC moves least.
  for (uint64_t seed : {1u, 2u}) {
    const double acrylic = meanPloughing(generate("acrylic", {}, 128, seed));
    const double oak = meanPloughing(generate("oak", {}, 128, seed));
    const double pvc = meanPloughing(generate("cut_pvc", {}, 128, seed));
    EXPECT_LT(acrylic, oak);
    EXPECT_LT(oak, pvc);
    EXPECT_LT(acrylic, 0.02);
  }
}

TEST(MaterialGenerators, BunnyOrderStoneMetalPlastic) {
  // Fig. 16: the stone bunny sticks, metal and plastic slide.
  for (uint64_t seed : {1u, 2u}) {
    const double stone = meanPloughing(generate("stone", {}, 128, seed));
    const double metal = meanPloughing(generate("metal", {}, 128, seed));
    const double plastic = meanPloughing(generate("plastic", {}, 128, seed));
    EXPECT_GT(stone, metal);
    EXPECT_GT(metal, plastic);
    EXPECT_GT(plastic, 0.0);
  }
}

TEST(MaterialGenerators, SlopeParameterScalesRoughnessAndZeroIsFlat) {
  const double low = meanPloughing(generate("plaster", {{"slope", "0.1"}}));
  const double high = meanPloughing(generate("plaster", {{"slope", "0.2"}}));
  EXPECT_TRUE(test::near(high / low, 2.0, 0.05));
  EXPECT_EQ(generate("plastic", {{"slope", "0"}}).texels(), NormalMap(128, 128).texels());
}

TEST(MaterialGenerators, OakAndMetalAreAnisotropicAlongTheirAxis) {
  // Grain and brushing along u: much more slope across (v) than along (u).
  for (const char* name : {"oak", "metal"}) {
    const NormalMap u = generate(name, {}, 128);
    EXPECT_GT(muAlong(u, 0, 1), 3.0 * muAlong(u, 1, 0)) << name;
    // Turning the axis to v swaps the roles.
    const NormalMap v = generate(name, {{"axis", "v"}}, 128);
    EXPECT_GT(muAlong(v, 1, 0), 3.0 * muAlong(v, 0, 1)) << name;
  }
}

TEST(MaterialGenerators, CutPvcMarksRunAcrossTheAxis) {
  const NormalMap map = generate("cut_pvc", {{"noise_slope", "0"}}, 128);
  EXPECT_GT(muAlong(map, 1, 0), 5.0 * muAlong(map, 0, 1));
}

TEST(MaterialGenerators, IsotropicOnesAreIsotropic) {
  for (const char* name : {"plaster", "stone", "plastic", "acrylic"}) {
    const NormalMap map = generate(name, {}, 128);
    EXPECT_TRUE(test::near(muAlong(map, 1, 0), muAlong(map, 0, 1), 0.15)) << name;
  }
}

}  // namespace
}  // namespace asperity
