// The paper's experiments (SPEC 7): each scene in scenes/ runs headless through the scene
// library and must show what Sec. 5 shows. Numbers are asserted, not just pass flags.
#include "experiments/experiment_outcomes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"

namespace asperity::experiments {
namespace {

RunOptions options() {
  RunOptions o;
  o.scenes_dir = test::sourcePath("scenes");
  o.record_every = 5;
  return o;
}

// Sliding to rest from v0 with mu >= mu0 everywhere cannot go farther than v0^2 / (2 mu0 g).
constexpr double kBoxSpeed = 2.0;  // m/s, boxes_on_materials.json
constexpr double kMu0 = 0.2;

TEST(ExperimentCatalog, ListsEveryExperimentWithLoadableScenes) {
  ASSERT_GE(experimentCatalog().size(), 4u);
  for (const Experiment& e : experimentCatalog()) {
    EXPECT_FALSE(e.paper.empty()) << e.id;
    for (const SceneRun& run : e.scenes) {
      EXPECT_GT(run.seconds, 0.0) << run.file;
      EXPECT_NO_THROW(loadScene(test::sourcePath("scenes/" + run.file))) << run.file;
    }
  }
}

TEST(ExperimentCatalog, UnknownIdIsAnErrorNamingTheKnownOnes) {
  try {
    findExperiment("boxes_on_marbles");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("boxes_on_materials"), std::string::npos) << e.what();
  }
}

TEST(ExperimentCatalog, MissingSceneFolderIsAnErrorNamingTheFile) {
  RunOptions o = options();
  o.scenes_dir = "no/such/folder";
  try {
    runExperiment("boxes_on_materials", o);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("boxes_on_materials.json"), std::string::npos);
  }
}

