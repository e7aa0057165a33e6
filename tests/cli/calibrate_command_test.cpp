// `asperity calibrate`: known gains back from the tribometer's numbers, fixed and free
// parameters, the three kinds of measurements, the figure, the scene written, and one test per
// kind of bad input (the row or the parameter named).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;

const std::vector<std::string> kPair = {"gen:sawtooth:1:size=128,period=16", "--a",
                                        "gen:sawtooth:2:size=128,period=16,axis=v", "--tracks",
                                        "2"};

std::vector<std::string> with(std::vector<std::string> head, std::vector<std::string> a,
                              std::vector<std::string> b = {}) {
  head.insert(head.end(), a.begin(), a.end());
  head.insert(head.end(), b.begin(), b.end());
  return head;
}

// Measurements of the pair at k_A 1.5, k_B 0.8, mu0 0.3: the tribometer's mu_model in 8
// directions, written once as CSV (and as tilt angles, and as slides from 1 m/s).
class CalibrateCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::tempDir("calibrate"));
    const auto r = runCli(with({"tribometer"}, kPair,
                               {"--k-a", "1.5", "--k-b", "0.8", "--mu0", "0.3", "--directions", "8",
                                "--tests", "drag", "--json"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ofstream mu(file("mu.csv")), tilt(file("tilt.csv")), slide(file("slide.csv"));
    mu << "angle_deg,mu\n";
    tilt << "angle_deg,tilt_deg\n";
    slide << "# launched at 1 m/s\nangle_deg,speed,distance\n";
    const nlohmann::json result = nlohmann::json::parse(r.out);
    for (const nlohmann::json& d : result["directions"]) {
      const double a = d["angle_deg"], m = d["mu_model"];
      mu << a << ',' << m << '\n';
      tilt << a << ',' << std::atan(m) * 180.0 / 3.14159265358979323846 << '\n';
      slide << a << ",1," << 1.0 / (2.0 * 9.81 * m) << '\n';
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string file(const std::string& name) { return *dir_ + "/" + name; }
  static nlohmann::json fitted(std::vector<std::string> args) {
    const auto r = runCli(with({"calibrate"}, args, {"--json"}));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
  }
  static std::string* dir_;
};
std::string* CalibrateCommand::dir_ = nullptr;

TEST_F(CalibrateCommand, RecoversTheGainsFromEachKindOfMeasurement) {
  for (const char* name : {"mu.csv", "tilt.csv", "slide.csv"}) {
    const nlohmann::json j = fitted(with({file(name)}, kPair));
    EXPECT_NEAR(j["k_a"].get<double>(), 1.5, 0.03) << name;
    EXPECT_NEAR(j["k_b"].get<double>(), 0.8, 0.016) << name;
    EXPECT_NEAR(j["mu0"].get<double>(), 0.3, 0.006) << name;
    EXPECT_LT(j["rms_residual"].get<double>(), 0.01) << name;
  }
}

TEST_F(CalibrateCommand, JsonHasTheFittedKeysOnly) {
  const nlohmann::json j =
      fitted(with({file("mu.csv")}, kPair, {"--k-a", "1.5", "--mu0", "0.3", "--fit", "k_b"}));
  EXPECT_FALSE(j.contains("k_a"));
  EXPECT_FALSE(j.contains("mu0"));
  EXPECT_NEAR(j["k_b"].get<double>(), 0.8, 0.016);
  EXPECT_TRUE(j.contains("rms_residual"));
}

TEST_F(CalibrateCommand, TableFigureAndScene) {
  const auto r = runCli(with({"calibrate", file("mu.csv")}, kPair,
                             {"--png", file("fit.png"), "--write", file("fitted.json")}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A residual for every row, named by its line.
  EXPECT_NE(r.out.find("rms residual"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n     9 "), std::string::npos) << r.out;
  EXPECT_EQ(test::slurpBinary(file("fit.png")).substr(1, 3), "PNG");
  // The scene holds the fitted values and runs.
  const nlohmann::json scene = nlohmann::json::parse(test::slurpBinary(file("fitted.json")));
  EXPECT_NEAR(scene["settings"]["mu0"].get<double>(), 0.3, 0.006);
  EXPECT_EQ(runCli({"run", file("fitted.json"), "--steps", "3"}).exit_code, 0);
}

TEST_F(CalibrateCommand, IntoAScenesBodies) {
  const auto r = runCli({"calibrate", file("mu.csv"), "--scene", "scenes/boxes_on_materials.json",
                         "--bodies", "box_concrete,plane_concrete", "--fit", "mu0", "--tracks", "1",
                         "--write", file("boxes.json"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double mu0 = nlohmann::json::parse(r.out)["mu0"];
  const nlohmann::json scene = nlohmann::json::parse(test::slurpBinary(file("boxes.json")));
  EXPECT_DOUBLE_EQ(scene["settings"]["mu0"].get<double>(), mu0);
  EXPECT_EQ(runCli({"run", file("boxes.json"), "--steps", "2"}).exit_code, 0);
}

TEST_F(CalibrateCommand, BadInputIsAOneLineError) {
  std::ofstream(file("header.csv")) << "angle,friction\n0,0.5\n";
  std::ofstream(file("nan.csv")) << "angle_deg,mu\n0,0.5\n90,nan\n";
  std::ofstream(file("below.csv")) << "angle_deg,mu\n0,0.5\n90,0.1\n";
  expectOneLineError(runCli(with({"calibrate", "missing.csv"}, kPair)), "missing.csv");
  expectOneLineError(runCli(with({"calibrate", file("header.csv")}, kPair)), "header.csv:1");
  expectOneLineError(runCli(with({"calibrate", file("nan.csv")}, kPair)), "nan.csv:3");
  expectOneLineError(runCli(with({"calibrate", file("below.csv")}, kPair, {"--mu0", "0.2"})),
                     "below.csv:3");
  expectOneLineError(runCli(with({"calibrate", file("mu.csv")}, kPair, {"--fit", "k_c"})), "k_c");
  expectOneLineError(
      runCli(with({"calibrate", file("mu.csv")}, kPair, {"--fit", "k_a", "--k-a", "1"})),
      "--fit k_a");
  expectOneLineError(
      runCli({"calibrate", file("mu.csv"), "gen:gaussian:1:size=32", "--tracks", "1"}),
      "k_a adds nothing");
  expectOneLineError(runCli({"calibrate", file("mu.csv"), "--scene",
                             "scenes/boxes_on_materials.json", "--bodies", "box_steel,nosuch"}),
                     "nosuch");
  expectOneLineError(runCli({"calibrate", file("mu.csv"), "nothere.png"}), "nothere.png");
}

}  // namespace
}  // namespace asperity
