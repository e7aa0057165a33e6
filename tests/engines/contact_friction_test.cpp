// ContactFriction: an engine's contacts get the frames and coefficients a World's step gives
// its own, deterministically on any thread count, the sense an engine with a symmetric cone
// needs, and clear errors for bad input.
#include "asperity/engines/contact_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "asperity/contact_area/mechanical.hpp"
#include "asperity/error.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// A ground plane with Gaussian slopes (sx 0.3 along u, sy 1 along v) under a turned cube.
std::unique_ptr<World> cubeOnRoughGround() {
  WorldSettings s;
  s.friction.mu0 = 0.2;
  auto world = std::make_unique<World>(s);
  BodyDesc ground = groundPlaneDesc();
  Surface& surface = ground.shapes[0].surface;
  surface.source.generator = {"gaussian", {{"sx", "0.3"}, {"sy", "1"}}, 256, 3};
  surface.gain = 2.0;
  resolveSurface(surface, world->diagnostics());
  world->createBody(ground);
  const Quat turn(Eigen::AngleAxisd(0.4, Vec3::UnitZ()));
  world->createBody(boxDesc("cube", Vec3(0.1, 0.1, 0.1), {Vec3(0.0, 0.0, 0.0995), turn}));
  world->setFrictionProvider(std::make_unique<CpuPatchSampler>());
  return world;
}

// The world's bodies as an engine's objects, and their states.
ObjectDesc objectOf(const Body& body) {
  ObjectDesc desc;
  desc.name = body.name.empty() ? "ground" : body.name;
  desc.shapes = body.shapes;
  return desc;
}

EngineContact engineContact(const Contact& c) {
  EngineContact e;
  e.object_a = c.body_a;
  e.object_b = c.body_b;
  e.shape_a = c.shape_a;
  e.shape_b = c.shape_b;
  e.feature_a = c.feature_a;
  e.feature_b = c.feature_b;
  e.point = c.point;
  e.normal = c.normal;
  e.depth = c.phi;
  e.key = c.key;
  return e;
}

TEST(ContactFriction, GivesAnEnginesContactsWhatAWorldStepGivesItsOwn) {
  auto world = cubeOnRoughGround();
  std::vector<ObjectState> before;
  for (const Body& b : world->bodies())
    before.push_back({b.pose, b.linear_velocity, b.angular_velocity});
  world->step();
  ASSERT_GE(world->contacts().size(), 4u);

  ContactFrictionSettings settings;
  settings.provider = "cpu";
  settings.friction = world->settings().friction;
  ContactFriction friction(settings);
  for (size_t i = 0; i < world->bodies().size(); ++i) {
    const ObjectId id = friction.addObject(objectOf(world->bodies()[i]));
    friction.setState(id, before[i]);
  }
  std::vector<EngineContact> contacts;
  for (const Contact& c : world->contacts()) contacts.push_back(engineContact(c));
  const auto results = friction.compute(contacts);
  ASSERT_EQ(results.size(), contacts.size());
  for (size_t i = 0; i < results.size(); ++i) {
    const Contact& c = world->contacts()[i];
    EXPECT_LT((results[i].t - c.t).norm(), 1e-12) << i;
    EXPECT_LT((results[i].b - c.b).norm(), 1e-12) << i;
    EXPECT_EQ(results[i].mu.count, c.mu.count);
    for (int k = 0; k < c.mu.count; ++k)
      EXPECT_NEAR(results[i].mu.mu[static_cast<size_t>(k)], c.mu.mu[static_cast<size_t>(k)], 1e-6)
          << i << " " << k;
    const BoxLimit box = BoxLimit::fromDirectional(c.mu);
    EXPECT_EQ(results[i].bounds.mu_pos_t, box.mu_pos_t);
    EXPECT_EQ(results[i].bounds.mu_neg_b, box.mu_neg_b);
    EXPECT_GT(results[i].bounds.mu_pos_b, 0.2);  // the rough v direction adds to mu0
  }
}

