// BulletScene against Asperity's own World on the same scenes: boxes launched over the
// anisotropic Gaussian (along and across), the sawtooth (both senses and along the ridges) and
// the four materials slide as far in Bullet as in Asperity, within 10 %.
#include "asperity/engines/bullet_scene.hpp"

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/test_support.hpp"

namespace asperity {
namespace {

// Runs `file` in both engines for 2 s; every dynamic body's slide must agree within 10 %.
void expectSameSlides(const std::string& file) {
  const SceneDesc scene = loadScene(test::sourcePath(file));
  const auto asperity = slideDistances(scene, SceneEngine::Asperity, 2.0);
  const auto bullet = slideDistances(scene, SceneEngine::Bullet, 2.0);
  ASSERT_EQ(asperity.size(), bullet.size());
  for (size_t i = 0; i < asperity.size(); ++i) {
    const auto& [name, expected] = asperity[i];
    const double got = bullet[i].second;
    std::printf("%s %-16s asperity %.4f  bullet %.4f  (%+.1f %%)\n", file.c_str(), name.c_str(),
                expected, got, 100.0 * (got - expected) / expected);
    EXPECT_TRUE(test::near(got, expected, 0.10)) << file << " " << name;
  }
}

TEST(BulletScene, AnisotropicGaussianSlidesAsInAsperity) {
  expectSameSlides("examples/engines/gaussian_launch.json");
}

TEST(BulletScene, SawtoothSlidesAsInAsperityBothWaysAndAlong) {
  expectSameSlides("examples/engines/sawtooth_launch.json");
}

TEST(BulletScene, BoxesOnMaterialsSlideAsInAsperity) {
  expectSameSlides("scenes/boxes_on_materials.json");
}

TEST(BulletScene, BuildsBodiesAsAWorldDoes) {
  const SceneDesc scene = loadScene(test::sourcePath("examples/engines/sawtooth_launch.json"));
  BulletScene bullet(scene);
  auto world = instantiate(scene);
  // Mass, pose and velocity of a launched box; the static planes have no mass.
  const Body& box = world->body(world->findBody("box_ramps"));
  btRigidBody& b = bullet.body("box_ramps");
  EXPECT_NEAR(1.0 / b.getInvMass(), 1.0 / box.inverse_mass, 1e-3);
  EXPECT_LT((bullet.position("box_ramps") - box.pose.position).norm(), 1e-6);
  EXPECT_NEAR(b.getLinearVelocity().x(), 1.0, 1e-6);
  EXPECT_EQ(bullet.body("plane_ramps").getInvMass(), 0.0f);
  EXPECT_EQ(bullet.objects().size(), scene.bodies.size());
  EXPECT_EQ(bullet.friction()->contactFriction().objectCount(), scene.bodies.size());
  EXPECT_NE(test::errorOf([&] { bullet.body("nobody"); }).find("'nobody'"), std::string::npos);
}

TEST(BulletScene, ScenesWithMoreThanBodiesAreErrorsNamingTheFile) {
  // The paper's own sawtooth scene pulls its boxes with springs.
  const std::string file = test::sourcePath("scenes/sawtooth_plane.json");
  const std::string error = test::errorOf([&] { BulletScene bullet(loadScene(file)); });
  EXPECT_NE(error.find(file), std::string::npos) << error;
  EXPECT_NE(error.find("springs are not supported"), std::string::npos) << error;
}

}  // namespace
}  // namespace asperity
