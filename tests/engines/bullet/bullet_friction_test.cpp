// BulletFriction: flat surfaces leave Bullet's own run as it was, the contact sides and normal
// follow SPEC 1, two worlds in one process stay independent, surfaces files attach objects by
// name, and bad input is an error naming it.
#include "asperity/engines/bullet.hpp"

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <vector>

#include "asperity/engines/bullet_scene.hpp"
#include "engines/bullet/bullet_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Bullet's speed below which it stops following the sliding (sqrt(SIMD_EPSILON) m/s).
const double kBulletSlidingSpeed = std::sqrt(static_cast<double>(SIMD_EPSILON));

// Bullet with Asperity's friction or without, and with frames along the sliding.
BulletSceneOptions withAsperity(bool asperity) {
  BulletSceneOptions o;
  o.asperity_friction = asperity;
  return o;
}
BulletSceneOptions autoFrames() {
  BulletSceneOptions o;
  o.frame_mode = FrameMode::Auto;
  return o;
}

// Asperity's friction on flat surfaces, frames along the sliding as Bullet's own (frame mode
// Auto with Bullet's threshold), against plain Bullet with two friction directions.
struct FlatPair {
  BulletScene asperity, plain;
  FlatPair(SceneDesc scene, const std::string& sampler)
      : asperity(withSampler(scene, sampler), autoFrames()), plain(scene, withAsperity(false)) {}
  static SceneDesc withSampler(SceneDesc scene, const std::string& sampler) {
    scene.friction_provider = sampler;
    scene.settings.frame.sliding_speed = kBulletSlidingSpeed;
    return scene;
  }
};

TEST(BulletFriction, MuZeroEverywhereGivesBulletsOwnTrajectory) {
  // A ball thrown with spin (one contact: no manifold reshuffles): the same path to float
  // precision when every contact gets mu0 (the constant provider).
  for (const Vec3& v : {Vec3(1.0, 0.4, 0.0), Vec3(-0.3, 0.9, 0.0)}) {
    BodyDesc ball = test::restingBox("ball", Vec3::Constant(0.1));
    ball.shapes[0].type = ShapeType::Sphere;
    ball.shapes[0].radius = 0.1;
    ball.linear_velocity = v;
    ball.angular_velocity = Vec3(2.0, -1.0, 3.0);
    FlatPair pair(test::groundScene(Surface{}, ball), "constant");
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
      pair.asperity.step();
      pair.plain.step();
      worst =
          std::max(worst, (pair.asperity.position("ball") - pair.plain.position("ball")).norm());
    }
    // Single-precision positions along a path of about 2 m.
    EXPECT_LT(worst, 1e-4) << v.transpose();
  }
}

TEST(BulletFriction, FlatTexturesKeepBulletsSlideDistances) {
  // Boxes on flat surfaces with the CPU sampler: flat faces add nothing to mu0, so each box
  // slides as far as in plain Bullet. Within 3 %: a sliding box rocks, its face tilts against
  // the contact plane, and a tilted face adds its slope (SPEC 2), about 1 to 2 % here; the
  // rest is how a box's four contact points change from step to step.
  for (const Vec3& v : {Vec3(1.0, 0.0, 0.0), Vec3(0.6, -0.8, 0.0), Vec3(-0.5, 0.5, 0.0)}) {
    BodyDesc box = test::restingBox("box", Vec3::Constant(0.1));
    box.linear_velocity = v;
    const SceneDesc scene = FlatPair::withSampler(test::groundScene(Surface{}, box), "cpu");
    const double flat = slideDistances(scene, SceneEngine::Bullet, 2.0, autoFrames())[0].second;
    const double plain = slideDistances(scene, SceneEngine::PlainBullet, 2.0)[0].second;
    EXPECT_TRUE(test::near(flat, plain, 0.03)) << v.transpose() << ": " << flat << " " << plain;
  }
}

