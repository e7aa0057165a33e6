// The texture's +u axis in world at a contact point (planes and boxes, texture rotation).
#include "dynamics/texture_axis.hpp"

#include <gtest/gtest.h>

namespace asperity {
namespace {

Body planeBody(double rotation) {
  Body b;
  b.type = BodyType::Static;
  Shape s;
  s.type = ShapeType::Plane;
  s.surface.texture_rotation = rotation;
  b.shapes = {s};
  return b;
}

TEST(TextureAxis, PlaneUIsWorldXTurnedByTheTextureRotation) {
  const auto u0 = textureAxisWorld(planeBody(0.0), 0, -1, Vec3(0.3, 0.2, 0));
  ASSERT_TRUE(u0.has_value());
  EXPECT_LT((*u0 - Vec3::UnitX()).norm(), 1e-12);
  const auto u90 = textureAxisWorld(planeBody(kPi / 2), 0, -1, Vec3::Zero());
  ASSERT_TRUE(u90.has_value());
  EXPECT_LT((*u90 - Vec3::UnitY()).norm(), 1e-12);
}

TEST(TextureAxis, BoxTopFaceTurnsWithTheBody) {
  Body b;
  Shape s;
  s.type = ShapeType::Box;
  b.shapes = {s};
  b.pose.rotation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()));
  // Top face (+z, face id 4): T = +x of the box, i.e. world +y after the turn.
  const auto u = textureAxisWorld(b, 0, 4, Vec3(0, 0, 0.1));
  ASSERT_TRUE(u.has_value());
  EXPECT_LT((*u - Vec3::UnitY()).norm(), 1e-12);
}

TEST(TextureAxis, BadShapeIndexGivesNothing) {
  EXPECT_FALSE(textureAxisWorld(planeBody(0.0), 3, -1, Vec3::Zero()).has_value());
  EXPECT_FALSE(textureAxisWorld(planeBody(0.0), -1, -1, Vec3::Zero()).has_value());
}

}  // namespace
}  // namespace asperity
