// Per-fragment model (SPEC 2, Eqs. 3 to 6) and Eq. 7, against closed forms.
#include "asperity/friction/fragment_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

constexpr double kTwoOverPi = 2.0 / kPi;

// A unit meso normal tilted by theta from +z (surface B's normal) toward azimuth phi.
Vec3f tilted(double theta, double phi, double z_sign = 1.0) {
  return Vec3f(static_cast<float>(std::sin(theta) * std::cos(phi)),
               static_cast<float>(std::sin(theta) * std::sin(phi)),
               static_cast<float>(z_sign * std::cos(theta)));
}

// Eq. 6: (2/pi) tan(arccos c) below the clamp.
TEST(PloughingTerm, MatchesClosedForm) {
  for (double c = 0.17; c <= 1.0; c += 0.01) {
    const double expected = kTwoOverPi * std::tan(std::acos(c));
    EXPECT_TRUE(near(ploughingTerm(static_cast<float>(c)), expected, 1e-5, 1e-6)) << c;
  }
  EXPECT_EQ(ploughingTerm(1.0f), 0.0f);
  EXPECT_EQ(ploughingTerm(1.0000001f), 0.0f);  // rounding past 1 stays flat
}

// Clamp: steeper than (2/pi) tan theta = mu_max (about 81 degrees for 4), facing away, NaN.
TEST(PloughingTerm, Clamps) {
  const double c_clamp = 1.0 / std::sqrt(1.0 + (kPi * 2.0) * (kPi * 2.0));  // tan = 2 pi
  EXPECT_EQ(ploughingTerm(static_cast<float>(c_clamp * 0.95)), kDefaultMuMax);
  EXPECT_LT(ploughingTerm(static_cast<float>(c_clamp * 1.05)), kDefaultMuMax);
  EXPECT_EQ(ploughingTerm(0.0f), kDefaultMuMax);
  EXPECT_EQ(ploughingTerm(-0.5f), kDefaultMuMax);
  EXPECT_EQ(ploughingTerm(std::numeric_limits<float>::quiet_NaN()), kDefaultMuMax);
  EXPECT_EQ(ploughingTerm(0.01f, 2.5f), 2.5f);
}

// g_B = P m' and g_A = -P m' for tilted facets in many azimuths.
TEST(PloughingVector, BothSidesInManyDirections) {
  for (double theta : {0.01, 0.3, 0.8, 1.2}) {
    const double p = kTwoOverPi * std::tan(theta);
    for (int i = 0; i < 12; ++i) {
      const double phi = 2.0 * kPi * i / 12;
      const Vec2f gb = ploughingVector(tilted(theta, phi), Side::B);
      EXPECT_TRUE(near(gb.x(), p * std::cos(phi), 1e-5, 1e-6)) << theta << " " << phi;
      EXPECT_TRUE(near(gb.y(), p * std::sin(phi), 1e-5, 1e-6)) << theta << " " << phi;
      // A faces -n: its facet tilted from -n toward phi gives -P m'.
      const Vec2f ga = ploughingVector(tilted(theta, phi, -1.0), Side::A);
      EXPECT_TRUE(near(ga.x(), -p * std::cos(phi), 1e-5, 1e-6)) << theta << " " << phi;
      EXPECT_TRUE(near(ga.y(), -p * std::sin(phi), 1e-5, 1e-6)) << theta << " " << phi;
    }
  }
}

// Near c = 1 the vector keeps full relative precision: g = (2/pi) m_tb / c.
TEST(PloughingVector, StableNearFlat) {
  for (double theta : {1e-3, 1e-5, 1e-7}) {
    const Vec2f g = ploughingVector(tilted(theta, 0.7), Side::B);
    EXPECT_TRUE(near(g.norm(), kTwoOverPi * std::tan(theta), 1e-5)) << theta;
    EXPECT_TRUE(near(std::atan2(g.y(), g.x()), 0.7, 1e-5)) << theta;
  }
}

// Parallel to the macro normal gives 0; the length of m does not matter.
TEST(PloughingVector, ParallelAndScale) {
  EXPECT_EQ(ploughingVector(Vec3f(0, 0, 1), Side::B), Vec2f::Zero());
  EXPECT_EQ(ploughingVector(Vec3f(0, 0, -1), Side::A), Vec2f::Zero());
  EXPECT_EQ(ploughingVector(Vec3f(0, 0, -1), Side::B), Vec2f::Zero());
  EXPECT_EQ(ploughingVector(Vec3f(0, 0, 0), Side::B), Vec2f::Zero());
  const Vec3f m = tilted(0.5, 2.0);
  const Vec2f g1 = ploughingVector(m, Side::B);
  const Vec2f g2 = ploughingVector(3.0f * m, Side::B);
  EXPECT_TRUE(near(g1.x(), g2.x(), 1e-6));
  EXPECT_TRUE(near(g1.y(), g2.y(), 1e-6));
}

