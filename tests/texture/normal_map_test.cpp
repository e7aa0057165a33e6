// NormalMap: flat construction, bilinear sampling at centres, midpoints and edges (Repeat, Clamp).
#include "asperity/texture/normal_map.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// A 2 x 2 map with four distinct unit normals.
NormalMap fourTexels() {
  NormalMap map(2, 2);
  map.at(0, 0) = Vec3f(0.6f, 0.0f, 0.8f);
  map.at(1, 0) = Vec3f(0.0f, 0.6f, 0.8f);
  map.at(0, 1) = Vec3f(-0.6f, 0.0f, 0.8f);
  map.at(1, 1) = Vec3f(0.0f, -0.6f, 0.8f);
  return map;
}

void expectVec(const Vec3f& actual, const Vec3f& expected, double tol = 1e-6) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(near(actual[c], expected[c], 0.0, tol)) << "component " << c;
  }
}

TEST(NormalMap, FlatConstructorHoldsUpNormals) {
  const NormalMap map(3, 5);
  EXPECT_EQ(map.width(), 3);
  EXPECT_EQ(map.height(), 5);
  ASSERT_EQ(map.texels().size(), 15u);
  for (const Vec3f& m : map.texels()) {
    expectVec(m, Vec3f(0, 0, 1), 0.0);
  }
  EXPECT_TRUE(NormalMap().empty());
  expectVec(NormalMap().sample(0.3f, 0.7f), Vec3f(0, 0, 1), 0.0);
}

TEST(NormalMap, TexelCentresAreExact) {
  const NormalMap map = fourTexels();
  for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Clamp}) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const float u = (static_cast<float>(i) + 0.5f) / 2.0f;
        const float v = (static_cast<float>(j) + 0.5f) / 2.0f;
        expectVec(map.sample(u, v, wrap), map.at(i, j));
      }
    }
  }
}

TEST(NormalMap, MidpointIsNormalisedAverage) {
  const NormalMap map = fourTexels();
  // Between texels (0,0) and (1,0) along u.
  const Vec3f expected = (0.5f * (map.at(0, 0) + map.at(1, 0))).normalized();
  expectVec(map.sample(0.5f, 0.25f), expected);
  // Centre of all four: the x and y parts cancel.
  expectVec(map.sample(0.5f, 0.5f), Vec3f(0, 0, 1));
}

TEST(NormalMap, RepeatWrapsAndClampHoldsAtEdges) {
  const NormalMap map = fourTexels();
  // u = 0 lies halfway between texel 1 (wrapped) and texel 0 under Repeat.
  const Vec3f wrapped = (0.5f * (map.at(1, 0) + map.at(0, 0))).normalized();
  expectVec(map.sample(0.0f, 0.25f, WrapMode::Repeat), wrapped);
  expectVec(map.sample(1.0f, 0.25f, WrapMode::Repeat), wrapped);
  expectVec(map.sample(-3.0f, 0.25f, WrapMode::Repeat), wrapped);
  // Clamp reads the edge texel there and beyond.
  expectVec(map.sample(0.0f, 0.25f, WrapMode::Clamp), map.at(0, 0));
  expectVec(map.sample(-5.0f, 0.25f, WrapMode::Clamp), map.at(0, 0));
  expectVec(map.sample(7.0f, 0.75f, WrapMode::Clamp), map.at(1, 1));
  // Repeat has period 1 in both coordinates.
  expectVec(map.sample(0.3f + 4.0f, 0.6f - 2.0f), map.sample(0.3f, 0.6f), 1e-5);
}

TEST(NormalMap, NonFiniteCoordinatesStayInside) {
  const NormalMap map = fourTexels();
  const Vec3f m =
      map.sample(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity());
  EXPECT_TRUE(near(m.norm(), 1.0, 1e-6));
}

}  // namespace
}  // namespace asperity
