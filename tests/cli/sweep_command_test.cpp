// `asperity sweep`: the same bytes on 1 and 2 threads, one row per sample whose hash equals
// `asperity run --hash` of the varied scene, and one test per bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;
using test::slurpBinary;

std::string minimal() {
  return test::sourcePath("scenes/examples/minimal.json");
}

std::vector<std::string> sweepArgs(const std::string& out, const std::string& threads) {
  return {"sweep",     minimal(), "--vary",    "/bodies/*/linear_velocity/0=uniform(0.5,1.5)",
          "--samples", "5",       "--seconds", "0.3",
          "--seed",    "4",       "--measure", "distance:box",
          "--threads", threads,   "--out",     out};
}

TEST(SweepCommand, SameBytesOnAnyThreadCount) {
  const std::string dir = test::tempDir("sweep");
  const auto one = runCli(sweepArgs(dir + "/one.csv", "1"));
  const auto two = runCli(sweepArgs(dir + "/two.csv", "2"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const std::string csv = slurpBinary(dir + "/one.csv");
  EXPECT_EQ(csv, slurpBinary(dir + "/two.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);
}

TEST(SweepCommand, RowHashEqualsRunOfTheVariedScene) {
  const std::string dir = test::tempDir("sweep_hash");
  ASSERT_EQ(runCli(sweepArgs(dir + "/s.csv", "2")).exit_code, 0);
  // Row of sample 0: its drawn velocity (column 2) written into the scene by hand.
  std::stringstream csv(slurpBinary(dir + "/s.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  const std::string value = row.substr(2, row.find(',', 2) - 2);
  const std::string hash = row.substr(row.rfind(',') + 1);
  nlohmann::json scene = nlohmann::json::parse(slurpBinary(minimal()));
  scene["bodies"][1]["linear_velocity"][0] = std::stod(value);
  const std::string edited = dir + "/edited.json";
  std::ofstream(edited) << scene.dump();
  const auto r = runCli({"run", edited, "--seconds", "0.3", "--hash"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, hash + "\n");
}

TEST(SweepCommand, BadInputsAreOneLineErrors) {
  const std::string out = test::tempDir("sweep_bad") + "/s.csv";
  expectOneLineError(runCli({"sweep", "missing.json", "--out", out}), "missing.json");
  // The sweep library's errors, with this command's option names.
  expectOneLineError(runCli({"sweep", minimal(), "--vary", "/nope=uniform(0,1)", "--out", out}),
                     "--vary /nope: /nope is not in the scene");
  expectOneLineError(runCli({"sweep", minimal(), "--vary", "/settings", "--out", out}),
                     "--vary '/settings': expected PATH=SPEC");
  expectOneLineError(
      runCli({"sweep", minimal(), "--vary", "/bodies/1/position/2=gamma(1,2)", "--out", out}),
      "--vary '/bodies/1/position/2=gamma(1,2)': unknown distribution 'gamma'");
  expectOneLineError(runCli({"sweep", minimal(), "--measure", "distance:ghost", "--out", out}),
                     "--measure 'distance:ghost': the scene has no body named 'ghost'");
  expectOneLineError(runCli({"sweep", minimal(), "--samples", "0", "--out", out}), "--samples");
  expectOneLineError(runCli({"sweep", minimal(), "--threads", "-1", "--out", out}), "--threads");
  expectOneLineError(runCli({"sweep", minimal(), "--seconds", "nan", "--out", out}), "--seconds");
  expectOneLineError(runCli({"sweep", minimal()}), "--out");
  expectOneLineError(runCli({"sweep", minimal(), "--out", "/no/such/dir/s.csv"}), "--out");
}

}  // namespace
}  // namespace asperity
