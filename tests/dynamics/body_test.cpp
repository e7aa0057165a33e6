// Live bodies from descriptions: centre-of-mass frame, principal axes, inverse inertia in
// world, static and kinematic bodies, and bad descriptions.
#include "asperity/dynamics/body.hpp"

#include <gtest/gtest.h>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

Shape cube(double half, const Vec3& at = Vec3::Zero()) {
  Shape s;
  s.type = ShapeType::Box;
  s.half_extents = Vec3::Constant(half);
  s.local.position = at;
  return s;
}

TEST(Body, CubeMassAndInverseInertia) {
  BodyDesc d;
  d.shapes = {cube(0.1)};
  const Body b = makeBody(d);
  const double m = 8.0;  // 1000 kg/m^3 * 0.008 m^3
  EXPECT_TRUE(near(b.inverse_mass, 1.0 / m, 1e-12));
  EXPECT_TRUE(near(b.inverse_inertia_local.x(), 1.0 / (m / 6 * 0.04), 1e-12));
}

TEST(Body, CompoundMovesTheFrameToTheCentreOfMass) {
  // A big and a small cube: the body frame moves to their centre of mass, the shapes follow,
  // and the description's pose is recovered by descriptionPose().
  BodyDesc d;
  d.pose.position = Vec3(1, 0, 0);
  d.shapes = {cube(0.1), cube(0.05, Vec3(0.15, 0, 0))};
  const Body b = makeBody(d);
  const double m1 = 8.0, m2 = 1.0;
  const double com_x = (m2 * 0.15) / (m1 + m2);
  EXPECT_TRUE(near(b.pose.position.x(), 1.0 + com_x, 1e-12));
  EXPECT_TRUE(near(b.shapes[0].local.position.x(), -com_x, 1e-12));
  EXPECT_LT((b.descriptionPose().position - d.pose.position).norm(), 1e-12);
  // Shapes keep their place in the world.
  EXPECT_LT(((b.pose * b.shapes[1].local).position - Vec3(1.15, 0, 0)).norm(), 1e-12);
}

TEST(Body, InverseInertiaWorldFollowsTheRotation) {
  BodyDesc d;
  Shape s = cube(0.1);
  s.half_extents = Vec3(0.3, 0.1, 0.1);
  d.shapes = {s};
  d.pose.rotation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()));
  const Body b = makeBody(d);
  const Mat3 iw = b.inverseInertiaWorld();
  // The long axis now points along world y.
  EXPECT_TRUE(near(iw(1, 1), b.inverse_inertia_local.x(), 1e-9));
  EXPECT_TRUE(near(iw(0, 0), b.inverse_inertia_local.y(), 1e-9));
}

TEST(Body, StaticAndKinematicHaveInfiniteMass) {
  BodyDesc d;
  d.shapes = {cube(0.1)};
  d.linear_velocity = Vec3(1, 0, 0);
  d.type = BodyType::Static;
  const Body s = makeBody(d);
  EXPECT_EQ(s.inverse_mass, 0.0);
  EXPECT_EQ(s.linear_velocity, Vec3::Zero());
  d.type = BodyType::Kinematic;
  const Body k = makeBody(d);
  EXPECT_EQ(k.inverse_mass, 0.0);
  EXPECT_EQ(k.linear_velocity, Vec3(1, 0, 0));
}

TEST(Body, MassOverrideScalesInertia) {
  BodyDesc d;
  d.shapes = {cube(0.1)};
  d.mass_override = 2.0;
  const Body b = makeBody(d);
  EXPECT_TRUE(near(b.inverse_mass, 0.5, 1e-12));
  EXPECT_TRUE(near(b.inverse_inertia_local.x(), 1.0 / (2.0 / 6 * 0.04), 1e-12));
}

TEST(Body, BadDescriptionsNameTheBody) {
  BodyDesc d;
  d.name = "crate";
  EXPECT_THROW(makeBody(d), Error);  // dynamic without shapes
  try {
    makeBody(d);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("crate"), std::string::npos);
  }
  d.shapes = {cube(0.1)};
  d.pose.position.x() = std::nan("");
  EXPECT_THROW(makeBody(d), Error);  // not finite
  d.pose.position.x() = 0.0;
  d.pose.rotation = Quat(2, 0, 0, 0);
  EXPECT_THROW(makeBody(d), Error);  // not a unit quaternion
  d.pose.rotation = Quat::Identity();
  d.mass_override = -1.0;
  EXPECT_THROW(makeBody(d), Error);
  d.mass_override = 0.0;
  Shape plane;
  plane.type = ShapeType::Plane;
  d.shapes = {plane};
  EXPECT_THROW(makeBody(d), Error);  // a plane on a dynamic body
}

TEST(Body, PointVelocityAddsRotation) {
  Body b;
  b.linear_velocity = Vec3(1, 0, 0);
  b.angular_velocity = Vec3(0, 0, 2);
  EXPECT_LT((b.pointVelocity(Vec3(0, 1, 0)) - Vec3(-1, 0, 0)).norm(), 1e-15);
}

}  // namespace
}  // namespace asperity