// Under the contact-area model (a stone ground and a steel cube, each with mechanical values)
// an engine's contacts get a world's coefficients, and the engine's normal force is the load.
TEST(ContactFriction, ServesTheContactAreaModelWithTheEnginesNormalForce) {
  FrictionModelSettings area;
  area.model = FrictionModel::ContactArea;
  auto world = std::make_unique<World>(WorldSettings{});
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source.generator = {"stone", {}, 256, 3};
  ground.shapes[0].surface.mechanical = findMechanical("concrete");
  resolveSurface(ground.shapes[0].surface, world->diagnostics());
  world->createBody(ground);
  BodyDesc cube = boxDesc("cube", Vec3(0.1, 0.1, 0.1), {Vec3(0.0, 0.0, 0.0995)});
  cube.shapes[0].surface.mechanical = findMechanical("steel");
  world->createBody(cube);
  auto sampler = std::make_unique<CpuPatchSampler>();
  sampler->setFrictionModels(area);
  world->setFrictionProvider(std::move(sampler));
  std::vector<ObjectState> before;
  for (const Body& b : world->bodies())
    before.push_back({b.pose, b.linear_velocity, b.angular_velocity});
  world->step();  // new contacts: no load yet, so both take the light load
  ASSERT_GE(world->contacts().size(), 4u);

  ContactFrictionSettings settings;
  settings.provider = "cpu";
  settings.models = area;
  ContactFriction friction(settings);
  for (size_t i = 0; i < world->bodies().size(); ++i)
    friction.setState(friction.addObject(objectOf(world->bodies()[i])), before[i]);
  std::vector<EngineContact> contacts;
  for (const Contact& c : world->contacts()) contacts.push_back(engineContact(c));
  const auto first = friction.compute(contacts);
  const std::vector<ContactFrictionResult> light(first.begin(), first.end());
  for (size_t i = 0; i < light.size(); ++i)
    for (int k = 0; k < light[i].mu.count; ++k)
      EXPECT_NEAR(light[i].mu.mu[static_cast<size_t>(k)],
                  world->contacts()[i].mu.mu[static_cast<size_t>(k)], 1e-6);
  // The engine's force is the load: pressed hard enough to flatten the summits, far more of
  // the patch is in contact (covered_pixels counts the pixels in contact under this model).
  for (EngineContact& e : contacts) e.normal_force = 1e6;
  friction.forgetHistory();
  const auto loaded = friction.compute(contacts);
  for (size_t i = 0; i < loaded.size(); ++i)
    EXPECT_GT(loaded[i].covered_pixels, 10 * light[i].covered_pixels);
  contacts[0].normal_force = -1.0;
  EXPECT_THROW(friction.compute(contacts), Error);
}

// A ring of contacts of boxes on the rough ground, keyless, as many engines hand them over.
std::vector<EngineContact> ringOfContacts(int count) {
  std::vector<EngineContact> out;
  for (int i = 0; i < count; ++i) {
    EngineContact e;
    e.object_a = 1;
    e.object_b = 0;
    const double a = 2.0 * kPi * i / count;
    e.point = Vec3(0.05 * std::cos(a), 0.05 * std::sin(a), 0.0);
    e.depth = 1e-4;
    out.push_back(e);
  }
  return out;
}

TEST(ContactFriction, SameBitsOnOneAndFourThreads) {
  auto world = cubeOnRoughGround();
  std::vector<std::vector<float>> runs;
  for (const int threads : {1, 4}) {
    ContactFrictionSettings settings;
    settings.provider = "cpu";
    settings.threads = threads;
    settings.friction.directions = 8;
    ContactFriction friction(settings);
    for (const Body& b : world->bodies())
      friction.setState(friction.addObject(objectOf(b)), {b.pose});
    std::vector<float> mu;
    for (int step = 0; step < 3; ++step) {
      for (const auto& r : friction.compute(ringOfContacts(400))) {
        mu.insert(mu.end(), r.mu.mu.begin(), r.mu.mu.begin() + r.mu.count);
      }
    }
    runs.push_back(mu);
  }
  EXPECT_EQ(runs[0], runs[1]);
}

