// Height fields: blur, rotation, central differences and slope scaling.
#include "texture/height_field.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;
using texgen::Edge;
using texgen::Field;

Field plane(int n, double a, double b) {
  Field f(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) f.at(i, j) = a * i + b * j;
  return f;
}

TEST(HeightField, NormalsOfAPlaneAreItsNormal) {
  const Field f = plane(8, 0.5, -0.25);
  const NormalMap map = texgen::normalsFromHeights(f, 2.0, Edge::Clamp);
  const Vec3f expected = Vec3f(-1.0f, 0.5f, 1.0f).normalized();
  for (const Vec3f& m : map.texels()) {
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(near(m[c], expected[c], 0.0, 1e-6));
  }
}

TEST(HeightField, WrapDifferencesSeeTheOtherSide) {
  Field f(4, 1);
  f.at(3, 0) = 2.0;
  EXPECT_EQ(texgen::slopeU(f, 0, 0, Edge::Wrap), -1.0);  // (h(1) - h(-1 -> 3)) / 2
  EXPECT_EQ(texgen::slopeU(f, 0, 0, Edge::Clamp), 0.0);  // one-sided h(1) - h(0)
  EXPECT_EQ(texgen::slopeV(f, 2, 0, Edge::Wrap), 0.0);
}

TEST(HeightField, BoxBlurKeepsTheMeanAndSmooths) {
  texgen::Rng rng(3);
  Field f = texgen::whiteNoise(32, 32, rng);
  double before = 0.0;
  for (double v : f.values) before += v;
  const double rough = texgen::rmsSlope(f, Edge::Wrap);
  texgen::boxBlur(f, 2, 2);
  double after = 0.0;
  for (double v : f.values) after += v;
  EXPECT_TRUE(near(after, before, 1e-9, 1e-9));
  EXPECT_LT(texgen::rmsSlope(f, Edge::Wrap), 0.3 * rough);
}

TEST(HeightField, ScaleToRmsSlopeAndStandardise) {
  texgen::Rng rng(4);
  Field f = texgen::whiteNoise(16, 16, rng);
  texgen::scaleToRmsSlope(f, 0.3, Edge::Wrap);
  EXPECT_TRUE(near(texgen::rmsSlope(f, Edge::Wrap), 0.3, 1e-12));
  texgen::standardise(f);
  double s1 = 0.0, s2 = 0.0;
  for (double v : f.values) {
    s1 += v;
    s2 += v * v;
  }
  EXPECT_TRUE(near(s1 / 256.0, 0.0, 0.0, 1e-12));
  EXPECT_TRUE(near(s2 / 256.0, 1.0, 1e-12));
  Field flat(4, 4, 2.0);
  texgen::standardise(flat);
  EXPECT_EQ(flat.values, std::vector<double>(16, 0.0));
}

TEST(HeightField, RotationByNinetyDegreesIsExact) {
  const Field f = plane(8, 1.0, 0.0);  // rises along u
  const Field r = texgen::rotated(f, 0.5 * kPi);
  // Content turned from +u toward +v: the output reads input (j, -1 - i) wrapped.
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) EXPECT_EQ(r.at(i, j), f.at(j, 7 - i));
  EXPECT_EQ(texgen::rotated(f, 0.0).values, f.values);
}

}  // namespace
}  // namespace asperity
