// The world as a container and stepper: momentum conservation of free bodies, jointed chains,
// bad input, lookups, the state hash and the step profile.
#include "asperity/world/world.hpp"

#include <memory>

#include <gtest/gtest.h>

#include "asperity/error.hpp"
#include "asperity/world/builders.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// Angular momentum of a body about its centre of mass, world frame: I_world w.
Vec3 angularMomentum(const Body& b) {
  return b.inverseInertiaWorld().inverse() * b.angular_velocity;
}

TEST(World, FreeBodyConservesMomentum) {
  // Torque-free tumbling of a 1:2:3 box spinning near its intermediate axis (unstable), no
  // gravity: linear momentum exactly, angular momentum to 1 % over 3 s at dt = 1 ms.
  WorldSettings s;
  s.gravity = Vec3::Zero();
  s.dt = 0.001;
  World world(s);
  BodyDesc d = boxDesc("brick", Vec3(0.05, 0.1, 0.15), {});
  d.linear_velocity = Vec3(0.3, -0.2, 0.1);
  d.angular_velocity = Vec3(0.1, 5.0, 0.1);
  const BodyId id = world.createBody(d);
  const Vec3 l0 = angularMomentum(world.body(id));
  const Vec3 p0 = world.body(id).linear_velocity;
  for (int i = 0; i < 3000; ++i) world.step();
  EXPECT_EQ(world.body(id).linear_velocity, p0);
  EXPECT_LT((angularMomentum(world.body(id)) - l0).norm(), 0.01 * l0.norm());
  EXPECT_LT((world.body(id).pose.position - (Vec3(0.3, -0.2, 0.1) * 3.0)).norm(), 1e-9);
}

TEST(World, BallJointedChainStaysConnected) {
  // Ten 0.1 m links hanging from a static anchor, released sideways: joint error < 1 mm
  // (dt = 1 ms as the paper's chain scenes).
  WorldSettings s;
  s.dt = 0.001;
  World world(s);
  BodyDesc anchor = boxDesc("anchor", Vec3::Constant(0.02), {Vec3(0, 0, 2), Quat::Identity()});
  anchor.type = BodyType::Static;
  BodyId previous = world.createBody(anchor);
  for (int i = 0; i < 10; ++i) {
    // Links lie along +x from the anchor (a horizontal chain that swings down).
    const Vec3 centre(0.05 + 0.1 * i, 0, 2);
    const BodyId link = world.createBody(
        boxDesc("link" + std::to_string(i), Vec3(0.05, 0.01, 0.01), {centre, Quat::Identity()}));
    JointDesc j;
    j.type = JointType::Ball;
    j.body_a = previous;
    j.body_b = link;
    j.anchor_a = i == 0 ? Vec3::Zero() : Vec3(0.05, 0, 0);
    j.anchor_b = Vec3(-0.05, 0, 0);
    world.createJoint(j);
    previous = link;
  }
  double worst = 0.0, lowest = 2.0;
  for (int step = 0; step < 1000; ++step) {
    world.step();
    for (int j = 0; j < 10; ++j) worst = std::max(worst, world.jointError(j));
    lowest = std::min(lowest, world.body(previous).pose.position.z());
  }
  EXPECT_LT(worst, 1e-3);
  // And it swung: the last link passed well below the anchor.
  EXPECT_LT(lowest, 1.3);
}

TEST(World, DistanceJointTakesInitialLengthAndFollowsItsCosine) {
  WorldSettings s;
  s.gravity = Vec3::Zero();
  World world(s);
  const BodyId a = world.createBody(boxDesc("a", Vec3::Constant(0.05), {}));
  const BodyId b =
      world.createBody(boxDesc("b", Vec3::Constant(0.05), {Vec3(0.3, 0, 0), Quat::Identity()}));
  JointDesc j;
  j.type = JointType::Distance;
  j.body_a = a;
  j.body_b = b;
  j.amplitude = 0.05;
  j.frequency = 1.0;
  j.phase = -0.5 * kPi;  // length(0) = rest length: no jump at the start
  const JointId index = world.createJoint(j);
  EXPECT_TRUE(near(world.joints()[static_cast<size_t>(index)].rest_length, 0.3, 1e-12));
  double worst = 0.0;
  for (int i = 0; i < 100; ++i) {
    world.step();
    worst = std::max(worst, world.jointError(index));
  }
  // Tracks 0.3 + 0.05 cos(2 pi t) to within a millimetre.
  EXPECT_LT(worst, 1e-3);
}

