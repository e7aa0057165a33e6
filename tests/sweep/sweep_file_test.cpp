// Sweeps written to their file as they run: rows in order as samples finish, a file cut at any
// byte (as a killed process leaves it) resumed to the bytes of an uninterrupted run on any
// thread count, and resumes that would mix two sweeps refused.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/sweep/sweep.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

SweepDesc boxes(uint64_t seed = 3) {
  SweepDesc d;
  d.scene_json = R"({
    "settings": {"friction_provider": "constant", "mu0": 0.4, "dt": 0.01},
    "bodies": [
      {"name": "ground", "type": "static", "shapes": [{"type": "plane"}]},
      {"name": "box", "position": [0, 0, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]}]})";
  d.scene_file = "boxes.json";
  d.vary = {parseVariation("/bodies/*/linear_velocity/0=uniform(0.5,2)")};
  d.samples = 12;
  d.seed = seed;
  d.seconds = 0.2;
  d.measures = {"distance:box"};
  return d;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(SweepFile, RowsReachTheFileInOrderAsTheTableOfRunAll) {
  const Sweep sweep(boxes());
  const std::string path = test::tempDir("sweep_file") + "/rows.csv";
  std::vector<int64_t> order;
  sweep.runInOrder(2, 0, [&](const SampleResult& r) { order.push_back(r.index); });
  for (size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], static_cast<int64_t>(i));
  EXPECT_EQ(runSweepToFile(sweep, {path, 2, false}), 12);
  EXPECT_EQ(slurp(path), sweep.csv(sweep.runAll(1)));
  // The journal stays beside the finished file, and so does the lock's file.
  EXPECT_EQ(slurp(sweepJournalPath(path)), sweepJournal(sweep));
  EXPECT_TRUE(std::filesystem::exists(path + ".lock"));
}

TEST(SweepFile, AFileCutAnywhereResumesToTheBytesOfOneRun) {
  const Sweep sweep(boxes());
  const std::string dir = test::tempDir("sweep_cut");
  const std::string whole = dir + "/whole.csv";
  runSweepToFile(sweep, {whole, 1, false});
  const std::string expected = slurp(whole);
  // Cuts at row ends and inside rows (a killed run leaves whole rows; a torn last row is cut
  // away), each with the journal a running sweep keeps, resumed on 1 and 3 threads. The empty
  // file is a kill after the journal was written and before the header.
  const std::string killed = dir + "/killed.csv";
  std::vector<size_t> cuts = {0};
  for (size_t cut = sweep.csvHeader().size(); cut <= expected.size(); cut += 37)
    cuts.push_back(cut);
  for (const size_t cut : cuts) {
    for (const int threads : {1, 3}) {
      write(killed, expected.substr(0, cut));
      write(sweepJournalPath(killed), sweepJournal(sweep));
      runSweepToFile(sweep, {killed, threads, true});
      EXPECT_EQ(slurp(killed), expected) << "cut at " << cut << ", " << threads << " threads";
      EXPECT_EQ(slurp(sweepJournalPath(killed)), sweepJournal(sweep));
    }
  }
  // A finished file resumes to itself: nothing runs.
  EXPECT_EQ(runSweepToFile(sweep, {killed, 2, true}), 0);
  EXPECT_EQ(slurp(killed), expected);
}

TEST(SweepFile, ResumesThatWouldMixTwoSweepsAreRefused) {
  const Sweep sweep(boxes());
  const std::string dir = test::tempDir("sweep_refused");
  const std::string path = dir + "/s.csv";
  runSweepToFile(sweep, {path, 1, false});
  const std::string half = slurp(path).substr(0, slurp(path).size() / 2);
  // Another seed's journal: named, with the field that differs.
  write(path, half);
  write(sweepJournalPath(path), sweepJournal(Sweep(boxes(4))));
  const std::string seed = test::errorOf([&] { runSweepToFile(sweep, {path, 1, true}); });
  EXPECT_NE(seed.find(sweepJournalPath(path)), std::string::npos) << seed;
  EXPECT_NE(seed.find("seed"), std::string::npos) << seed;
  // No journal and an unfinished file; no file at all; another table's header.
  std::filesystem::remove(sweepJournalPath(path));
  EXPECT_NE(test::errorOf([&] {
              runSweepToFile(sweep, {path, 1, true});
            }).find("journal"),
            std::string::npos);
  EXPECT_NE(test::errorOf([&] {
              runSweepToFile(sweep, {dir + "/none.csv", 1, true});
            }).find("does not exist"),
            std::string::npos);
  write(path, "sample,x\n0,1\n");
  write(sweepJournalPath(path), sweepJournal(sweep));
  EXPECT_NE(test::errorOf([&] {
              runSweepToFile(sweep, {path, 1, true});
            }).find("header"),
            std::string::npos);
  // A folder that does not exist.
  EXPECT_NE(test::errorOf([&] {
              runSweepToFile(sweep, {dir + "/no/s.csv", 1, false});
            }).find("cannot open"),
            std::string::npos);
}

