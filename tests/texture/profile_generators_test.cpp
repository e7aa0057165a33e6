// Sawtooth, thread and cones: facet angles, area fractions and the facing directions documented in
// docs/textures.md, checked against the friction oracle mu_d (SPEC 1, 2).
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

using test::generate;
using test::muAlong;
using test::near;

double degrees(double radians) {
  return radians * 180.0 / kPi;
}

TEST(SawtoothGenerator, RampsFaceMinusAxisAndSteepFacesFacePlusAxis) {
  const NormalMap map = generate("sawtooth", {{"period", "32"}}, 128);
  int ramp = 0, steep = 0;
  for (const Vec3f& m : map.texels()) {
    EXPECT_EQ(m.y(), 0.0f);
    const double tilt = degrees(std::atan(test::tanTilt(m)));
    if (m.x() < 0) {
      ++ramp;  // ramp rising toward +u: normal tilts toward -u
      EXPECT_TRUE(near(tilt, 20.0, 0.0, 1e-4));
    } else {
      ++steep;
      EXPECT_TRUE(near(tilt, 70.0, 0.0, 1e-4));
    }
  }
  // ramp_width 0.5: half the texels each.
  EXPECT_EQ(ramp, steep);
}

TEST(SawtoothGenerator, AgainstTheSteepFacesIsTowardMinusAxis) {
  // mu_{+u} resists sliding toward -u and comes from facets facing +u: the steep faces.
  const NormalMap map = generate("sawtooth", {}, 128);
  const double plough = 2.0 / kPi;
  const double against_steep = muAlong(map, 1, 0);
  const double against_ramps = muAlong(map, -1, 0);
  EXPECT_TRUE(near(against_steep, 0.5 * plough * std::tan(70.0 * kPi / 180.0), 1e-4));
  EXPECT_TRUE(near(against_ramps, 0.5 * plough * std::tan(20.0 * kPi / 180.0), 1e-4));
  // Along the ridges (v) there is no ploughing.
  EXPECT_EQ(muAlong(map, 0, 1), 0.0);
  EXPECT_EQ(muAlong(map, 0, -1), 0.0);
}

TEST(SawtoothGenerator, AxisTurnsTheRidges) {
  // axis v: the ramps rise toward +v.
  const NormalMap v = generate("sawtooth", {{"axis", "v"}}, 64);
  EXPECT_GT(muAlong(v, 0, 1), 5.0 * muAlong(v, 0, -1));
  EXPECT_TRUE(near(muAlong(v, 1, 0), 0.0, 0.0, 1e-6));
  // axis 180: ramps rise toward -u, so the steep faces face -u.
  const NormalMap back = generate("sawtooth", {{"axis", "180"}}, 64);
  EXPECT_GT(muAlong(back, -1, 0), 5.0 * muAlong(back, 1, 0));
  EXPECT_EQ(generate("sawtooth", {{"axis", "90"}}, 64).texels(), v.texels());
}

TEST(SawtoothGenerator, RampWidthSetsAreaFractions) {
  const NormalMap map = generate("sawtooth", {{"ramp_width", "0.75"}, {"period", "16"}}, 64);
  int ramp = 0;
  for (const Vec3f& m : map.texels()) ramp += m.x() < 0 ? 1 : 0;
  EXPECT_EQ(ramp, 3 * 64 * 64 / 4);
}

TEST(SawtoothGenerator, SmoothingBlendsFacetsAtTheEdges) {
  const NormalMap sharp = generate("sawtooth", {}, 64);
  const NormalMap smooth = generate("sawtooth", {{"smoothing", "4"}}, 64);
  const double t20 = std::tan(20.0 * kPi / 180.0);
  const double t70 = std::tan(70.0 * kPi / 180.0);
  int between = 0;
  for (const Vec3f& m : smooth.texels()) {
    const double s = -m.x() / m.z();
    if (s > -t70 + 1e-3 && s < t20 - 1e-3 && std::abs(s + t70) > 1e-3) ++between;
  }
  EXPECT_GT(between, 0);
  // The box filter keeps the mean slope.
  double mean_sharp = 0.0, mean_smooth = 0.0;
  for (size_t k = 0; k < sharp.texels().size(); ++k) {
    mean_sharp += -sharp.texels()[k].x() / sharp.texels()[k].z();
    mean_smooth += -smooth.texels()[k].x() / smooth.texels()[k].z();
  }
  EXPECT_TRUE(near(mean_smooth, mean_sharp, 1e-3, 1e-3));
}

