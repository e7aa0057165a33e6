// The driver stage: springs (the paper's mouse spring) and timed loads.
#include "dynamics/drivers.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

World weightless(double dt = 0.001) {
  WorldSettings s;
  s.gravity = Vec3::Zero();
  s.dt = dt;
  return World(s);
}

TEST(Drivers, SpringOscillatesAtItsNaturalFrequency) {
  // m = 8 kg, k = 800 N/m: omega = 10 rad/s. Start 5 cm off the target at rest: after half
  // a period (pi / 10 s) the body is 5 cm on the other side.
  World world = weightless();
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  world.body(cube).pose.position.x() = 0.05;
  world.addSpring(SpringDesc{"mouse", cube, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 800.0, 0.0});
  const int steps = static_cast<int>(std::round(kPi / 10.0 / 0.001));
  for (int i = 0; i < steps; ++i) world.step();
  EXPECT_TRUE(near(world.body(cube).pose.position.x(), -0.05, 0.01));
}

TEST(Drivers, DampedSpringSettlesOnAMovingTarget) {
  // A critically damped spring dragging the body at 0.2 m/s along y: it ends up following.
  World world = weightless(0.01);
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  const double k = 800.0, c = 2.0 * std::sqrt(k * 8.0);
  world.addSpring(SpringDesc{"drag", cube, Vec3::Zero(), Vec3::Zero(), Vec3(0, 0.2, 0), k, c});
  for (int i = 0; i < 300; ++i) world.step();
  EXPECT_TRUE(near(world.body(cube).linear_velocity.y(), 0.2, 1e-3));
  // Steady following needs no spring force: the body sits on the target.
  EXPECT_LT(std::abs(world.body(cube).pose.position.y() - 0.2 * world.time()), 1e-3);
}

TEST(Drivers, OffCentreSpringTurnsTheBody) {
  World world = weightless();
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  // Pulling the +x face along +y spins the body about +z.
  world.addSpring(
      SpringDesc{"twist", cube, Vec3(0.1, 0, 0), Vec3(0.1, 0.1, 0), Vec3::Zero(), 100.0, 0.0});
  world.step();
  // F = k (0, 0.1, 0) = (0, 10, 0) N at r = (0.1, 0, 0): torque (0, 0, 1) N m on an 8 kg cube
  // of side 0.2 m (I = 8 * 0.08 / 12), so w_z = dt * 1 / I after one step, nothing else.
  const double inertia = 8.0 * (0.04 + 0.04) / 12.0;
  const Vec3 w = world.body(cube).angular_velocity;
  EXPECT_TRUE(near(w.z(), world.settings().dt / inertia, 1e-12)) << w.z();
  EXPECT_LT(std::abs(w.x()) + std::abs(w.y()), 1e-15);
}

TEST(Drivers, ForceActsOnlyWithinItsInterval) {
  // F = 16 N on 8 kg during [0.1, 0.3) s: dv = 2 m/s^2 * 0.2 s = 0.4 m/s.
  World world = weightless(0.01);
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  world.addLoad(
      LoadDesc{"push", cube, LoadDesc::Kind::Force, Vec3(16, 0, 0), Vec3::Zero(), 0.1, 0.3});
  for (int i = 0; i < 50; ++i) world.step();
  EXPECT_TRUE(near(world.body(cube).linear_velocity.x(), 0.4, 1e-9));
}

TEST(Drivers, ImpulseFiresExactlyOnce) {
  World world = weightless(0.01);
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  world.addLoad(
      LoadDesc{"kick", cube, LoadDesc::Kind::Impulse, Vec3(0, 4, 0), Vec3::Zero(), 0.25, 0.0});
  world.addLoad(LoadDesc{"spin", cube, LoadDesc::Kind::AngularImpulse, Vec3(0, 0, 0.1),
                         Vec3::Zero(), 0.0, 0.0});
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_TRUE(near(world.body(cube).linear_velocity.y(), 0.5, 1e-12));
  // I = m s^2 / 6 = 8 * 0.04 / 6.
  EXPECT_TRUE(near(world.body(cube).angular_velocity.z(), 0.1 / (8.0 * 0.04 / 6.0), 1e-9));
}

TEST(Drivers, OffCentreImpulseAndTorque) {
  World world = weightless(0.01);
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  const double inertia = 8.0 * 0.04 / 6.0;
  // An impulse on the +x face along +y: linear 1/8, angular 0.1 / I about +z.
  world.addLoad(
      LoadDesc{"tap", cube, LoadDesc::Kind::Impulse, Vec3(0, 1, 0), Vec3(0.1, 0, 0), 0.0, 0.0});
  world.step();
  EXPECT_TRUE(near(world.body(cube).linear_velocity.y(), 1.0 / 8.0, 1e-12));
  EXPECT_TRUE(near(world.body(cube).angular_velocity.z(), 0.1 / inertia, 1e-9));
  // A torque of 1 N m for 0.1 s adds 0.1 / I.
  world.addLoad(LoadDesc{"twist", cube, LoadDesc::Kind::Torque, Vec3(0, 0, 1), Vec3::Zero(),
                         world.time(), world.time() + 0.1});
  for (int i = 0; i < 20; ++i) world.step();
  EXPECT_TRUE(near(world.body(cube).angular_velocity.z(), 0.2 / inertia, 1e-6));
}

// The stage is a function of the data it is handed: bodies without a world, one impulse due
// now, one due later; gravity reaches the dynamic body only.
TEST(Drivers, TheStageRunsOnPlainBodies) {
  BodyDesc floor = boxDesc("floor", Vec3(1, 1, 0.1), {});
  floor.type = BodyType::Static;
  std::vector<Body> bodies = {makeBody(boxDesc("cube", Vec3::Constant(0.1), {})), makeBody(floor)};
  const double mass = 1.0 / bodies[0].inverse_mass;
  std::vector<LoadDesc> loads(2);
  loads[0] = {"now", 0, LoadDesc::Kind::Impulse, Vec3(2.0, 0, 0), Vec3::Zero(), 0.5};
  loads[1] = {"later", 0, LoadDesc::Kind::Impulse, Vec3(0, 5.0, 0), Vec3::Zero(), 0.6};
  const double dt = 0.01;
  applyDrivers(bodies, {}, loads, Vec3(0, 0, -10.0), 0.5, dt);
  EXPECT_TRUE(near(bodies[0].linear_velocity.x(), 2.0 / mass, 1e-12));
  EXPECT_EQ(bodies[0].linear_velocity.y(), 0.0);
  EXPECT_TRUE(near(bodies[0].linear_velocity.z(), -10.0 * dt, 1e-12));
  EXPECT_EQ(bodies[1].linear_velocity, Vec3::Zero());
}

}  // namespace
}  // namespace asperity