// One process at a time: a sweep whose file another holds is refused, naming the holder.
TEST(SweepFile, ASecondWriterIsRefusedNamingTheHolder) {
  const Sweep sweep(boxes());
  const std::string path = test::tempDir("sweep_lock") + "/s.csv";
  const int held = ::open((path + ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX | LOCK_NB), 0);
  ASSERT_EQ(::pwrite(held, "4242", 4, 0), 4);
  for (const bool resume : {false, true}) {
    const std::string error = test::errorOf([&] { runSweepToFile(sweep, {path, 1, resume}); });
    EXPECT_NE(error.find("another sweep is writing it (process 4242 holds " + path + ".lock)"),
              std::string::npos)
        << error;
  }
  ::close(held);  // released: the sweep runs
  EXPECT_EQ(runSweepToFile(sweep, {path, 1, false}), 12);
}

// A finished file keeps its journal: a resume with other arguments is refused naming the
// field, one with the same arguments runs nothing; a changed row is refused naming its line.
TEST(SweepFile, AFinishedOrTamperedFileIsCheckedOnResume) {
  const Sweep sweep(boxes());
  const std::string path = test::tempDir("sweep_done") + "/s.csv";
  runSweepToFile(sweep, {path, 1, false});
  const std::string whole = slurp(path);
  const std::string other = test::errorOf([&] {
    runSweepToFile(Sweep(boxes(4)), {path, 1, true});
  });
  EXPECT_NE(other.find("seed differs"), std::string::npos) << other;
  EXPECT_EQ(runSweepToFile(sweep, {path, 1, true}), 0);
  EXPECT_EQ(slurp(path), whole);
  // Row 4 (line 6) replaced by five fields, some not numbers.
  std::string tampered = whole;
  const size_t start = tampered.find("\n4,") + 1;
  tampered.replace(start, tampered.find('\n', start) - start, "4,nan,inf,-1e999,garbage");
  write(path, tampered);
  const std::string error = test::errorOf([&] { runSweepToFile(sweep, {path, 1, true}); });
  EXPECT_NE(error.find("line 6 (sample 4) is not"), std::string::npos) << error;
  EXPECT_EQ(slurp(path), tampered);  // refused before anything is cut or written
}

// A resume through a symbolic link would cut the file the link names: refused, that file kept.
TEST(SweepFile, AResumeThroughALinkIsRefused) {
  const Sweep sweep(boxes());
  const std::string dir = test::tempDir("sweep_link");
  runSweepToFile(sweep, {dir + "/real.csv", 1, false});
  const std::string half = slurp(dir + "/real.csv").substr(0, 300);
  write(dir + "/real.csv", half);
  std::filesystem::create_symlink(dir + "/real.csv", dir + "/link.csv");
  write(sweepJournalPath(dir + "/link.csv"), sweepJournal(sweep));
  EXPECT_NE(test::errorOf([&] {
              runSweepToFile(sweep, {dir + "/link.csv", 1, true});
            }).find("is a symbolic link"),
            std::string::npos);
  EXPECT_EQ(slurp(dir + "/real.csv"), half);
}

TEST(SweepFile, AFullDiskIsAnErrorNamingTheFile) {
  const Sweep sweep(boxes());
  const std::string message = test::errorOf([&] {
    runSweepToFile(sweep, {"/dev/full", 1, false});
  });
  EXPECT_NE(message.find("/dev/full: write failed"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists("/dev/full.sweep"));
}

}  // namespace
}  // namespace asperity
