// The integration stage: semi-implicit Euler for positions, exact rotations, kinematic bodies.
#include <gtest/gtest.h>

#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

TEST(Integrate, FreeFallFollowsSemiImplicitEuler) {
  // v_n = -g n dt, x_n = -g dt^2 n (n + 1) / 2.
  World world;
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  const int n = 50;
  for (int i = 0; i < n; ++i) world.step();
  const double g = 9.81, dt = 0.01;
  EXPECT_TRUE(near(world.body(cube).linear_velocity.z(), -g * n * dt, 1e-12));
  EXPECT_TRUE(near(world.body(cube).pose.position.z(), -g * dt * dt * n * (n + 1) / 2, 1e-12));
}

TEST(Integrate, SpinAboutAPrincipalAxisTurnsByOmegaT) {
  WorldSettings s;
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDesc d = boxDesc("brick", Vec3(0.1, 0.2, 0.3), {});
  d.angular_velocity = Vec3(0, 0, 2.0);
  const BodyId id = world.createBody(d);
  for (int i = 0; i < 100; ++i) world.step();
  const Eigen::AngleAxisd aa(world.body(id).pose.rotation);
  EXPECT_TRUE(near(aa.angle(), 2.0, 1e-9));
  EXPECT_TRUE(near(aa.axis().z(), 1.0, 1e-12));
  EXPECT_TRUE(near(world.body(id).pose.rotation.norm(), 1.0, 1e-14));
}

TEST(Integrate, KinematicBodiesMoveWithTheirVelocityAndStaticOnesStay) {
  World world;
  BodyDesc k = boxDesc("belt", Vec3(1, 1, 0.1), {});
  k.type = BodyType::Kinematic;
  k.linear_velocity = Vec3(0.5, 0, 0);
  const BodyId belt = world.createBody(k);
  BodyDesc s = boxDesc("wall", Vec3::Constant(0.1), {Vec3(5, 0, 0), Quat::Identity()});
  s.type = BodyType::Static;
  const BodyId wall = world.createBody(s);
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_TRUE(near(world.body(belt).pose.position.x(), 0.5, 1e-12));
  EXPECT_EQ(world.body(belt).linear_velocity, Vec3(0.5, 0, 0));  // no gravity on it
  EXPECT_EQ(world.body(wall).pose.position, Vec3(5, 0, 0));
}

}  // namespace
}  // namespace asperity
