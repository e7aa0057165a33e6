// Running sweeps: the Coulomb slide distance v^2 / (2 mu g) per sample, identical results on
// any thread count, the CSV table, and the errors of bad sweeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/sweep/sweep.hpp"
#include "asperity/world/run_loop.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// A box sliding on a plane with constant friction mu0 = 0.5.
SweepDesc slidingBox(int64_t samples) {
  SweepDesc d;
  d.scene_json = R"({
    "settings": {"sampler": "constant", "mu0": 0.5, "dt": 0.005},
    "bodies": [
      {"name": "ground", "type": "static", "shapes": [{"type": "plane"}]},
      {"name": "box", "position": [0, 0, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]}]})";
  d.scene_file = "sliding_box.json";
  d.vary = {parseVariation("/bodies/*/linear_velocity/0=uniform(0.5,2)")};
  d.samples = samples;
  d.seed = 7;
  d.seconds = 0.6;
  d.measures = {"distance:box", "speed:box", "height:box", "angle:box"};
  return d;
}

TEST(SweepRun, SlideDistanceIsCoulombsForEverySample) {
  const Sweep sweep(slidingBox(6));
  for (const SampleResult& r : sweep.runAll(2)) {
    // d = v^2 / (2 mu g), at rest (speed 0), on the ground (z = 0.1), not turned.
    const double v = r.values[0];
    EXPECT_TRUE(test::near(r.measures[0], v * v / (2.0 * 0.5 * 9.81), 0.03, 0.003)) << "v = " << v;
    EXPECT_NEAR(r.measures[1], 0.0, 1e-6);
    EXPECT_NEAR(r.measures[2], 0.1, 2e-3);
    EXPECT_NEAR(r.measures[3], 0.0, 0.5);
  }
}

TEST(SweepRun, ResultsDoNotDependOnTheThreadCount) {
  const Sweep sweep(slidingBox(8));
  const auto one = sweep.runAll(1), two = sweep.runAll(2), all = sweep.runAll(0);
  EXPECT_EQ(sweep.csv(one), sweep.csv(two));
  EXPECT_EQ(sweep.csv(one), sweep.csv(all));
  // A subset of indices gives the same rows as the full run.
  const std::vector<int64_t> some = {5, 2};
  const auto subset = sweep.runAll(2, some);
  EXPECT_EQ(subset[0].state_hash, one[5].state_hash);
  EXPECT_EQ(subset[1].state_hash, one[2].state_hash);
}

TEST(SweepRun, CsvHasOneColumnPerValuePoseAndMeasure) {
  const Sweep sweep(slidingBox(2));
  const std::string csv = sweep.csv(sweep.runAll(1));
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header,
            "sample,/bodies/*/linear_velocity/0,ground.x,ground.y,ground.z,ground.qw,ground.qx,"
            "ground.qy,ground.qz,box.x,box.y,box.z,box.qw,box.qx,box.qy,box.qz,distance:box,"
            "speed:box,height:box,angle:box,state_hash");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
}

TEST(SweepRun, BadSweepsAreRejectedNamingTheCulprit) {
  auto expectError = [](SweepDesc d, const std::string& part) {
    try {
      const Sweep sweep(std::move(d));
      sweep.runAll(1);
      ADD_FAILURE() << "accepted; expected " << part;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  SweepDesc d = slidingBox(2);
  d.samples = 0;
  expectError(d, "samples: must be in 1..100000000, got 0");
  d = slidingBox(2);
  d.seconds = -1.0;
  expectError(d, "seconds: must be a finite number >= 0");
  d = slidingBox(2);
  d.measures = {"distance:nobody"};
  expectError(d, "no body named 'nobody'");
  d.measures = {"volume:box"};
  expectError(d, "measure 'volume:box'");
  // A drawn value the scene rejects names the sample and the JSON path.
  d = slidingBox(2);
  d.vary = {parseVariation("/bodies/1/shapes/0/half_extents/0=uniform(-2,-1)")};
  expectError(d, "sample 0: sliding_box.json: /bodies/1/shapes/0/half_extents/0");
  // The OpenGL sampler needs a context that pool threads do not have.
  d = slidingBox(2);
  const size_t sampler = d.scene_json.find("\"constant\"");
  d.scene_json.replace(sampler, 10, "\"gl\"");
  expectError(d,
              "sampler \"gl\" cannot run in a sweep (available: cone, constant, cpu)");
  // A scene that is not JSON names its file.
  d = slidingBox(2);
  d.scene_json = "{";
  expectError(d, "sliding_box.json: not valid JSON");
  d = slidingBox(2);
  const std::vector<int64_t> outside = {2};
  EXPECT_THROW(Sweep(d).runAll(1, outside), Error);
}

}  // namespace
}  // namespace asperity
