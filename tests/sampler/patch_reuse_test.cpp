// Patch coherence (sampler/patch_reuse.hpp): resting contacts keep their sample, moving ones
// are sampled again, the kept coefficients stay those a fresh sample gives, and the result
// does not depend on the thread count.
#include "sampler/patch_reuse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/sampler/patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

std::unique_ptr<World> scene(const std::string& file, double reuse_pixels, int threads = 1) {
  SceneDesc desc = loadScene(test::sourcePath("scenes/" + file));
  desc.settings.friction.reuse_pixels = reuse_pixels;
  desc.settings.threads = threads;
  return instantiate(desc);
}

// Reused contacts over all contacts during `steps` steps.
double reusedShare(World& world, int steps) {
  double reused = 0, contacts = 0;
  for (int i = 0; i < steps; ++i) {
    world.step();
    reused += world.profile().reused;
    contacts += world.profile().contacts;
  }
  return contacts > 0 ? reused / contacts : 0.0;
}

TEST(PatchReuse, OnByDefaultAndOffAtZero) {
  EXPECT_EQ(FrictionSettings{}.reuse_pixels, 0.1);
  auto world = scene("stacking.json", 0.0);
  EXPECT_EQ(reusedShare(*world, 100), 0.0);
}

// The world's cpu sampler with patch coherence, checked at every call against a fresh sample
// of each contact it kept: the largest difference of any direction's mu, and how many of the
// kept (contact, direction) pairs differ by more than 0.005.
class CheckedReuse : public FrictionProvider {
 public:
  CheckedReuse() = default;
  std::string name() const override { return "cpu"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override {
    std::vector<Contact> fresh(contacts.begin(), contacts.end());
    FrictionSettings every_step = settings;
    every_step.reuse_pixels = 0.0;
    reference_.computeCoefficients(bodies, fresh, every_step);
    sampler_.computeCoefficients(bodies, contacts, settings);
    for (size_t i = 0; i < contacts.size(); ++i)
      for (int k = 0; k < contacts[i].mu.count; ++k) {
        const double apart = std::abs(double(contacts[i].mu.mu[static_cast<size_t>(k)]) -
                                      double(fresh[i].mu.mu[static_cast<size_t>(k)]));
        worst = std::max(worst, apart);
        kept += apart > 0.0;
        far += apart > 0.005;
      }
  }
  ProviderStats lastStats() const override { return sampler_.lastStats(); }
  double worst = 0.0;
  int kept = 0, far = 0;  // (contact, direction) pairs that differ at all, by more than 0.005

 private:
  CpuPatchSampler sampler_, reference_;
};

TEST(PatchReuse, RestingStackKeepsItsSamplesWithFreshCoefficients) {
  auto world = scene("stacking.json", 0.1);
  auto checked = std::make_unique<CheckedReuse>();
  const CheckedReuse& check = *checked;
  world->setFrictionProvider(std::move(checked));
  reusedShare(*world, 200);  // the stacks, hit at 0.2 s, have settled by 2 s
  const double share = reusedShare(*world, 50);
  std::printf("stacking: reused %.3f, differing pairs %d, beyond 0.005 %d, worst %.4f\n", share,
              check.kept, check.far, check.worst);
  EXPECT_GT(share, 0.8);
  // A kept sample is what sampling the contact again would give, to well within mu's scale
  // (mu 0.2 to 0.4 here). Each pixel reads one texel's facet, so a pixel centre that crossed a
  // texel edge within the 0.1 pixel move reads a neighbouring facet in a fresh sample: about
  // one pair in twenty differs by more than 0.005, by a few hundredths at most, as much as two
  // fresh samples a tenth of a pixel apart differ (docs/samplers.md, "Patch coherence").
  EXPECT_GT(check.kept, 10000);
  EXPECT_LT(check.far, check.kept / 10);
  EXPECT_LT(check.worst, 0.1);
}

TEST(PatchReuse, SlidingBoxesAreSampledEveryStep) {
  // The boxes slide about a centimetre per step, eight patch pixels: nothing is kept.
  auto world = scene("boxes_on_materials.json", 0.25);
  EXPECT_EQ(reusedShare(*world, 20), 0.0);
}

// A textured box thrown along a floor: the floor is the scene's last body, plain or textured.
std::unique_ptr<World> slidingBox(bool textured_floor, double speed) {
  nlohmann::json floor = {{"base_color", {0.3, 0.3, 0.3}}, {"gain", 1}};
  if (textured_floor) floor = "concrete";
  const nlohmann::json scene = {
      {"settings", {{"dt", 0.01}, {"mu0", 0.2}, {"patch_width", 0.02}, {"frame_mode", "world"}}},
      {"materials",
       {{"concrete",
         {{"normal_map", {{"generator", "concrete"}, {"size", 128}, {"seed", 3}}},
          {"gain", 1},
          {"texture_size", 0.2}}}}},
      {"bodies",
       {{{"name", "box"},
         {"position", {0, 0, 0.1}},
         {"linear_velocity", {speed, 0, 0}},
         {"shapes",
          {{{"type", "box"}, {"half_extents", {0.1, 0.1, 0.1}}, {"surface", "concrete"}}}}},
        {{"name", "floor"},
         {"type", "static"},
         {"shapes", {{{"type", "plane"}, {"surface", floor}}}}}}}};
  return instantiate(parseScene(scene, "sliding box"));
}

TEST(PatchReuse, ABoxSlidingOnAPlainFloorKeepsItsSamples) {
  // Every point of an untextured plane looks the same to a patch: the box's samples hold while
  // the box keeps its place under the contact frame, however far it slides (a few patch pixels
  // a step here), and stay what sampling again would give. On a textured floor they do not.
  for (double speed : {1.0, 2.0, 3.0}) {
    SCOPED_TRACE(speed);
    auto plain = slidingBox(false, speed);
    auto checked = std::make_unique<CheckedReuse>();
    const CheckedReuse& check = *checked;
    plain->setFrictionProvider(std::move(checked));
    plain->step();  // land
    const Vec3 before = plain->bodies()[0].pose.position;
    EXPECT_GT(reusedShare(*plain, 15), 0.8);
    const double moved = (plain->bodies()[0].pose.position - before).norm();
    EXPECT_GT(moved, 0.05);  // far more than the 0.1 pixel (0.125 mm) tolerance
    // Here bit for bit: the box only translates, so its pixels are the same.
    EXPECT_EQ(check.far, 0);
    EXPECT_LT(check.worst, 0.005);
    auto textured = slidingBox(true, speed);
    textured->step();
    EXPECT_EQ(reusedShare(*textured, 15), 0.0);
  }
}

TEST(PatchReuse, TheWormKeepsItsSamplesOnItsPlainFloor) {
  // The crawling worm's segments slide along an untextured floor: most of their samples are
  // kept, and stay close to what sampling again gives.
  auto world = scene("crawling_worm.json", 0.1);
  auto checked = std::make_unique<CheckedReuse>();
  const CheckedReuse& check = *checked;
  world->setFrictionProvider(std::move(checked));
  const double share = reusedShare(*world, 200);
  std::printf("crawling_worm: reused %.3f, differing pairs %d, beyond 0.005 %d, worst %.4f\n",
              share, check.kept, check.far, check.worst);
  EXPECT_GT(share, 0.8);
  // Its sawtooth skin strays as the sawtooth plate does (docs/samplers.md, "Patch coherence"):
  // a tenth of a pixel's move changes a fresh sample by a few hundredths; samples of few
  // pixels, which one pixel would change by far more, are not kept.
  EXPECT_LT(check.far, check.kept / 5);
  EXPECT_LT(check.worst, 0.1);
}

TEST(PatchReuse, SameBitsOnOneAndTwoThreads) {
  auto one = scene("stacking.json", 0.25, 1), two = scene("stacking.json", 0.25, 2);
  for (int i = 0; i < 150; ++i) one->step(), two->step();
  EXPECT_EQ(one->stateHash(), two->stateHash());
}

TEST(PatchReuse, BadToleranceIsNamed) {
  FrictionSettings s;
  s.reuse_pixels = -1.0;
  EXPECT_NE(test::errorOf([&] {
              validate(s, "cpu sampler");
            }).find("cpu sampler: reuse_pixels must be a finite number >= 0, got -1"),
            std::string::npos);
}

}  // namespace
}  // namespace asperity
