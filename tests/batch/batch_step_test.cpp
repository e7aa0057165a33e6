// A batch's actions and step: actions hold for every step of one call and are then cleared,
// velocity targets move kinematic bodies exactly, bad actions name their body, and a failing
// world is named.
#include <gtest/gtest.h>

#include "asperity/batch/batch.hpp"
#include "asperity/error.hpp"
#include "batch/batch_scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::act;
using test::pushedBoxes;

TEST(BatchStep, ActionsHoldForEveryStepOfOneCall) {
  Batch once(pushedBoxes(3, 2)), each(pushedBoxes(3, 2));
  // k calls of one step with the same actions agree with one call of k steps.
  act(once, 0);
  once.step(5);
  for (int s = 0; s < 5; ++s) {
    act(each, 0);
    each.step();
  }
  EXPECT_EQ(once.stateHashes(), each.stateHashes());
  // They are cleared after the call: no force acts, the finger keeps its velocity.
  once.step(3);
  for (int s = 0; s < 3; ++s) each.step();
  EXPECT_EQ(once.stateHashes(), each.stateHashes());
  EXPECT_EQ(once.world(0).loads().size(), 0u);
}

TEST(BatchStep, VelocityTargetsMoveKinematicBodiesAtThatVelocity) {
  Batch batch(pushedBoxes(2, 1));
  const BodyId finger = batch.bodyIndex("finger");
  const std::vector<double> v = {0.5, 0, 0, 0, -0.25, 0};
  batch.setAction(BatchAction::LinearVelocity, finger, v);
  batch.step(10);
  // 10 steps of 10 ms: 5 cm along x for world 0, -2.5 cm along y for world 1.
  const std::vector<double>& p = batch.state().positions;
  const size_t bodies = batch.bodyNames().size();
  EXPECT_NEAR(p[finger * 3], 0.05, 1e-12);
  EXPECT_NEAR(p[(bodies + finger) * 3 + 1], -0.2 - 0.025, 1e-12);
  // A spin about z with the velocity of the origin kept.
  batch.setAction(BatchAction::AngularVelocity, finger, std::vector<double>{0, 0, 1, 0, 0, 2});
  batch.setAction(BatchAction::LinearVelocity, finger, v);
  batch.step();
  const std::vector<double>& w = batch.state().angular_velocities;
  EXPECT_EQ(w[(bodies + finger) * 3 + 2], 2.0);
  EXPECT_EQ(batch.state().linear_velocities[finger * 3], 0.5);
}

TEST(BatchStep, BadActionsAreRejectedNamingTheBodyOrJoint) {
  Batch batch(pushedBoxes(2, 1));
  const std::vector<double> three = {1, 2, 3, 4, 5, 6}, nan = {1, 2, 3, 4, std::nan(""), 6};
  auto error = [&](BatchAction kind, uint32_t target, const std::vector<double>& v) {
    return test::errorOf([&] { batch.setAction(kind, target, v); });
  };
  EXPECT_EQ(error(BatchAction::Force, 1, {1, 2, 3}),
            "force on 'box': needs 6 numbers (n x 3), got 3");
  EXPECT_EQ(error(BatchAction::Force, 1, nan),
            "force on 'box': the value of world 1 is not finite");
  EXPECT_EQ(error(BatchAction::Force, 0, three),
            "force on 'plate': the body is static (forces and torques move dynamic bodies only)");
  EXPECT_EQ(error(BatchAction::Torque, 3, three),
            "torque on 'finger': the body is kinematic (forces and torques move dynamic bodies "
            "only)");
  EXPECT_EQ(error(BatchAction::LinearVelocity, 0, three),
            "velocity on 'plate': the body is static");
  EXPECT_EQ(error(BatchAction::Force, 9, three), "force on body id 9: no such body");
  EXPECT_EQ(error(BatchAction::JointTarget, 1, {0.1, 0.2}),
            "joint target on 'pin': only distance joints take a target");
  EXPECT_EQ(error(BatchAction::JointTarget, 5, {0.1, 0.2}),
            "joint target on joint id 5: no such joint");
  EXPECT_EQ(test::errorOf([&] { batch.step(-1); }), "step: the step count must be >= 0, got -1");
  // A rejected action leaves the others as they were.
  batch.setAction(BatchAction::LinearVelocity, 3, three);
  EXPECT_NE(error(BatchAction::LinearVelocity, 3, nan), "");
  batch.step();
  EXPECT_EQ(batch.state().linear_velocities[3 * 3], 1.0);
}

TEST(BatchStep, AFailingWorldIsNamedAndTheOthersStep) {
  Batch batch(pushedBoxes(5, 2));
  // A force far too large for worlds 2 and 4 (max_speed 1000 m/s).
  std::vector<double> f(15, 0.0);
  f[2 * 3] = f[4 * 3] = 1e9;
  batch.setAction(BatchAction::Force, batch.bodyIndex("box"), f);
  const std::string e = test::errorOf([&] { batch.step(2); });
  EXPECT_EQ(e.rfind("world 2: ", 0), 0u) << e;
  EXPECT_EQ(batch.world(0).stepCount(), 2);
  EXPECT_EQ(batch.world(2).stepCount(), 1);
}

}  // namespace
}  // namespace asperity
