// The contact-frame stage (SPEC 5): world, body (axis and callback), texture and auto modes.
#include "asperity/frames/contact_frames.hpp"

#include <gtest/gtest.h>

#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Every contact's frame is right-handed and orthonormal with b = n x t.
void expectFrames(const World& world) {
  for (const Contact& c : world.contacts()) {
    EXPECT_NEAR(c.t.norm(), 1.0, 1e-12);
    EXPECT_NEAR(c.t.dot(c.normal), 0.0, 1e-12);
    EXPECT_LT((c.b - c.normal.cross(c.t)).norm(), 1e-12);
  }
}

TEST(ContactFrames, ProjectedTangentFallsBackWhenTheAxisIsNormal) {
  const Vec3 n = Vec3(1, 0, 1).normalized();
  const Vec3 t = projectedTangent(n, Vec3::UnitX(), Vec3::UnitY());
  EXPECT_LT((t - Vec3(1, 0, -1).normalized()).norm(), 1e-12);
  // World x along the normal: the fallback y is used.
  EXPECT_LT((projectedTangent(Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitY()) - Vec3::UnitY()).norm(),
            1e-12);
  // Both vanish: still a unit vector in the plane.
  const Vec3 any = projectedTangent(Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ());
  EXPECT_NEAR(any.norm(), 1.0, 1e-12);
  EXPECT_NEAR(any.z(), 0.0, 1e-12);
}

// A cube resting (slightly sunk) on the ground; frame mode and axis as given; one step.
struct Scene {
  std::unique_ptr<World> world;
  BodyId cube = kNoBody;
};
Scene restingCube(FrameMode mode, const Vec3& world_axis = Vec3::UnitX(),
                  const Vec3& cube_axis = Vec3::Zero(), double yaw = 0.0,
                  double plane_texture_rotation = 0.0) {
  WorldSettings s;
  s.frame.mode = mode;
  s.frame.world_axis = world_axis;
  Scene scene{std::make_unique<World>(s), kNoBody};
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.texture_rotation = plane_texture_rotation;
  scene.world->createBody(ground);
  BodyDesc d = boxDesc("cube", Vec3::Constant(0.1),
                       {Vec3(0, 0, 0.099), Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ()))});
  d.frame_axis = cube_axis;
  scene.cube = scene.world->createBody(d);
  scene.world->step();
  EXPECT_FALSE(scene.world->contacts().empty());
  return scene;
}

TEST(ContactFrames, WorldModeProjectsTheSceneAxis) {
  const Scene s = restingCube(FrameMode::World, Vec3(1, 1, 5));
  expectFrames(*s.world);
  for (const Contact& c : s.world->contacts()) {
    EXPECT_LT((c.t - Vec3(1, 1, 0).normalized()).norm(), 1e-9);
  }
}

TEST(ContactFrames, BodyModeUsesTheBodyAxisThenTheCallback) {
  // The cube's local x turned 90 degrees about z: t = world y.
  const Scene s = restingCube(FrameMode::Body, Vec3::UnitX(), Vec3::UnitX(), 0.5 * kPi);
  expectFrames(*s.world);
  for (const Contact& c : s.world->contacts()) EXPECT_LT((c.t - Vec3::UnitY()).norm(), 1e-9);
  // No axis on either body: the callback decides.
  Scene cb = restingCube(FrameMode::Body);
  cb.world->setFrameCallback([](const World&, const Contact&) { return Vec3(-1, 0, 0); });
  cb.world->step();
  ASSERT_GE(cb.world->contacts().size(), 4u);  // a resting cube: the loop below checks them
  for (const Contact& c : cb.world->contacts()) EXPECT_LT((c.t + Vec3::UnitX()).norm(), 1e-9);
}

TEST(ContactFrames, TextureModeFollowsTheTextureOfB) {
  // The plane is B (the normal points from it into the cube); its texture turned 30 degrees.
  const double r = kPi / 6;
  const Scene s = restingCube(FrameMode::Texture, Vec3::UnitX(), Vec3::Zero(), 0.0, r);
  expectFrames(*s.world);
  for (const Contact& c : s.world->contacts()) {
    ASSERT_EQ(c.body_b, 0u);
    EXPECT_LT((c.t - Vec3(std::cos(r), std::sin(r), 0)).norm(), 1e-9);
  }
}

TEST(ContactFrames, AutoModeAlignsTWithTheSlidingVelocity) {
  // A cube sliding along (1, 2, 0): t along its sliding direction at every contact.
  WorldSettings s;
  s.frame.mode = FrameMode::Auto;
  World world(s);
  world.createBody(groundPlaneDesc());
  BodyDesc d = boxDesc("cube", Vec3::Constant(0.1), {Vec3(0, 0, 0.099), Quat::Identity()});
  d.linear_velocity = Vec3(1, 2, 0);
  world.createBody(d);
  world.step();
  ASSERT_FALSE(world.contacts().empty());
  for (const Contact& c : world.contacts()) {
    EXPECT_LT((c.t - Vec3(1, 2, 0).normalized()).norm(), 1e-3);
  }
  // At rest the world frame is kept.
  const Scene rest = restingCube(FrameMode::Auto);
  for (const Contact& c : rest.world->contacts()) EXPECT_LT((c.t - Vec3::UnitX()).norm(), 1e-9);
}

}  // namespace
}  // namespace asperity