TEST(BulletFriction, TheDynamicObjectIsAAndTheNormalPointsFromBTowardA) {
  // Bullet's manifold holds the static ground as body 0 here; the adapter hands it over as B.
  BulletScene scene(
      test::groundScene(test::sawtoothSurface(), test::restingBox("box", Vec3::Constant(0.1))));
  for (int i = 0; i < 5; ++i) scene.step();
  const auto contacts = scene.friction()->lastContacts();
  ASSERT_EQ(contacts.size(), 4u);
  const ContactFriction& friction = scene.friction()->contactFriction();
  for (const EngineContact& c : contacts) {
    EXPECT_EQ(c.object_a, friction.findObject("box"));
    EXPECT_GT(c.normal.z(), 0.99);  // from the ground (B) up toward the box (A)
    EXPECT_GE(c.depth, 0.0);
    EXPECT_NEAR(c.point.z(), 0.0, 1e-3);
  }
}

// The paper's sawtooth with a box launched along x, in a world of its own.
SceneDesc sawtoothLaunch(double vx) {
  BodyDesc box = test::restingBox("box", Vec3::Constant(0.1));
  box.linear_velocity = Vec3(vx, 0.0, 0.0);
  return test::groundScene(test::sawtoothSurface(), box);
}

TEST(BulletFriction, TwoWorldsInOneProcessStayIndependent) {
  // Alone, each world's box ends somewhere; stepped in turn with another world, at the same bits.
  auto alone = [](const SceneDesc& scene, bool asperity) {
    BulletScene s(scene, withAsperity(asperity));
    for (int i = 0; i < 100; ++i) s.step();
    return s.position("box");
  };
  const SceneDesc up = sawtoothLaunch(1.0), down = sawtoothLaunch(-1.0);
  BulletScene a(up), b(down), c(up, withAsperity(false));
  for (int i = 0; i < 100; ++i) {
    a.step();
    b.step();
    c.step();
  }
  EXPECT_EQ(a.position("box"), alone(up, true));
  EXPECT_EQ(b.position("box"), alone(down, true));
  EXPECT_EQ(c.position("box"), alone(up, false));
  // And the two senses of the sawtooth differ, as they should (SPEC 7).
  EXPECT_GT(std::abs(a.position("box").x()), 2.0 * std::abs(b.position("box").x()));
}

// A Bullet world built by hand as docs/engines.md shows: a ground box and a 0.2 m box.
struct HandBuilt {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btBoxShape ground_shape{btVector3(1.5f, 0.4f, 0.05f)};
  btBoxShape box_shape{btVector3(0.1f, 0.1f, 0.1f)};
  std::unique_ptr<btRigidBody> ground, box;

  explicit HandBuilt(float vx) {
    world.setGravity(btVector3(0, 0, -9.81f));
    ground = std::make_unique<btRigidBody>(0.0f, nullptr, &ground_shape);
    ground->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, -0.05f)));
    btVector3 inertia;
    box_shape.calculateLocalInertia(8.0f, inertia);
    box = std::make_unique<btRigidBody>(8.0f, nullptr, &box_shape, inertia);
    box->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(-1, 0, 0.1f)));
    box->setLinearVelocity(btVector3(vx, 0, 0));
    box->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(ground.get());
    world.addRigidBody(box.get());
  }
  ~HandBuilt() {
    world.removeRigidBody(box.get());
    world.removeRigidBody(ground.get());
  }
  std::map<std::string, btCollisionObject*> objects() {
    return {{"ground", ground.get()}, {"box", box.get()}};
  }
};

// Writes a surfaces file for the hand-built world into a fresh folder; returns its path.
std::string surfacesFile(const std::string& text) {
  const std::string path = test::tempDir("bullet_friction") + "/surfaces.json";
  std::ofstream(path) << text;
  return path;
}