TEST(World, ADistanceJointsRestLengthCanBeSet) {
  WorldSettings s;
  s.gravity = Vec3::Zero();
  World world(s);
  const BodyId a = world.createBody(boxDesc("a", Vec3::Constant(0.05), {}));
  const BodyId b =
      world.createBody(boxDesc("b", Vec3::Constant(0.05), {Vec3(0.3, 0, 0), Quat::Identity()}));
  JointDesc j;
  j.name = "tie";
  j.type = JointType::Distance;
  j.body_a = a;
  j.body_b = b;
  const JointId tie = world.createJoint(j);
  j.name = "ball";  // between two other bodies, far away
  j.type = JointType::Ball;
  j.body_a =
      world.createBody(boxDesc("c", Vec3::Constant(0.05), {Vec3(0, 1, 0), Quat::Identity()}));
  j.body_b =
      world.createBody(boxDesc("d", Vec3::Constant(0.05), {Vec3(0, 1, 0), Quat::Identity()}));
  const JointId ball = world.createJoint(j);
  // The joint pulls the bodies to the new length.
  world.setJointRestLength(tie, 0.25);
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_NEAR((world.body(b).pose.position - world.body(a).pose.position).norm(), 0.25, 1e-3);
  // Other joint types, unknown ids, bad lengths.
  EXPECT_EQ(test::errorOf([&] { world.setJointRestLength(ball, 0.1); }),
            "joint 'ball': only distance joints have a rest length");
  EXPECT_EQ(test::errorOf([&] { world.setJointRestLength(7, 0.1); }), "joint id 7 does not exist");
  EXPECT_EQ(test::errorOf([&] { world.setJointRestLength(tie, -1.0); }),
            "joint 'tie': rest length must be a finite number >= 0 (m)");
}

TEST(World, HingeKeepsItsAxisAndFixedKeepsItsPose) {
  WorldSettings s;
  s.dt = 0.001;
  World world(s);
  BodyDesc base = boxDesc("base", Vec3::Constant(0.05), {Vec3(0, 0, 1), Quat::Identity()});
  base.type = BodyType::Static;
  const BodyId b0 = world.createBody(base);
  const BodyId door =
      world.createBody(boxDesc("door", Vec3(0.2, 0.01, 0.1), {Vec3(0.25, 0, 1), Quat::Identity()}));
  JointDesc hinge;
  hinge.type = JointType::Hinge;
  hinge.body_a = b0;
  hinge.body_b = door;
  hinge.anchor_a = Vec3(0.05, 0, 0);
  hinge.anchor_b = Vec3(-0.2, 0, 0);
  hinge.axis_a = hinge.axis_b = Vec3::UnitY();  // swings down about y
  world.createJoint(hinge);
  const BodyId glued = world.createBody(
      boxDesc("glued", Vec3::Constant(0.02), {Vec3(0.47, 0, 1), Quat::Identity()}));
  JointDesc fixed;
  fixed.type = JointType::Fixed;
  fixed.body_a = door;
  fixed.body_b = glued;
  fixed.anchor_a = Vec3(0.2, 0, 0);
  fixed.anchor_b = Vec3(-0.02, 0, 0);
  world.createJoint(fixed);
  for (int i = 0; i < 1000; ++i) world.step();
  // The door swung in the x-z plane only; the glued block turned with it.
  const Body& d = world.body(door);
  EXPECT_LT(std::abs(d.pose.position.y()), 1e-3);
  EXPECT_LT((d.pose.rotation * Vec3::UnitY() - Vec3::UnitY()).norm(), 1e-3);
  EXPECT_LT(d.pose.position.z(), 0.95);
  EXPECT_LT(world.body(glued).pose.rotation.angularDistance(d.pose.rotation), 1e-2);
  EXPECT_LT(world.jointError(0), 1e-3);
  EXPECT_LT(world.jointError(1), 1e-3);
}