TEST(ContactFriction, SymmetricConesTakeTheSenseTheContactSlidesIn) {
  // A flat pair with mu0 0.2 and a sawtooth-like bound: the sense choice only.
  EXPECT_EQ(symmetricCoefficient(0.3, 0.7, 0.5, 0, 1e-3), 0.7);   // slides +: friction along -
  EXPECT_EQ(symmetricCoefficient(0.3, 0.7, -0.5, 0, 1e-3), 0.3);  // slides -: friction along +
  EXPECT_EQ(symmetricCoefficient(0.3, 0.7, 0.0, -1, 1e-3), 0.3);  // at rest: the last sense
  EXPECT_EQ(symmetricCoefficient(0.3, 0.7, 0.0, 0, 1e-3), 0.7);   // unknown: the larger

  // Through compute: the cube slides along +x, then rests; the sense is remembered by key.
  auto world = cubeOnRoughGround();
  ContactFriction friction;
  for (const Body& b : world->bodies())
    friction.setState(friction.addObject(objectOf(b)), {b.pose});
  std::vector<EngineContact> one = ringOfContacts(1);
  one[0].key = 7;
  friction.setState(1, {world->bodies()[1].pose, Vec3(0.5, 0.0, 0.0)});
  const ContactFrictionResult sliding = friction.compute(one)[0];
  EXPECT_NEAR(sliding.sliding.x(), 0.5, 1e-12);
  EXPECT_EQ(sliding.symmetric_t, sliding.bounds.mu_neg_t);
  friction.setState(1, {world->bodies()[1].pose});
  const ContactFrictionResult resting = friction.compute(one)[0];
  EXPECT_EQ(resting.symmetric_t, resting.bounds.mu_neg_t);
}

TEST(ContactFriction, BadInputIsAnErrorNamingIt) {
  ContactFriction friction;
  ObjectDesc ground;
  ground.name = "ground";
  ground.shapes = groundPlaneDesc().shapes;
  friction.addObject(ground);
  EXPECT_NE(
      test::errorOf([&] { friction.addObject(ground); }).find("'ground' is registered already"),
      std::string::npos);
  ObjectDesc unresolved = ground;
  unresolved.name = "rough";
  unresolved.shapes[0].surface.source.normal_map_file = "rough.png";
  EXPECT_NE(test::errorOf([&] { friction.addObject(unresolved); }).find("is not resolved"),
            std::string::npos);
  EngineContact c;
  c.object_a = 5;
  c.object_b = 0;
  EXPECT_NE(test::errorOf([&] {
              friction.compute({&c, 1});
            }).find("contact 0: object A (5)"),
            std::string::npos);
  c.object_a = 0;
  c.normal = Vec3(0, 0, 2);
  EXPECT_NE(test::errorOf([&] {
              friction.compute({&c, 1});
            }).find("unit vector"),
            std::string::npos);
  c.normal = Vec3::UnitZ();
  c.depth = -1.0;
  EXPECT_NE(test::errorOf([&] { friction.compute({&c, 1}); }).find("depth"), std::string::npos);
  ContactFrictionSettings bad;
  bad.provider = "magic";
  EXPECT_NE(test::errorOf([&] { ContactFriction f(bad); }).find("magic"), std::string::npos);
  bad = {};
  bad.friction.directions = 3;
  EXPECT_NE(test::errorOf([&] { ContactFriction f(bad); }).find("directions"), std::string::npos);
  EXPECT_NE(test::errorOf([&] { friction.setState(9, {}); }).find("object 9"), std::string::npos);
}

}  // namespace
}  // namespace asperity
