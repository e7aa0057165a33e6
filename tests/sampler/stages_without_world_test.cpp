// The seam that other engines build on: contact frames, friction providers and limit bounds
// called on contacts made by hand, with no World. A cube rests on a plane whose texture is one
// tilted facet, so every provider's coefficient has an exact oracle (SPEC 2) in any frame.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "asperity/frames/contact_frames.hpp"
#include "asperity/friction/limit_surfaces/box_limit.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/sampler/constant_provider.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/world/builders.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

constexpr double kSlope = 0.5;  // the facet's slope along texture u
constexpr double kGain = 2.0;   // k_B of the plane
constexpr double kMu0 = 0.2;

// Every texel the facet normalize(-kSlope, 0, 1): it rises toward +u.
std::shared_ptr<const NormalMap> facetMap() {
  auto map = std::make_shared<NormalMap>(64, 64);
  const Vec3f m = Vec3f(static_cast<float>(-kSlope), 0.0f, 1.0f).normalized();
  for (int j = 0; j < 64; ++j) {
    for (int i = 0; i < 64; ++i) map->at(i, j) = m;
  }
  return map;
}

// Body 0: the textured ground plane (B); body 1: a flat 0.2 m cube (A) resting on it.
std::vector<Body> bodies() {
  BodyDesc plane = groundPlaneDesc();
  plane.shapes[0].surface.normal_map = facetMap();
  plane.shapes[0].surface.gain = kGain;
  const BodyDesc cube =
      boxDesc("cube", Vec3(0.1, 0.1, 0.1), Transform{Vec3(0, 0, 0.1), Quat::Identity()});
  return {makeBody(plane), makeBody(cube)};
}

// The contact under the cube's centre, as an engine would hand it over.
Contact contactUnderCube() {
  Contact c;
  c.body_a = 1;
  c.body_b = 0;
  c.shape_a = c.shape_b = 0;
  c.point = c.witness_a = c.witness_b = Vec3(0.01, -0.02, 0.0);
  c.normal = Vec3::UnitZ();
  c.phi = 1e-4;
  return c;
}

// SPEC 2 for the plane's facet (B): mu_d = mu0 + k (2/pi) tan(theta) max(0, m'.d), where m'
// points down the facet's slope (-u = -x) and tan(theta) = kSlope.
double facetOracle(const Vec3& d) {
  return kMu0 + kGain * (2.0 / kPi) * kSlope * std::max(0.0, -d.x());
}

struct Case {
  const char* name;
  std::unique_ptr<FrictionProvider> (*make)();
  bool textured;     // false: mu0 in every direction
  double tolerance;  // relative
};

std::vector<Case> cases() {
  // The cone provider interpolates a cone of 64 directions kept in the texture's frame.
  return {
      {"constant", [] { return std::unique_ptr<FrictionProvider>(new ConstantProvider()); }, false,
       1e-6},
      {"cone", [] { return std::unique_ptr<FrictionProvider>(new ConeProvider()); }, true, 1e-2},
      {"cpu", [] { return std::unique_ptr<FrictionProvider>(new CpuPatchSampler()); }, true, 2e-3}};
}

TEST(StagesWithoutWorld, FramesProvidersAndBoxBoundsOnHandMadeContacts) {
  const std::vector<Body> scene = bodies();
  FrictionSettings settings;
  settings.mu0 = kMu0;
  settings.directions = 8;
  for (const Case& c : cases()) {
    // Frames turned about n in twelve directions: the bounds turn with them.
    for (int k = 0; k < 12; ++k) {
      const double angle = 2.0 * kPi * k / 12.0;
      FrameInputs in;
      in.bodies = scene;
      in.world_axis = Vec3(std::cos(angle), std::sin(angle), 0.0);
      std::vector<Contact> contacts{contactUnderCube()};
      computeContactFrames(FrameMode::World, in, contacts);
      const Contact& contact = contacts[0];
      EXPECT_LT((contact.t - in.world_axis).norm(), 1e-12) << c.name << " " << k;
      EXPECT_LT((contact.b - Vec3::UnitZ().cross(in.world_axis)).norm(), 1e-12);
      c.make()->computeCoefficients(scene, contacts, settings);
      const BoxLimit bounds = BoxLimit::fromDirectional(contact.mu);
      const double expected[4] = {facetOracle(contact.t), facetOracle(contact.b),
                                  facetOracle(-contact.t), facetOracle(-contact.b)};
      const double got[4] = {bounds.mu_pos_t, bounds.mu_pos_b, bounds.mu_neg_t, bounds.mu_neg_b};
      for (int side = 0; side < 4; ++side) {
        const double want = c.textured ? expected[side] : kMu0;
        EXPECT_TRUE(near(got[side], want, c.tolerance))
            << c.name << " angle " << k << " side " << side;
      }
      EXPECT_FALSE(contact.fallback) << c.name;
    }
  }
}

TEST(StagesWithoutWorld, AutoFramesWithoutAPredictionKeepTheWorldFrame) {
  // An engine that hands its contacts over alone has no frictionless prediction to offer.
  const std::vector<Body> scene = bodies();
  FrameInputs in;
  in.bodies = scene;
  in.world_axis = Vec3(0.0, 1.0, 0.0);
  std::vector<Contact> contacts{contactUnderCube()};
  computeContactFrames(FrameMode::Auto, in, contacts);
  EXPECT_LT((contacts[0].t - Vec3::UnitY()).norm(), 1e-12);
}

TEST(StagesWithoutWorld, AutoFramesFollowTheHandedPrediction) {
  // The cube predicted to slide along (1, 1, 0) relative to the still plane.
  const std::vector<Body> scene = bodies();
  const std::vector<Vec3> linear{Vec3::Zero(), Vec3(0.3, 0.3, 0.0)};
  const std::vector<Vec3> angular{Vec3::Zero(), Vec3::Zero()};
  FrameInputs in;
  in.bodies = scene;
  in.predict_velocities = [&](std::span<const Contact>) {
    return PredictedVelocities{linear, angular};
  };
  std::vector<Contact> contacts{contactUnderCube()};
  computeContactFrames(FrameMode::Auto, in, contacts);
  EXPECT_LT((contacts[0].t - Vec3(1.0, 1.0, 0.0).normalized()).norm(), 1e-12);
}

}  // namespace
}  // namespace asperity