TEST(World, BadInputIsRejectedWithItsName) {
  World world;
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  JointDesc j;
  j.name = "hinge1";
  j.body_a = cube;
  j.body_b = 7;
  try {
    world.createJoint(j);
    FAIL() << "unknown body accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hinge1"), std::string::npos);
  }
  j.body_b = cube;
  EXPECT_THROW(world.createJoint(j), Error);  // a body joined to itself
  EXPECT_THROW(world.addSpring(SpringDesc{"s", 9, {}, {}, {}, 1.0, 0.0}), Error);
  EXPECT_THROW(world.addSpring(SpringDesc{"s", cube, {}, {}, {}, -1.0, 0.0}), Error);
  LoadDesc load;
  load.body = 42;
  EXPECT_THROW(world.addLoad(load), Error);
  EXPECT_THROW(world.body(99), Error);
  EXPECT_THROW(world.setFrictionProvider(nullptr), Error);
  world.settings().dt = 0.0;
  EXPECT_THROW(world.step(), Error);
  world.settings().dt = 0.01;
  world.settings().iterations = 0;
  EXPECT_THROW(world.step(), Error);
}

// Finished loads leave the list; the ones still to act stay, and the motion is unchanged.
TEST(World, FinishedLoadsAreDroppedWithoutChangingTheMotion) {
  const auto build = [](World& world) {
    world.settings().gravity = Vec3::Zero();
    const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
    LoadDesc push{"push", cube, LoadDesc::Kind::Force, Vec3(1, 0, 0), Vec3::Zero(), 0.0, 0.05};
    LoadDesc kick{"kick", cube, LoadDesc::Kind::Impulse, Vec3(0, 1, 0), Vec3::Zero(), 0.02};
    LoadDesc later{"later", cube, LoadDesc::Kind::Impulse, Vec3(0, 0, 1), Vec3::Zero(), 0.5};
    LoadDesc spin{"spin", cube, LoadDesc::Kind::Torque, Vec3(0, 0, 1), Vec3::Zero(), 0.0, 1.0};
    for (const LoadDesc& l : {push, kick, later, spin}) world.addLoad(l);
  };
  World pruned, kept;
  build(pruned);
  build(kept);
  for (int i = 0; i < 10; ++i) {  // t = 0.1 s: push has ended, kick has fired
    pruned.step();
    kept.step();
  }
  EXPECT_EQ(pruned.removeFinishedLoads(), 2u);
  ASSERT_EQ(pruned.loads().size(), 2u);
  EXPECT_EQ(pruned.loads()[0].name, "later");
  EXPECT_EQ(pruned.loads()[1].name, "spin");
  for (int i = 0; i < 60; ++i) {
    pruned.step();
    kept.step();
  }
  EXPECT_EQ(pruned.stateHash(), kept.stateHash());
  EXPECT_EQ(pruned.removeFinishedLoads(), 1u);  // "later" fired at 0.5 s
}

TEST(World, LookupsAndClock) {
  World world;
  world.createBody(groundPlaneDesc());
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  EXPECT_EQ(world.findBody("cube"), cube);
  EXPECT_EQ(world.findBody("nothing"), kNoBody);
  EXPECT_EQ(world.body(cube).name, "cube");
  // Every create function returns its own typed id, indexing its list.
  JointDesc j;
  j.name = "j";
  j.body_a = 0;
  j.body_b = cube;
  SpringDesc sd;
  sd.name = "s";
  sd.body = cube;
  LoadDesc ld;
  ld.name = "l";
  ld.body = cube;
  const JointId joint = world.createJoint(j);
  const SpringId spring = world.addSpring(sd);
  const LoadId load = world.addLoad(ld);
  EXPECT_EQ(world.joints()[joint].name, "j");
  EXPECT_EQ(world.springs()[spring].name, "s");
  EXPECT_EQ(world.loads()[load].name, "l");
  world.step();
  world.step();
  EXPECT_EQ(world.stepCount(), 2);
  EXPECT_TRUE(near(world.time(), 0.02, 1e-15));
}

