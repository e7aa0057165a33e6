// The one helper behind every output (asperity/math/atomic_file.hpp): whole files appear only
// complete under their names, an error leaves the old file and no temporary, devices are
// written in place with a one-line error, and record files append whole records.
#include "asperity/math/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(AtomicFile, WritesTheWholeFileAndLeavesNoTemporary) {
  const std::string path = test::tempDir("atomic") + "/out.json";
  std::ofstream(path) << "old";
  const std::string text(1 << 20, 'x');
  writeFileAtomically(path, text);
  EXPECT_EQ(slurp(path), text);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(AtomicFile, AFailureNamesThePathAndKeepsTheOldFile) {
  EXPECT_EQ(errorOf([] { writeFileAtomically("/dev/full", "data"); }),
            "/dev/full: write failed: No space left on device");
  const std::string dir = test::tempDir("atomic");
  EXPECT_EQ(errorOf([&] { writeFileAtomically(dir + "/none/x", "data"); }),
            dir + "/none/x: cannot open for writing: No such file or directory");
  // A directory in the way of the rename: the file's old content (none) and no temporary.
  std::filesystem::create_directory(dir + "/taken");
  std::ofstream(dir + "/taken/f") << "keep";
  EXPECT_NE(errorOf([&] { writeFileAtomically(dir + "/taken", "data"); }), "");
  EXPECT_EQ(slurp(dir + "/taken/f"), "keep");
  EXPECT_FALSE(std::filesystem::exists(dir + "/taken.tmp"));
}

TEST(AtomicFile, AnOutputNotCommittedLeavesTheFinalNameAlone) {
  const std::string path = test::tempDir("atomic") + "/frame.png";
  std::ofstream(path) << "previous";
  {
    AtomicOutput out(path);
    EXPECT_EQ(out.temporaryPath(), path + ".tmp");
    std::ofstream(out.temporaryPath()) << "half a fr";
  }
  EXPECT_EQ(slurp(path), "previous");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  {
    AtomicOutput out(path);
    std::ofstream(out.temporaryPath()) << "whole frame";
    out.commit();
  }
  EXPECT_EQ(slurp(path), "whole frame");
}

TEST(AtomicFile, DevicesAreWrittenInPlace) {
  AtomicOutput out("/dev/null");
  EXPECT_EQ(out.temporaryPath(), "/dev/null");
  out.commit();
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  writeFileAtomically("/dev/null", "nothing");
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

TEST(RecordFile, AppendsWholeRecordsAndKeepsOnRequest) {
  const std::string path = test::tempDir("records") + "/t.csv";
  {
    RecordFile file(path);
    file.append("a,b\n");
    EXPECT_EQ(slurp(path), "a,b\n");  // in the file at once, not in a buffer
    file.append("1,2\n3,4\n");
    file.sync();
    EXPECT_TRUE(file.regular());
  }
  {
    RecordFile file(path, "", true);
    file.append("5,6\n");
  }
  EXPECT_EQ(slurp(path), "a,b\n1,2\n3,4\n5,6\n");
  RecordFile truncated(path);
  EXPECT_EQ(slurp(path), "");
  EXPECT_EQ(errorOf([] {
              RecordFile full("/dev/full", "--out /dev/full");
              full.append("x\n");
            }),
            "--out /dev/full: write failed: No space left on device");
}

// One rule for links: an output replaces the link it is given, whole files and growing ones
// alike, and never writes into the file the link names; a planted temporary link is replaced
// too. Continuing a file through a link is refused; a link to a device is written in place.
TEST(RecordFile, OutputsReplaceALinkAndNeverWriteThroughIt) {
  const std::string dir = test::tempDir("links");
  const std::string victim = dir + "/victim.txt";
  std::ofstream(victim) << "keep me\n";
  const auto linked = [&](const std::string& name) {
    const std::string path = dir + "/" + name;
    std::filesystem::remove(path);
    std::filesystem::create_symlink(victim, path);
    return path;
  };
  {
    const std::string out = linked("run.csv");
    RecordFile file(out);
    file.append("1,2\n");
    EXPECT_FALSE(std::filesystem::is_symlink(out));
    EXPECT_EQ(slurp(out), "1,2\n");
  }
  const std::string whole = linked("scene.json");
  writeFileAtomically(whole, "{}\n");
  EXPECT_FALSE(std::filesystem::is_symlink(whole));
  const std::string planted = dir + "/state.bin";
  linked("state.bin.tmp");
  writeFileAtomically(planted, "bytes");
  EXPECT_EQ(slurp(planted), "bytes");
  EXPECT_EQ(slurp(victim), "keep me\n");
  const std::string resumed = linked("resume.csv");
  EXPECT_EQ(errorOf([&] { RecordFile file(resumed, "", true); }),
            resumed + ": is a symbolic link; a file is continued only under its own name");
  const std::string to_device = dir + "/null";
  std::filesystem::create_symlink("/dev/null", to_device);
  RecordFile device(to_device);
  device.append("x\n");
  EXPECT_TRUE(std::filesystem::is_symlink(to_device));
  EXPECT_EQ(slurp(victim), "keep me\n");
}

}  // namespace
}  // namespace asperity
