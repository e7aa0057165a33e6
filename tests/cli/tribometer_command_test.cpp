// `asperity tribometer`: JSON with one entry per direction, a scene's bodies, the figures, the
// same numbers on any thread count, a toppled block as null, and one test per kind of bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;

// Runs `tribometer ARGS` and returns the result.
test::CommandResult tribometer(std::vector<std::string> args) {
  args.insert(args.begin(), "tribometer");
  return runCli(args);
}

// A quick run: 4 directions, one track, small generated textures.
const std::vector<std::string> kQuick = {"gen:gaussian:1:size=64",
                                         "--a",
                                         "gen:gaussian:2:size=64",
                                         "--mu0",
                                         "0.2",
                                         "--directions",
                                         "4",
                                         "--tracks",
                                         "1"};

std::vector<std::string> with(std::vector<std::string> args, std::vector<std::string> more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(TribometerCommand, JsonHasEveryDirectionWithItsThreeCoefficients) {
  const auto r = tribometer(with(kQuick, {"--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["directions"].size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    const nlohmann::json& d = j["directions"][k];
    EXPECT_DOUBLE_EQ(d["angle_deg"].get<double>(), 90.0 * static_cast<double>(k));
    ASSERT_TRUE(d["mu_s"].is_number() && d["mu_k"].is_number() && d["mu_model"].is_number());
    // mu0 plus the ploughing of two rough surfaces; mu_k delivers mu_model, the plain mean of
    // the corners' coefficients, to within what one track over 4 mm facets of rms slope 1 lets
    // the loads lean toward the grippier corners (tests/tribometer/drag_test.cpp holds mu_k to
    // the load-weighted mean within 1 %).
    EXPECT_GT(d["mu_k"].get<double>(), 0.3);
    EXPECT_NEAR(d["mu_k"].get<double>(), d["mu_model"].get<double>(),
                0.1 * d["mu_model"].get<double>());
  }
}

TEST(TribometerCommand, SameOutputOnOneAndTwoThreads) {
  const auto one = tribometer(with(kQuick, {"--json", "--threads", "1"}));
  const auto two = tribometer(with(kQuick, {"--json", "--threads", "2"}));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
}

TEST(TribometerCommand, TwoBodiesOfAScene) {
  const auto r =
      tribometer({"--scene", "scenes/boxes_on_materials.json", "--bodies", "box_steel,plane_steel",
                  "--directions", "4", "--tracks", "1", "--tests", "drag", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  // The scene's mu0 = 0.2 and gains 2 on plaster and steel; no tilt table asked for.
  for (const nlohmann::json& d : j["directions"]) {
    EXPECT_TRUE(d["mu_s"].is_null());
    EXPECT_GT(d["mu_k"].get<double>(), 0.2);
  }
}

TEST(TribometerCommand, AToppledBlockHasNoStaticCoefficient) {
  // A 30 cm tall block tips over at tan = 1/3, below mu0 = 0.8.
  const std::vector<std::string> args = {"gen:gaussian:1:size=32",
                                         "--sampler",
                                         "constant",
                                         "--mu0",
                                         "0.8",
                                         "--block-height",
                                         "0.3",
                                         "--directions",
                                         "4",
                                         "--tracks",
                                         "1",
                                         "--tests",
                                         "tilt"};
  const auto json = tribometer(with(args, {"--json"}));
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_TRUE(nlohmann::json::parse(json.out)["directions"][0]["mu_s"].is_null());
  const auto table = tribometer(args);
  EXPECT_NE(table.out.find("toppled"), std::string::npos) << table.out;
}

TEST(TribometerCommand, WritesTheFigure) {
  const std::string dir = test::tempDir("tribometer");
  const auto r = tribometer(with(kQuick, {"--png", dir + "/t.png", "--svg", dir + "/t.svg"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::slurpBinary(dir + "/t.png").substr(1, 3), "PNG");
  EXPECT_NE(test::slurpBinary(dir + "/t.svg").find("<svg"), std::string::npos);
  EXPECT_NE(r.out.find("mu_model"), std::string::npos);
}

TEST(TribometerCommand, BadInputIsAOneLineError) {
  expectOneLineError(tribometer({"missing.png"}), "missing.png");
  expectOneLineError(tribometer({"gen:gaussian:1", "--directions", "0"}), "--directions");
  expectOneLineError(tribometer({"gen:gaussian:1", "--directions", "many"}), "--directions");
  expectOneLineError(tribometer({"gen:nosuch:1"}), "nosuch");
  expectOneLineError(tribometer({"gen:oak"}), "gen:oak");
  expectOneLineError(tribometer({"gen:oak:1", "--a", "nothere.png"}), "nothere.png");
  expectOneLineError(
      tribometer({"--scene", "scenes/boxes_on_materials.json", "--bodies", "box_steel,nosuch"}),
      "nosuch");
  expectOneLineError(tribometer({"--scene", "scenes/boxes_on_materials.json"}), "--bodies");
  expectOneLineError(tribometer({}), "B.png");
  expectOneLineError(tribometer({"gen:oak:1", "--scene", "scenes/boxes_on_materials.json",
                                 "--bodies", "box_steel,plane_steel"}),
                     "not both");
  expectOneLineError(tribometer({"gen:oak:1", "--load", "-1"}), "--load");
  expectOneLineError(tribometer({"gen:oak:1", "--tests", "spin"}), "--tests");
  expectOneLineError(tribometer({"gen:oak:1", "--sampler", "gl"}), "--sampler");
}

}  // namespace
}  // namespace asperity