const char* kSawtoothFile = R"({"surfaces": {
  "ground": {"normal_map": {"generator": "sawtooth", "params": {"period": 16, "axis": 0},
             "size": 128}, "gain": 4, "texture_size": 0.08},
  "box": {"gain": 1}}})";

TEST(BulletFriction, ASurfacesFileAttachesObjectsByName) {
  // Up the ramps in a hand-built world: as far as Asperity slides the same box (within 10 %).
  HandBuilt bullet(1.0f);
  BulletFriction friction(bullet.world);
  friction.attach(loadEngineSurfaces(surfacesFile(kSawtoothFile)), bullet.objects());
  for (int i = 0; i < 200; ++i) bullet.world.stepSimulation(0.01f, 0);
  const double slid = bullet.box->getWorldTransform().getOrigin().x() + 1.0;
  const SceneDesc scene = loadScene(test::sourcePath("examples/engines/sawtooth_launch.json"));
  double asperity = 0.0;
  for (const auto& [name, d] : slideDistances(scene, SceneEngine::Asperity, 2.0))
    if (name == "box_ramps") asperity = d;
  EXPECT_TRUE(test::near(slid, asperity, 0.10)) << slid << " " << asperity;
  EXPECT_EQ(friction.lastContacts().size(), 4u);
}

TEST(BulletFriction, BadInputIsAnErrorNamingIt) {
  HandBuilt bullet(0.0f);
  BulletFriction friction(bullet.world);
  // An object name the world lacks names the name and the file; nothing is attached then.
  const std::string path = surfacesFile(R"({"surfaces": {"box": {}, "gripper": {}}})");
  std::string error =
      test::errorOf([&] { friction.attach(loadEngineSurfaces(path), bullet.objects()); });
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("unknown object \"gripper\""), std::string::npos) << error;
  EXPECT_EQ(friction.contactFriction().objectCount(), 0u);
  // A missing texture names its path.
  const std::string missing = surfacesFile(R"({"surfaces": {"box": {"normal_map": "oak.png"}}})");
  error = test::errorOf([&] { friction.attach(loadEngineSurfaces(missing), bullet.objects()); });
  EXPECT_NE(error.find("oak.png"), std::string::npos) << error;
  // A shape with no Asperity counterpart, a null object, an object attached twice.
  btConeShapeZ cone(0.1f, 0.2f);
  btCollisionObject lone;
  lone.setCollisionShape(&cone);
  EXPECT_NE(test::errorOf([&] { friction.attach(&lone, "cone", Surface{}); }).find("'Cone"),
            std::string::npos);
  EXPECT_NE(test::errorOf([&] { friction.attach(nullptr, "none", Surface{}); }).find("null"),
            std::string::npos);
  friction.attach(bullet.box.get(), "box", Surface{});
  EXPECT_NE(test::errorOf([&] {
              friction.attach(bullet.box.get(), "box2", Surface{});
            }).find("attached already"),
            std::string::npos);
}

TEST(BulletFriction, DetachedObjectsGetBulletsFrictionBack) {
  HandBuilt bullet(1.0f);
  BulletFriction friction(bullet.world);
  friction.attach(loadEngineSurfaces(surfacesFile(kSawtoothFile)), bullet.objects());
  bullet.world.stepSimulation(0.01f, 0);
  bullet.world.stepSimulation(0.01f, 0);
  ASSERT_FALSE(friction.lastContacts().empty());
  friction.detach(bullet.box.get());
  bullet.world.stepSimulation(0.01f, 0);
  EXPECT_TRUE(friction.lastContacts().empty());
  // Bullet picks its own friction directions again.
  const btPersistentManifold& m = *bullet.dispatcher.getManifoldByIndexInternal(0);
  for (int j = 0; j < m.getNumContacts(); ++j)
    EXPECT_EQ(
        m.getContactPoint(j).m_contactPointFlags & BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED, 0);
}

}  // namespace
}  // namespace asperity
