// State checks after each step: non-finite values and runaway speeds stop the run with a
// StepError naming the body, the step and the likely cause; load-time stability warnings.
#include "asperity/world/state_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"

namespace asperity {
namespace {

World weightless(double dt = 0.01) {
  WorldSettings s;
  s.gravity = Vec3::Zero();
  s.dt = dt;
  return World(s);
}

// The StepError that stepping `world` up to `steps` times throws; fails the test if none.
StepError stepUntilError(World& world, int steps) {
  for (int i = 0; i < steps; ++i) {
    try {
      world.step();
    } catch (const StepError& e) {
      return e;
    }
  }
  ADD_FAILURE() << "no StepError in " << steps << " steps";
  return StepError("", kNoBody, -1);
}

TEST(StateCheck, OrdinaryMotionPassesAndWarnsOfNothing) {
  // A cube resting on the ground for a second: no error, no warning.
  World world;
  world.createBody(groundPlaneDesc());
  world.createBody(boxDesc("cube", Vec3::Constant(0.1), Transform{Vec3(0, 0, 0.1)}));
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_TRUE(stabilityWarnings(world).empty());
}

TEST(StateCheck, RunawaySpeedNamesBodyAndStep) {
  // 999 m/s is allowed; 1001 m/s is above the default limit of 1000 m/s at the first step.
  // Their paths do not cross (they would collide: fast bodies are swept).
  World world = weightless();
  world.createBody(boxDesc("slow", Vec3::Constant(0.1), {}));
  const BodyId fast =
      world.createBody(boxDesc("fast", Vec3::Constant(0.1), Transform{Vec3(0, 5, 0)}));
  world.body(0).linear_velocity = Vec3(999, 0, 0);
  world.body(fast).linear_velocity = Vec3(0, 1001, 0);
  const StepError e = stepUntilError(world, 1);
  EXPECT_EQ(e.body(), fast);
  EXPECT_EQ(e.step(), 1);
  EXPECT_NE(std::string(e.what()).find("step 1 (t = 0.01 s): body 'fast': speed 1e+03 m/s"),
            std::string::npos)
      << e.what();
  // The limit is a setting; 0 switches it off.
  world.settings().max_speed = 0.0;
  EXPECT_NO_THROW(world.step());
}

// Bodies piled into one point: every pair overlaps. Past max_pairs the step stops at the
// broadphase, before the pairs get their narrowphase state, naming the bodies in most pairs.
TEST(StateCheck, BodiesPiledInOnePointStopAtThePairBudget) {
  World world = weightless();
  for (int i = 0; i < 1000; ++i)
    world.createBody(boxDesc("box" + std::to_string(i), Vec3::Constant(0.1), {}));
  const StepError e = stepUntilError(world, 1);
  EXPECT_EQ(e.step(), 1);
  EXPECT_EQ(e.body(), 0u);
  EXPECT_NE(std::string(e.what()).find("step 1: 499500 overlapping shape pairs, more than "
                                       "max_pairs 100000 (pairs of the bodies in most: 999, "
                                       "999, 999) in \"box0\", \"box1\", \"box2\""),
            std::string::npos)
      << e.what();
}

TEST(StateCheck, ThePairBudgetIsASettingAndZeroHasNone) {
  for (const int64_t budget : {int64_t{9}, int64_t{10}, int64_t{0}}) {
    World world = weightless();
    world.settings().max_pairs = budget;
    for (int i = 0; i < 5; ++i)  // 10 pairs
      world.createBody(boxDesc("box" + std::to_string(i), Vec3::Constant(0.1), {}));
    if (budget == 9) {
      EXPECT_NE(std::string(stepUntilError(world, 1).what()).find("10 overlapping shape pairs"),
                std::string::npos);
    } else {
      EXPECT_NO_THROW(world.step()) << budget;
    }
  }
}

TEST(StateCheck, NonFiniteVelocityIsNamed) {
  World world = weightless();
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  world.body(cube).angular_velocity.z() = std::numeric_limits<double>::quiet_NaN();
  const StepError e = stepUntilError(world, 1);
  EXPECT_EQ(e.body(), cube);
  EXPECT_NE(std::string(e.what()).find("body 'cube': "), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
}

TEST(StateCheck, StiffSpringIsWarnedAndBlamed) {
  // m = 8 kg, k = 1e7 N/m: period 2 pi sqrt(8e-7) = 5.6 ms, under 2 dt = 20 ms. Explicit
  // spring forces then grow the amplitude every step until the speed limit stops the run.
  World world = weightless();
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  world.body(cube).pose.position.x() = 0.01;
  world.addSpring(SpringDesc{"stiff", cube, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 1e7, 0.0});
  const auto warnings = stabilityWarnings(world);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("spring 'stiff': period 0.00562 s is shorter than 2 dt", 0), 0u)
      << warnings[0];
  const StepError e = stepUntilError(world, 100);
  EXPECT_EQ(e.body(), cube);
  EXPECT_NE(std::string(e.what()).find("likely cause: spring 'stiff' has a period"),
            std::string::npos)
      << e.what();
}

TEST(StateCheck, JointMassRatioBeyondAMillionIsWarned) {
  // 8 kg against 8e-9 kg (a 1 mm cube of density 8): ratio 1e9.
  World world = weightless();
  const BodyId heavy = world.createBody(boxDesc("heavy", Vec3::Constant(0.1), {}));
  const BodyId light =
      world.createBody(boxDesc("light", Vec3::Constant(0.0005), Transform{Vec3(0.2, 0, 0)}, 8.0));
  JointDesc joint;
  joint.name = "link";
  joint.body_a = heavy;
  joint.body_b = light;
  world.createJoint(joint);
  const auto warnings = stabilityWarnings(world);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind("joint 'link': mass ratio 1e+09 between 'heavy' and 'light'", 0), 0u)
      << warnings[0];
  EXPECT_NE(likelyCause(world, light).find("joint 'link' joins masses in a ratio of 1e+09"),
            std::string::npos);
}

}  // namespace
}  // namespace asperity