TEST(ThreadGenerator, SymmetricFlanksAtNinetyMinusFlankAngle) {
  // ISO metric: 30-degree flanks, so facets tilt 60 degrees, half toward +v and half toward -v.
  const NormalMap map = generate("thread", {{"pitch_texels", "16"}}, 64);
  int up = 0, down = 0;
  for (const Vec3f& m : map.texels()) {
    EXPECT_EQ(m.x(), 0.0f);
    EXPECT_TRUE(near(degrees(std::atan(test::tanTilt(m))), 60.0, 0.0, 1e-4));
    (m.y() > 0 ? up : down) += 1;
  }
  EXPECT_EQ(up, down);
  EXPECT_TRUE(near(muAlong(map, 0, 1), muAlong(map, 0, -1), 1e-9));
  EXPECT_EQ(muAlong(map, 1, 0), 0.0);
}

TEST(ThreadGenerator, HelixLeansTheRidges) {
  // One start: the profile advances one pitch per map width, so the gradient leans by
  // pitch / size across the axis.
  const NormalMap map = generate("thread", {{"starts", "1"}, {"pitch_texels", "8"}}, 64);
  for (const Vec3f& m : map.texels()) {
    EXPECT_TRUE(near(m.x() / m.y(), 8.0 / 64.0, 1e-4));
  }
  // Whole starts tile: column 0 continues column 63 shifted by one pitch over the width.
  EXPECT_TRUE(near(map.at(0, 10).y(), map.at(63, 2).y(), 0.0, 1e-6));
}

TEST(ConesGenerator, FlanksTiltAlphaOutwardAndCoverPiBaseSquared) {
  // Large cones (radius 32 texels): every flank texel tilts alpha, away from its apex.
  const NormalMap map = generate("cones", {{"flank_angle", "30"}, {"period", "64"}}, 256);
  int flank = 0;
  for (int j = 0; j < map.height(); ++j) {
    for (int i = 0; i < map.width(); ++i) {
      const Vec3f& m = map.at(i, j);
      if (m.z() == 1.0f) continue;
      ++flank;
      EXPECT_TRUE(near(degrees(std::atan(test::tanTilt(m))), 30.0, 0.0, 1e-4));
      // Outward: along the offset from the apex at (32, 32) + 64 (m, n) texels.
      const double dx = std::fmod(i + 0.5, 64.0) - 32.0, dy = std::fmod(j + 0.5, 64.0) - 32.0;
      EXPECT_GT(m.x() * dx + m.y() * dy, 0.0);
    }
  }
  // base 0.5: the cones cover pi / 4 of the plane.
  EXPECT_TRUE(near(flank / 65536.0, kPi / 4.0, 0.01));
}

TEST(ConesGenerator, ModelValueIsBaseSquaredTimesBowdenTabor) {
  // mu_d = base^2 (2/pi) tan(alpha) in every direction (docs/textures.md), alpha 5 to 45.
  for (double alpha : {5.0, 15.0, 30.0, 45.0}) {
    for (double base : {0.5, 0.3}) {
      const NormalMap map = generate("cones",
                                     {{"flank_angle", std::to_string(alpha)},
                                      {"period", "64"},
                                      {"base", std::to_string(base)}},
                                     256);
      const double expected = base * base * 2.0 / kPi * std::tan(alpha * kPi / 180.0);
      for (int k = 0; k < 16; ++k) {
        const double a = 2.0 * kPi * k / 16.0;
        EXPECT_TRUE(near(muAlong(map, std::cos(a), std::sin(a)), expected, 0.02))
            << "alpha " << alpha << " base " << base << " direction " << k;
      }
    }
  }
}

}  // namespace
}  // namespace asperity
