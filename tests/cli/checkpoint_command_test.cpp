// `asperity run --save-state / --load-state / --checkpoint-every`: a run continued from its
// checkpoint ends with the hash and the trajectory of one uninterrupted run, for the cpu,
// constant and gl samplers and on another thread count; a run killed while it writes leaves a
// trajectory of whole rows and a checkpoint it continues from; bad files are one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;
using test::slurpBinary;

std::string scene(const std::string& name) {
  return test::sourcePath("scenes/" + name + ".json");
}

std::string run(const std::vector<std::string>& args) {
  const auto r = runCli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

// The uninterrupted hash of 0.4 s against 0.2 s saved on one thread and 0.2 s loaded on two.
void expectContinues(const std::string& name, const std::string& sampler) {
  SCOPED_TRACE(name + " with " + sampler);
  const std::string state = test::tempDir("state") + "/s.state";
  const std::string whole =
      run({"run", scene(name), "--sampler", sampler, "--seconds", "0.4", "--hash"});
  run({"run", scene(name), "--sampler", sampler, "--seconds", "0.2", "--save-state", state});
  EXPECT_EQ(run({"run", scene(name), "--sampler", sampler, "--seconds", "0.2", "--load-state",
                 state, "--threads", "2", "--hash"}),
            whole);
}

TEST(CheckpointCommand, ContinuedRunsEndWithTheUninterruptedHash) {
  for (const char* sampler : {"cpu", "constant"}) {
    expectContinues("stacking", sampler);
    expectContinues("sawtooth_plane", sampler);
  }
}

// The OpenGL sampler (Mesa's llvmpipe without a GPU) when the tool has it.
TEST(CheckpointCommand, ContinuedRunsEndWithTheUninterruptedHashOnTheGlSampler) {
  const auto probe = runCli({"run", scene("stacking"), "--sampler", "gl", "--steps", "1"});
  if (probe.exit_code != 0) GTEST_SKIP() << "no gl sampler: " << probe.err;
  expectContinues("stacking", "gl");
}

// The trajectory of a continued run is the rest of the uninterrupted one's, row for row.
TEST(CheckpointCommand, TheContinuedTrajectoryIsTheRestOfTheWhole) {
  const std::string dir = test::tempDir("state");
  run({"run", scene("boxes_on_materials"), "--seconds", "0.4", "--every", "5", "--out",
       dir + "/whole.csv"});
  run({"run", scene("boxes_on_materials"), "--seconds", "0.2", "--every", "5", "--save-state",
       dir + "/s.state", "--out", dir + "/first.csv"});
  run({"run", scene("boxes_on_materials"), "--seconds", "0.2", "--every", "5", "--load-state",
       dir + "/s.state", "--out", dir + "/second.csv"});
  const std::string whole = slurpBinary(dir + "/whole.csv");
  const std::string first = slurpBinary(dir + "/first.csv");
  std::string second = slurpBinary(dir + "/second.csv");
  // The second file starts with the header and the saved state's rows, the first's last ones.
  const size_t header = second.find('\n') + 1;
  const size_t rows = static_cast<size_t>(std::count(first.begin(), first.end(), '\n')) - 1;
  const size_t per_step = rows / (20 / 5 + 1);
  size_t cut = header;
  for (size_t k = 0; k < per_step; ++k) cut = second.find('\n', cut) + 1;
  EXPECT_EQ(first.substr(first.size() - (cut - header)), second.substr(header, cut - header));
  EXPECT_EQ(first + second.substr(cut), whole);
}

// Killed while running, a run leaves whole trajectory rows and its last periodic checkpoint;
// continued from that checkpoint it ends as one uninterrupted run does.
TEST(CheckpointCommand, AKilledRunContinuesFromItsLastCheckpoint) {
  const std::string dir = test::tempDir("state");
  const std::string state = dir + "/s.state", csv = dir + "/t.csv";
  const std::string total = "60";  // s: far longer than the test waits
  EXPECT_TRUE(test::killWhen({"run", scene("stacking"), "--seconds", total, "--save-state", state,
                              "--checkpoint-every", "0.1", "--out", csv},
                             [&] { return std::filesystem::exists(state); },
                             std::chrono::milliseconds(100)));
  // The kill may land while a checkpoint is written: then s.state.tmp is left beside it, and
  // s.state is still the last complete one (loaded below).
  const std::string rows = slurpBinary(csv);
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.back(), '\n');
  std::stringstream lines(rows);
  for (std::string line; std::getline(lines, line);)
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 15) << line;
  // Where the checkpoint stands: the first step of a continued trajectory.
  const std::string probe = dir + "/probe.csv";
  run({"run", scene("stacking"), "--steps", "0", "--load-state", state, "--out", probe});
  const std::string first_row = slurpBinary(probe).substr(slurpBinary(probe).find('\n') + 1);
  const long saved = std::stol(first_row.substr(0, first_row.find(',')));
  ASSERT_GT(saved, 0);
  ASSERT_EQ(saved % 10, 0);  // every 0.1 s of dt 0.01
  const long steps = saved + 20;
  EXPECT_EQ(run({"run", scene("stacking"), "--steps", std::to_string(steps - saved),
                 "--load-state", state, "--hash"}),
            run({"run", scene("stacking"), "--steps", std::to_string(steps), "--hash"}));
}

TEST(CheckpointCommand, BadStateFilesAreOneLineErrors) {
  const std::string dir = test::tempDir("state");
  const std::string state = dir + "/s.state";
  run({"run", scene("stacking"), "--steps", "5", "--save-state", state});
  expectOneLineError(runCli({"run", scene("sawtooth_plane"), "--load-state", state}),
                     state + ": saved from another scene");
  expectOneLineError(runCli({"run", scene("stacking"), "--sampler", "constant", "--load-state",
                             state}),
                     "saved with friction provider");
  const std::string bytes = slurpBinary(state);
  std::ofstream(dir + "/cut.state", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expectOneLineError(runCli({"run", scene("stacking"), "--load-state", dir + "/cut.state"}),
                     "cut.state: truncated");
  expectOneLineError(runCli({"run", scene("stacking"), "--load-state", scene("stacking")}),
                     "not an Asperity state file");
  expectOneLineError(runCli({"run", scene("stacking"), "--load-state", dir + "/none.state"}),
                     "--load-state");
  expectOneLineError(runCli({"run", scene("stacking"), "--steps", "2", "--save-state",
                             "/dev/full"}),
                     "--save-state /dev/full: write failed");
  expectOneLineError(runCli({"run", scene("stacking"), "--checkpoint-every", "0.1"}),
                     "--checkpoint-every requires --save-state");
  expectOneLineError(runCli({"run", scene("stacking"), "--steps", "2", "--save-state",
                             dir + "/no/dir/s.state"}),
                     "cannot open for writing");
}

// The trajectory on a full disk is still the one-line error of before.
TEST(CheckpointCommand, AFullDiskIsOneLineErrorForTheTrajectoryAndStats) {
  expectOneLineError(runCli({"run", scene("stacking"), "--steps", "2", "--out", "/dev/full"}),
                     "--out /dev/full: write failed");
  expectOneLineError(runCli({"run", scene("stacking"), "--steps", "2", "--stats", "/dev/full"}),
                     "--stats /dev/full: write failed");
}

}  // namespace
}  // namespace asperity
