// The debug draw list (src/world/debug_draw.cpp): layer parsing and the geometry of each layer.
#include "asperity/world/debug_draw.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

Contact restingContact() {
  Contact c;
  c.point = Vec3(0.3, -0.2, 0.0);
  c.normal = Vec3::UnitZ();
  c.t = Vec3::UnitX();
  c.b = Vec3::UnitY();
  c.mu = DirectionalMu::uniform(4, 0.5f);
  c.mu.mu[1] = 0.25f;  // along +b
  c.lambda_n = 0.2;    // N s
  return c;
}

TEST(DebugDraw, ParsesLayerLists) {
  EXPECT_EQ(parseDebugLayers("contacts"), uint32_t(kLayerContacts));
  EXPECT_EQ(parseDebugLayers("contacts, frames,cones,patches"),
            uint32_t(kLayerContacts | kLayerFrames | kLayerCones | kLayerPatches));
  EXPECT_EQ(parseDebugLayers("all"), parseDebugLayers("contacts,frames,cones,patches"));
  EXPECT_EQ(parseDebugLayers(""), 0u);
  EXPECT_EQ(parseDebugLayers("none"), 0u);
}

TEST(DebugDraw, UnknownLayerNamesItself) {
  try {
    parseDebugLayers("contacts,normals");
    FAIL() << "accepted 'normals'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown layer 'normals'"), std::string::npos);
  }
}

TEST(DebugDraw, ContactPointsAndFallbackColour) {
  Contact a = restingContact(), b = restingContact();
  b.fallback = true;
  const std::vector<Contact> contacts{a, b};
  DebugDrawOptions o;
  o.layers = kLayerContacts;
  DebugDrawList list;
  appendContactLayers(contacts, 0.01, o, list);
  ASSERT_EQ(list.points.size(), 2u);
  EXPECT_EQ(list.points[0].position, a.point);
  EXPECT_EQ(list.points[0].color, o.contact_color);
  EXPECT_EQ(list.points[1].color, o.fallback_color);
  EXPECT_TRUE(list.lines.empty());
}

TEST(DebugDraw, FramesAreTheContactAxes) {
  const Contact c = restingContact();
  DebugDrawOptions o;
  o.layers = kLayerFrames;
  o.frame_length = 0.1;
  DebugDrawList list;
  appendContactLayers(std::span(&c, 1), 0.01, o, list);
  ASSERT_EQ(list.lines.size(), 3u);
  EXPECT_TRUE((list.lines[0].b - (c.point + 0.1 * c.t)).norm() < 1e-12);
  EXPECT_TRUE((list.lines[1].b - (c.point + 0.1 * c.b)).norm() < 1e-12);
  EXPECT_TRUE((list.lines[2].b - (c.point + 0.1 * c.normal)).norm() < 1e-12);
}

TEST(DebugDraw, PatchIsASquareOfWidthW) {
  const Contact c = restingContact();
  DebugDrawOptions o;
  o.layers = kLayerPatches;
  o.patch_width = 0.02;
  DebugDrawList list;
  appendContactLayers(std::span(&c, 1), 0.01, o, list);
  ASSERT_EQ(list.polygons.size(), 1u);
  const auto& loop = list.polygons[0].loop;
  ASSERT_EQ(loop.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(near((loop[(i + 1) % 4] - loop[i]).norm(), 0.02, 1e-12));
    EXPECT_TRUE(near((loop[i] - c.point).dot(c.normal), 0.0, 0.0, 1e-15));
  }
}

TEST(DebugDraw, ConeVerticesAreMuTimesNormalForceAlongEachDirection) {
  // SPEC 4, polygon: vertex k at mu_k d_k * (lambda_n / dt) * scale.
  const Contact c = restingContact();
  DebugDrawOptions o;
  o.layers = kLayerCones;
  o.cone_scale = 0.01;
  const double dt = 0.01;
  DebugDrawList list;
  appendContactLayers(std::span(&c, 1), dt, o, list);
  ASSERT_EQ(list.lines.size(), 8u);  // a spoke and an edge per direction
  const double force = c.lambda_n / dt;
  for (int k = 0; k < 4; ++k) {
    const double angle = 0.5 * kPi * k;
    const Vec3 d = std::cos(angle) * c.t + std::sin(angle) * c.b;
    const Vec3 expected = c.point + d * (double(c.mu.mu[size_t(k)]) * force * o.cone_scale);
    const DebugLine& spoke = list.lines[size_t(2 * k)];
    EXPECT_TRUE((spoke.b - expected).norm() < 1e-6) << k;
    EXPECT_EQ(spoke.color, directionColor(angle));
  }
}

TEST(DebugDraw, NoConeWithoutNormalImpulse) {
  Contact c = restingContact();
  c.lambda_n = 0.0;
  DebugDrawOptions o;
  o.layers = kLayerCones;
  DebugDrawList list;
  appendContactLayers(std::span(&c, 1), 0.01, o, list);
  EXPECT_TRUE(list.empty());
}

TEST(DebugDraw, DirectionColoursAreDistinctHues) {
  EXPECT_EQ(directionColor(0.0), Vec3(1.0, 0.0, 0.0));
  EXPECT_TRUE((directionColor(2.0 * kPi) - Vec3(1.0, 0.0, 0.0)).norm() < 1e-12);
  EXPECT_GT((directionColor(0.5 * kPi) - directionColor(1.5 * kPi)).norm(), 1.0);
}

}  // namespace
}  // namespace asperity