// Facing away or too steep: length mu_max along m'.
TEST(PloughingVector, ClampedFacets) {
  const Vec2f away_b = ploughingVector(Vec3f(0.6f, 0.0f, -0.8f), Side::B);
  EXPECT_TRUE(near(away_b.x(), kDefaultMuMax, 1e-6));
  EXPECT_EQ(away_b.y(), 0.0f);
  const Vec2f away_a = ploughingVector(Vec3f(0.0f, 0.6f, 0.8f), Side::A);
  EXPECT_EQ(away_a.x(), 0.0f);
  EXPECT_TRUE(near(away_a.y(), -kDefaultMuMax, 1e-6));
  const Vec2f steep = ploughingVector(tilted(1.5, kPi / 4), Side::B, 2.0f);
  EXPECT_TRUE(near(steep.norm(), 2.0, 1e-6));
  EXPECT_TRUE(near(steep.x(), steep.y(), 1e-6));
  // Tiny tangential parts whose float squares underflow still point the right way.
  const Vec2f tiny = ploughingVector(Vec3f(1e-30f, -1e-30f, -1.0f), Side::B);
  EXPECT_TRUE(near(tiny.x(), kDefaultMuMax / std::sqrt(2.0), 1e-6));
  EXPECT_TRUE(near(tiny.y(), -kDefaultMuMax / std::sqrt(2.0), 1e-6));
}

// SPEC 2: mu_{d,B} = max(0, m'.d) P and mu_{d,A} = max(0, -m'.d) P, with c = -n.m for A.
TEST(FragmentMu, MatchesSpecFormula) {
  const auto dirs = sampleDirections(16);
  for (double theta : {0.2, 0.9}) {
    for (double phi : {0.0, 1.0, 3.5}) {
      for (Side side : {Side::A, Side::B}) {
        const double z = side == Side::B ? 1.0 : -1.0;
        const Vec3f m = tilted(theta, phi, z);
        const double c = z * m.z();
        const double p = kTwoOverPi * std::tan(std::acos(c));
        for (const Vec2& d : dirs) {
          const double md = std::cos(phi) * d.x() + std::sin(phi) * d.y();
          const double expected = std::max(0.0, (side == Side::B ? md : -md)) * p;
          EXPECT_TRUE(near(fragmentMu(m, side, d.cast<float>()), expected, 1e-5, 1e-6));
        }
      }
    }
  }
}

// A facet on B facing +t raises only mu_{+t}; a facet on A facing +t only mu_{-t}.
TEST(FragmentMu, DirectionConventions) {
  const Vec3f b_facet = tilted(0.4, 0.0);
  EXPECT_GT(fragmentMu(b_facet, Side::B, Vec2f(1, 0)), 0.2f);
  EXPECT_EQ(fragmentMu(b_facet, Side::B, Vec2f(-1, 0)), 0.0f);
  EXPECT_NEAR(fragmentMu(b_facet, Side::B, Vec2f(0, 1)), 0.0f, 1e-7f);
  const Vec3f a_facet = tilted(0.4, 0.0, -1.0);
  EXPECT_GT(fragmentMu(a_facet, Side::A, Vec2f(-1, 0)), 0.2f);
  EXPECT_EQ(fragmentMu(a_facet, Side::A, Vec2f(1, 0)), 0.0f);
}

// Eq. 7 term by term; an empty span is a flat surface.
TEST(CombinePatch, Eq7) {
  const std::vector<double> a = {0.1, 0.2, 0.3, 0.4};
  const std::vector<double> b = {0.5, 0.0, 0.25, 1.0};
  const DirectionalMu mu = combinePatch(a, b, PatchGains{0.2, 2.0, 4.0});
  ASSERT_EQ(mu.count, 4);
  for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(mu.mu[k], float(0.2 + 2.0 * a[k] + 4.0 * b[k]));
  const DirectionalMu only_b = combinePatch({}, b, PatchGains{0.1, 7.0, 1.0});
  for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(only_b.mu[k], float(0.1 + b[k]));
}

// Mismatched or out-of-range direction counts throw.
TEST(CombinePatch, RejectsBadShapes) {
  const std::vector<double> four(4, 0.0), five(5, 0.0), three(3, 0.0);
  EXPECT_THROW(combinePatch(four, five, PatchGains{}), Error);
  EXPECT_THROW(combinePatch(three, three, PatchGains{}), Error);
  EXPECT_THROW(combinePatch({}, {}, PatchGains{}), Error);
}

}  // namespace
}  // namespace asperity
