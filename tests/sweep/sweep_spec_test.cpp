// Variations: PATH=SPEC parsing, `*` expansion, and seeded draws that depend only on
// (seed, sample, variation).
#include "asperity/sweep/sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "asperity/error.hpp"

namespace asperity {
namespace {

// Two sliding boxes on a plane, constant friction.
nlohmann::json twoBoxes() {
  return nlohmann::json::parse(R"({
    "settings": {"sampler": "constant", "mu0": 0.5},
    "bodies": [
      {"name": "ground", "type": "static", "shapes": [{"type": "plane"}]},
      {"name": "a", "position": [0, 0, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]},
      {"name": "b", "position": [0, 1, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]}]})");
}

SweepDesc descWith(std::vector<std::string> vary, int64_t samples = 16) {
  SweepDesc d;
  d.scene_json = twoBoxes().dump();
  d.scene_file = "two_boxes.json";
  for (const std::string& v : vary) d.vary.push_back(parseVariation(v));
  d.samples = samples;
  d.seconds = 0.0;
  return d;
}

TEST(SweepSpec, ParsesEveryDistribution) {
  const Variation u = parseVariation("/settings/mu0=uniform(0.1, 0.3)");
  EXPECT_EQ(u.path, "/settings/mu0");
  EXPECT_EQ(u.distribution, Distribution::Uniform);
  EXPECT_EQ(u.args, (std::vector<double>{0.1, 0.3}));
  EXPECT_EQ(parseVariation("/a=normal(1,2)").distribution, Distribution::Normal);
  EXPECT_EQ(parseVariation("/a=choice(1,2,5)").args.size(), 3u);
  EXPECT_EQ(parseVariation("/a=grid(0,1,5)").distribution, Distribution::Grid);
}

TEST(SweepSpec, RejectsBadSpecsNamingThem) {
  for (const char* bad : {"/a", "a=uniform(0,1)", "/a=uniform(0)", "/a=uniform(1,0)",
                          "/a=normal(0,-1)", "/a=choice()", "/a=grid(0,1,0)", "/a=grid(0,1,2.5)",
                          "/a=beta(1,2)", "/a=uniform(0,x)", "/a=uniform(0,nan)", "/a=uniform"}) {
    try {
      parseVariation(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const SweepError& e) {
      // In the library's words; a front end names its own option for the field.
      EXPECT_EQ(e.field(), SweepField::Vary) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("variation '", 0), 0u) << e.what();
      EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
      EXPECT_EQ(e.messageNaming("--vary"), "--vary " + e.subject() + ": " + e.problem());
    }
  }
}

TEST(SweepSpec, StarExpandsToEveryArrayElement) {
  const auto p = expandPath(twoBoxes(), "/bodies/*/linear_velocity/0");
  EXPECT_EQ(
      p, (std::vector<std::string>{"/bodies/1/linear_velocity/0", "/bodies/2/linear_velocity/0"}));
  // Below a '*', elements without the rest of the path (the ground's velocity) drop out; a
  // path that no element has is an error.
  EXPECT_EQ(expandPath(twoBoxes(), "/bodies/*/position/2").size(), 2u);
  EXPECT_THROW(expandPath(twoBoxes(), "/bodies/*/velocity/0"), Error);
  EXPECT_THROW(expandPath(twoBoxes(), "/bodies/*/linear_velocity/7"), Error);
  EXPECT_THROW(expandPath(twoBoxes(), "/settings/nope"), Error);
  EXPECT_THROW(expandPath(twoBoxes(), "/bodies/1/name"), Error);  // not a number
  EXPECT_THROW(expandPath(twoBoxes(), "/settings/*"), Error);     // not an array
}

TEST(SweepSpec, DrawsDependOnlyOnSeedSampleAndVariation) {
  const Sweep one(descWith({"/settings/mu0=uniform(0.2,0.4)", "/bodies/1/position/0=normal(0,1)"}));
  SweepDesc d =
      descWith({"/settings/mu0=uniform(0.2,0.4)", "/bodies/1/position/0=normal(0,1)"}, 64);
  const Sweep more(d);
  // The same sample gives the same values whatever the sample count.
  for (int64_t i = 0; i < 16; ++i) EXPECT_EQ(one.values(i), more.values(i));
  // Another seed draws other values.
  d.seed = 2;
  EXPECT_NE(Sweep(d).values(0), more.values(0));
}

TEST(SweepSpec, UniformStaysInRangeAndNormalHasItsMoments) {
  const Sweep s(
      descWith({"/settings/mu0=uniform(0.2,0.4)", "/bodies/1/position/0=normal(3,2)"}, 20000));
  double sum = 0.0, sum2 = 0.0;
  for (int64_t i = 0; i < 20000; ++i) {
    const auto v = s.values(i);
    EXPECT_GE(v[0], 0.2);
    EXPECT_LT(v[0], 0.4);
    sum += v[1], sum2 += v[1] * v[1];
  }
  // Mean 3 and sd 2 within about 4 standard errors.
  const double mean = sum / 20000.0, sd = std::sqrt(sum2 / 20000.0 - mean * mean);
  EXPECT_NEAR(mean, 3.0, 0.06);
  EXPECT_NEAR(sd, 2.0, 0.06);
}

TEST(SweepSpec, ChoiceTakesEveryValueAndGridsEnumerateInMixedRadix) {
  const Sweep s(descWith({"/settings/mu0=choice(0.1,0.2,0.3)", "/bodies/1/position/0=grid(0,1,3)",
                          "/bodies/2/position/0=grid(5,6,2)"},
                         6));
  std::set<double> seen;
  for (int64_t i = 0; i < 300; ++i) seen.insert(s.values(i % 6)[0]);
  const Sweep wide(descWith({"/settings/mu0=choice(0.1,0.2,0.3)"}, 300));
  for (int64_t i = 0; i < 300; ++i) seen.insert(wide.values(i)[0]);
  EXPECT_EQ(seen, (std::set<double>{0.1, 0.2, 0.3}));
  // First grid fastest: (0, 5), (0.5, 5), (1, 5), (0, 6), (0.5, 6), (1, 6).
  const double first[] = {0.0, 0.5, 1.0, 0.0, 0.5, 1.0}, second[] = {5, 5, 5, 6, 6, 6};
  for (int64_t i = 0; i < 6; ++i) {
    EXPECT_EQ(s.values(i)[1], first[i]);
    EXPECT_EQ(s.values(i)[2], second[i]);
  }
}

}  // namespace
}  // namespace asperity
