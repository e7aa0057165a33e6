// `asperity sweep`: the same bytes on 1 and 2 threads, one row per sample whose hash equals
// `asperity run --hash` of the varied scene, and one test per bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

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

using test::lineCount;

// `asperity ARGS` killed with SIGKILL once `path` has `lines` lines.
void killWhenWritten(const std::vector<std::string>& args, const std::string& path, long lines) {
  test::killWhen(args, [&] { return lineCount(path) >= lines; });
}

TEST(SweepCommand, AKilledSweepKeepsItsRowsAndResumesToTheBytesOfOneRun) {
  const std::string dir = test::tempDir("sweep_kill");
  auto args = [&](const std::string& out, const std::string& threads) {
    return std::vector<std::string>{
        "sweep",     minimal(), "--vary",    "/bodies/*/linear_velocity/0=uniform(0.5,1.5)",
        "--samples", "60",      "--seconds", "0.5",
        "--seed",    "2",       "--threads", threads,
        "--out",     out};
  };
  ASSERT_EQ(runCli(args(dir + "/whole.csv", "2")).exit_code, 0);
  const std::string whole = slurpBinary(dir + "/whole.csv");
  // Killed at several moments, on one and two threads.
  for (const long lines : {2L, 9L, 31L}) {
    for (const std::string threads : {"1", "2"}) {
      const std::string out = dir + "/killed.csv";
      std::filesystem::remove(out);
      killWhenWritten(args(out, threads), out, lines);
      // What the kill left: whole rows only, the first ones of the uninterrupted table.
      const std::string left = slurpBinary(out);
      ASSERT_FALSE(left.empty());
      EXPECT_LT(left.size(), whole.size()) << "killed after the sweep ended";
      EXPECT_TRUE(std::filesystem::exists(out + ".sweep"));
      EXPECT_EQ(left.back(), '\n');
      EXPECT_EQ(whole.compare(0, left.size(), left), 0) << lines << " lines, " << threads;
      auto resume = args(out, threads == "1" ? "2" : "1");
      resume.push_back("--resume");
      const auto r = runCli(resume);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(slurpBinary(out), whole) << lines << " lines, " << threads;
    }
  }
}

// Killed at random moments (after the header, up to past the end): the file is always valid
// CSV (the header's column count on every line, each line ended) and a prefix of the
// uninterrupted table, and a resume always gives that table's bytes.
TEST(SweepCommand, KilledAtRandomMomentsTheFileIsValidAndResumes) {
  const std::string dir = test::tempDir("sweep_random_kill");
  auto args = [&](const std::string& out, const std::string& threads) {
    return std::vector<std::string>{
        "sweep",     minimal(), "--vary",    "/bodies/*/linear_velocity/0=uniform(0.5,1.5)",
        "--samples", "40",      "--seconds", "0.5",
        "--seed",    "9",       "--threads", threads,
        "--out",     out};
  };
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(runCli(args(dir + "/whole.csv", "2")).exit_code, 0);
  const auto run_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                          std::chrono::steady_clock::now() - start)
                          .count();
  const std::string whole = slurpBinary(dir + "/whole.csv");
  const std::string header = whole.substr(0, whole.find('\n') + 1);
  const auto columns = std::count(header.begin(), header.end(), ',');
  const unsigned seed = std::random_device{}();
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 random(seed);
  std::uniform_int_distribution<long> delay_ms(0, std::max<long>(1, run_ms));
  for (int trial = 0; trial < 6; ++trial) {
    const std::string threads = trial % 2 == 0 ? "1" : "2";
    const std::string out = dir + "/killed.csv";
    std::filesystem::remove(out);
    std::filesystem::remove(out + ".sweep");
    const long delay = delay_ms(random);
    SCOPED_TRACE("killed " + std::to_string(delay) + " ms after the header, " + threads);
    test::killWhen(
        args(out, threads), [&] { return lineCount(out) >= 1; }, std::chrono::milliseconds(delay));
    const std::string left = slurpBinary(out);
    ASSERT_FALSE(left.empty());
    EXPECT_EQ(left.back(), '\n');
    std::stringstream lines(left);
    for (std::string line; std::getline(lines, line);)
      EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << line;
    EXPECT_EQ(whole.compare(0, left.size(), left), 0);
    auto resume = args(out, threads == "1" ? "2" : "1");
    resume.push_back("--resume");
    const auto r = runCli(resume);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurpBinary(out), whole);
  }
}

// A finished file keeps its journal: resumed with the same arguments there is nothing to do,
// with another seed the resume is refused naming the field.
TEST(SweepCommand, AResumeOfAFinishedFileSaysSoOrIsRefused) {
  const std::string out = test::tempDir("sweep_finished") + "/s.csv";
  const std::vector<std::string> args = {
      "sweep",     minimal(), "--vary",    "/bodies/*/linear_velocity/0=uniform(0.5,1.5)",
      "--samples", "4",       "--seconds", "0.1",
      "--out",     out};
  ASSERT_EQ(runCli(args).exit_code, 0);
  const std::string whole = slurpBinary(out);
  auto again = args;
  again.push_back("--resume");
  const auto same = runCli(again);
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.err.find("already holds all 4 samples: nothing to do"), std::string::npos)
      << same.err;
  again.insert(again.end(), {"--seed", "5"});
  test::expectOneLineError(runCli(again), "seed differs");
  EXPECT_EQ(slurpBinary(out), whole);
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
  expectOneLineError(runCli({"sweep", minimal(), "--out", "/dev/full"}),
                     "--out /dev/full: write failed");
  // A resume with other arguments than the killed sweep's names the journal and the field.
  const std::string dir = test::tempDir("sweep_resume_bad");
  ASSERT_EQ(runCli(sweepArgs(dir + "/s.csv", "1")).exit_code, 0);
  expectOneLineError(runCli({"sweep", minimal(), "--out", dir + "/none.csv", "--resume"}),
                     "does not exist");
}

}  // namespace
}  // namespace asperity