// Sec. 5.1: the rougher the plane, the shorter the slide.
TEST(BoxesOnMaterials, RougherPlanesStopBoxesSooner) {
  const Outcome out = runExperiment("boxes_on_materials", options());
  const double concrete = out.value("slide_concrete"), cast_iron = out.value("slide_cast_iron");
  const double steel = out.value("slide_steel"), plastic = out.value("slide_plastic");
  EXPECT_LT(concrete, cast_iron);
  EXPECT_LT(cast_iron, steel);
  EXPECT_LE(steel, plastic);
  // Every slide stops within the mu0-only bound; the rough concrete at least 30 % sooner.
  const double bound = kBoxSpeed * kBoxSpeed / (2.0 * kMu0 * 9.81);
  EXPECT_LT(plastic, bound);
  EXPECT_LT(concrete, 0.7 * plastic);
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.2, Fig. 12: along the ridges > up the ramps > against the steep faces (stuck).
TEST(SawtoothPlane, GlidesAlongSlidesUpRampsSticksAgainstSteepFaces) {
  const Outcome out = runExperiment("sawtooth_plane", options());
  const double along = out.value("travel_along"), ramp = out.value("travel_ramp");
  const double steep = out.value("travel_steep");
  EXPECT_GT(along, ramp);
  EXPECT_GT(ramp, 0.1);
  EXPECT_TRUE(steep < 0.05 || out.value("tilt_steep_max") > 30.0) << out.explanation;
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.3, Fig. 14: the acrylic cube leaves the stack, the PVC cube moves least.
TEST(Stacking, AcrylicShootsOutPvcMovesLeastBothDirections) {
  const Outcome out = runExperiment("stacking", options());
  for (const std::string dir : {"sideways", "forward"}) {
    const double acrylic = out.value(dir + "_acrylic"), oak = out.value(dir + "_oak");
    const double pvc = out.value(dir + "_pvc");
    EXPECT_GT(acrylic, 0.2) << dir << ": a cube width, clear of the stack";
    EXPECT_GT(acrylic, oak) << dir;
    EXPECT_GT(oak, pvc) << dir;
    EXPECT_LT(pvc, 0.2) << dir << ": still on the stack";
  }
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.2: the worm's centre of mass advances every period; the turned texture reverses it.
TEST(CrawlingWorm, CrawlsForwardSteadilyAndBackwardWithTurnedTexture) {
  const Outcome out = runExperiment("crawling_worm", options());
  EXPECT_GT(out.value("advance_forward"), 0.05);
  EXPECT_GT(out.value("least_period_forward"), 0.0);
  EXPECT_LT(out.value("advance_reversed"), -0.05);
  EXPECT_GT(out.value("least_period_reversed"), 0.0);
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.5: planes turned 45 degrees; auto and texture frames recover along > ramp > steep,
// world frames (diagonal to the ridges) lose it: the box pulled along the ridges is held back.
TEST(SawtoothPlaneRotated, AutoAndTextureFramesRecoverTheOrderingWorldDoesNot) {
  const Outcome out = runExperiment("sawtooth_plane_rotated", options());
  for (const std::string mode : {"auto", "texture"}) {
    EXPECT_GT(out.value(mode + "_along"), out.value(mode + "_ramp")) << mode;
    EXPECT_GT(out.value(mode + "_ramp"), 0.1) << mode;
    EXPECT_LT(out.value(mode + "_steep"), 0.05) << mode;
  }
  // The aligned frames give the unrotated scene's glide along the ridges, world frames far less.
  EXPECT_LT(out.value("world_along"), 0.6 * out.value("auto_along"));
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.4, Fig. 16: stone sticks and tips where it lands; metal and plastic slide upright to
// the logo and tumble on it.
TEST(TumblingBunnies, StoneSticksAndTipsOthersSlideThenTumbleAtTheLogo) {
  const Outcome out = runExperiment("tumbling_bunnies", options());
  const double stone = out.value("travel_stone");
  EXPECT_LT(stone, out.value("travel_metal") / 3.0);
  EXPECT_LT(stone, out.value("travel_plastic") / 3.0);
  EXPECT_GT(std::max(out.value("rotation_before_logo_stone"), out.value("rotation_on_logo_stone")),
            45.0);
  for (const std::string b : {"metal", "plastic"}) {
    EXPECT_LT(out.value("rotation_before_logo_" + b), 45.0) << b;
    EXPECT_GT(out.value("rotation_on_logo_" + b), 45.0) << b;
  }
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.2, Fig. 13: the thread is only in the normal map; with frames along it a torque screws
// the nut at one pitch per turn and an axial push (0.3 of its weight) does not move it.
TEST(NutBolt, TorqueScrewsOnePitchPerTurnPushDoesNotSlide) {
  const Outcome out = runExperiment("nut_bolt", options());
  EXPECT_GE(std::abs(out.value("turns")), 1.0);
  EXPECT_NEAR(std::abs(out.value("advance_per_turn")), 0.0007, 0.15 * 0.0007);
  EXPECT_LT(out.value("pushed_displacement"), 0.0001);
  EXPECT_TRUE(out.passed) << out.explanation;
}

// Sec. 5.1, Figs. 10 and 11: the same throw wraps the rough rod and slips off the smooth one.
// Over 40 throws (2 to 6 m/s, the hit moved up to 10 mm, heading up to 5 degrees; a sweep, the
// same draws for both rods) the rough rod holds at least 10 more than the smooth one, which
// lets at least 30 slip. Measured: 22 and 5 held (seeds 2 and 3: 23 and 9, 24 and 7); the
// issue's 36 of 40 on the rough rod is not reached: docs/experiments.md has why. The hold map
// (constant mu) holds no throw at mu 0.1 and every throw from mu 0.5; the rods sample about
// 0.26 and 0.14.
TEST(ChainBolas, WrapsTheRoughRodSlipsOffTheSmoothOne) {
  const Outcome out = runExperiment("chain_bolas", options());
  EXPECT_GT(out.value("height_rough"), 0.5);
  EXPECT_LT(out.value("height_smooth"), 0.2);
  EXPECT_GE(out.value("throws_held_rough"), out.value("throws_held_smooth") + 10);
  EXPECT_LE(out.value("throws_held_smooth"), 10);
  EXPECT_EQ(out.value("hold_map_held_mu_0.1"), 0);
  EXPECT_EQ(out.value("hold_map_held_mu_0.5_0.6"), 10);
  EXPECT_GT(out.value("sampled_mu_rough"), out.value("sampled_mu_smooth") + 0.08);
  ASSERT_EQ(out.tables.size(), 1u);
  EXPECT_EQ(out.tables[0].rows.size(), 40u);
  EXPECT_TRUE(out.passed) << out.explanation;
}

// The grip the bolas relies on, at rest: the same chain laid over each rod with leg tensions
// 1.44:1 (weights 1.4 and 0.87 kg). The rough rod's sampled mu (about 0.3) holds it, the smooth
// rod's (about 0.13) lets the heavy side run to the ground. docs/experiments.md has the margins.
double heavyBallDrop(const std::string& scene_file, double seconds) {
  const Recording rec = simulate(scene_file, seconds, options(), {"ball_0"});
  const std::vector<Transform>& heavy = rec.of("ball_0");
  return heavy.front().position.z() - heavy.back().position.z();
}

TEST(ChainBolas, DrapedChainHoldsOnTheRoughRodRunsOffTheSmoothOne) {
  EXPECT_LT(heavyBallDrop("chain_draped_rough.json", 3.0), 0.01);
  EXPECT_GT(heavyBallDrop("chain_draped_smooth.json", 3.0), 1.0);  // on the ground
}

}  // namespace
}  // namespace asperity::experiments
