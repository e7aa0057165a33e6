// Gaussian slopes against the friction oracle of SPEC 2, and Ra roughness (Sec. 5.1).
#include "texture/noise_generators.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

using test::generate;
using test::muAlong;
using test::near;

// Sample standard deviation of the slope -m_x / m_z (c = 0) or -m_y / m_z (c = 1).
double slopeStd(const NormalMap& map, int c) {
  double s1 = 0.0, s2 = 0.0;
  for (const Vec3f& m : map.texels()) {
    const double s = -m[c] / m.z();
    s1 += s;
    s2 += s * s;
  }
  const auto n = static_cast<double>(map.texels().size());
  return std::sqrt(s2 / n - (s1 / n) * (s1 / n));
}

TEST(GaussianGenerator, SlopeStatisticsMatchSxSy) {
  const NormalMap map = generate("gaussian", {{"sx", "0.3"}, {"sy", "2"}}, 256);
  EXPECT_TRUE(near(slopeStd(map, 0), 0.3, 0.02));
  EXPECT_TRUE(near(slopeStd(map, 1), 2.0, 0.02));
}

TEST(GaussianGenerator, IsotropicSigmaOneGivesMu0254InEveryDirection) {
  // SPEC 2: mu_d = (2 / pi) sigma_d / sqrt(2 pi) = 0.2540 for sigma = 1.
  const NormalMap map = generate("gaussian", {}, 256);
  const double expected = 2.0 / kPi / std::sqrt(2.0 * kPi);
  for (int k = 0; k < 8; ++k) {
    const double a = 2.0 * kPi * k / 8.0;
    EXPECT_TRUE(near(muAlong(map, std::cos(a), std::sin(a)), expected, 0.02)) << "k = " << k;
  }
}

TEST(GaussianGenerator, AnisotropicGivesMu00254AlongXAnd0254AlongY) {
  // Fig. 8, middle row: sx = 0.1, sy = 1.
  const NormalMap map = generate("gaussian", {{"sx", "0.1"}, {"sy", "1"}}, 256);
  const double base = 2.0 / kPi / std::sqrt(2.0 * kPi);
  EXPECT_TRUE(near(muAlong(map, 1, 0), 0.1 * base, 0.02));
  EXPECT_TRUE(near(muAlong(map, -1, 0), 0.1 * base, 0.02));
  EXPECT_TRUE(near(muAlong(map, 0, 1), base, 0.02));
  EXPECT_TRUE(near(muAlong(map, 0, -1), base, 0.02));
}

TEST(RoughnessGenerator, HeightsHaveTheRequestedRa) {
  for (double ra : {1.0, 0.15, 0.01}) {
    const texgen::Field h = texgen::roughnessHeightsMm(ra, 256, 3);
    double mean = 0.0;
    for (double v : h.values) mean += v;
    mean /= static_cast<double>(h.values.size());
    double mad = 0.0;
    for (double v : h.values) mad += std::abs(v - mean);
    EXPECT_TRUE(near(mad / static_cast<double>(h.values.size()), ra, 0.01)) << "Ra " << ra;
  }
}

TEST(RoughnessGenerator, SlopesFollowFromRaAndTexelPitch) {
  // Central differences of i.i.d. heights: slope std = sigma / (sqrt(2) texel).
  const double ra = 0.15;
  const double sigma = ra / std::sqrt(2.0 / kPi);
  const NormalMap one_mm = generate("roughness", {{"ra_mm", "0.15"}}, 256);
  EXPECT_TRUE(near(slopeStd(one_mm, 0), sigma / std::sqrt(2.0), 0.02));
  const NormalMap half_mm = generate("roughness", {{"ra_mm", "0.15"}, {"texel_mm", "0.5"}}, 256);
  EXPECT_TRUE(near(slopeStd(half_mm, 1), 2.0 * sigma / std::sqrt(2.0), 0.02));
}

TEST(RoughnessGenerator, PresetsMatchTheirRaAndOrder) {
  // Sec. 5.1: concrete 1 mm, cast iron 0.15 mm, steel 0.01 mm; Ra = 0 is exactly flat.
  EXPECT_EQ(generate("concrete").texels(), generate("roughness", {{"ra_mm", "1"}}).texels());
  EXPECT_EQ(generate("cast_iron").texels(), generate("roughness", {{"ra_mm", "0.15"}}).texels());
  EXPECT_EQ(generate("steel").texels(), generate("roughness", {{"ra_mm", "0.01"}}).texels());
  EXPECT_GT(test::meanPloughing(generate("concrete")), test::meanPloughing(generate("cast_iron")));
  EXPECT_GT(test::meanPloughing(generate("cast_iron")), test::meanPloughing(generate("steel")));
  EXPECT_EQ(generate("roughness", {{"ra_mm", "0"}}).texels(), NormalMap(128, 128).texels());
}

}  // namespace
}  // namespace asperity