// prepare() builds the collision objects once, ahead of the step that would have, and changes
// no result; a new body makes the next call build again.
TEST(World, PrepareBuildsOnceAndChangesNoBits) {
  auto make = [] {
    auto world = std::make_unique<World>();
    world->createBody(groundPlaneDesc());
    world->createBody(boxDesc("cube", Vec3::Constant(0.1), {Vec3(0, 0, 0.12), Quat::Identity()}));
    return world;
  };
  const auto plain = make(), prepared = make();
  EXPECT_GT(prepared->prepare(), 0.0);
  EXPECT_EQ(prepared->prepare(), 0.0);
  for (int i = 0; i < 20; ++i) {
    plain->step();
    prepared->step();
  }
  EXPECT_EQ(prepared->stateHash(), plain->stateHash());
  EXPECT_EQ(prepared->prepare(), 0.0);
  prepared->createBody(boxDesc("second", Vec3::Constant(0.1), {Vec3(1, 0, 0.1), Quat::Identity()}));
  EXPECT_GT(prepared->prepare(), 0.0);
}

TEST(World, StateHashSeesEveryBit) {
  World world;
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  const uint64_t h = world.stateHash();
  world.body(cube).angular_velocity.z() = std::nextafter(0.0, 1.0);
  EXPECT_NE(world.stateHash(), h);
}

TEST(World, ProfileCountsContactsAndStages) {
  World world;
  world.createBody(groundPlaneDesc());
  world.createBody(boxDesc("cube", Vec3::Constant(0.1), {Vec3(0, 0, 0.099), Quat::Identity()}));
  world.step();
  const StepProfile& p = world.profile();
  EXPECT_EQ(p.contacts, static_cast<int>(world.contacts().size()));
  EXPECT_GE(p.contacts, 4);
  EXPECT_EQ(p.fallbacks, 0);
  // Every stage was timed, and the stages add up to at most the whole step.
  double stages = 0.0;
  for (int i = 0; i < kStageCount; ++i) {
    EXPECT_GE(p.ms(static_cast<Stage>(i)), 0.0) << stageName(static_cast<Stage>(i));
    stages += p.ms(static_cast<Stage>(i));
  }
  EXPECT_GT(p.ms(Stage::Solve), 0.0);
  EXPECT_LE(stages, p.total_ms * (1 + 1e-9));
  // The solve stage's parts were timed inside it.
  double parts = 0.0;
  for (int k = 0; k < kSolveStageCount; ++k) {
    EXPECT_GE(p.solve_ms[static_cast<size_t>(k)], 0.0)
        << solveStageName(static_cast<SolveStage>(k));
    parts += p.solve_ms[static_cast<size_t>(k)];
  }
  EXPECT_GT(p.solve_ms[static_cast<size_t>(SolveStage::Iterate)], 0.0);
  EXPECT_LE(parts, p.ms(Stage::Solve) * (1 + 1e-9));
}

// One ProfileSums for every front end: sums, means and the --stats names in step order.
TEST(World, ProfileSumsAverageStepsInStageOrder) {
  ProfileSums sums;
  StepProfile a, b;
  a.ms(Stage::Collide) = 1.0;
  b.ms(Stage::Collide) = 3.0;
  a.contacts = 10;
  b.contacts = 20;
  a.reused = 4;
  a.total_ms = b.total_ms = 5.0;
  sums.add(a);
  sums.add(b);
  EXPECT_EQ(sums.steps, 2);
  EXPECT_DOUBLE_EQ(sums.meanMs(Stage::Collide), 2.0);
  EXPECT_EQ(sums.max_contacts, 20);
  const auto means = sums.means();
  std::vector<std::string> names;
  for (const auto& [name, value] : means) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{
                       "contacts", "fallbacks", "reused", "drivers_ms", "collide_ms", "frames_ms",
                       "friction_ms", "patch_ms", "averaging_ms", "solve_ms",
                       "solve_prepare_joints_ms", "solve_prepare_rows_ms",
                       "solve_await_friction_ms", "solve_set_limits_ms", "solve_warm_start_ms",
                       "solve_iterate_ms", "solve_store_impulses_ms", "integrate_ms", "total_ms"}));
  EXPECT_DOUBLE_EQ(means[0].second, 15.0);
  EXPECT_DOUBLE_EQ(means[2].second, 2.0);  // reused
  EXPECT_DOUBLE_EQ(means[4].second, 2.0);  // collide_ms
  EXPECT_DOUBLE_EQ(means.back().second, 5.0);
}

}  // namespace
}  // namespace asperity
