// `asperity render`: PNG frames, one PNG at a time, MP4 through ffmpeg, and one-line errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace asperity {
namespace {

namespace fs = std::filesystem;
using test::runCli;

const std::string kScene = test::sourcePath("scenes/examples/minimal.json");

// Every error is one line on stderr and a non-zero exit.
void expectOneLineError(const test::CommandResult& r, const std::string& fragment) {
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(RenderCommand, OnePngAtAGivenTime) {
  const std::string out = test::tempDir("png") + "/frame.png";
  const auto r = runCli({"render", kScene, "--frame-at", "0.05", "--size", "96x64", "--layers",
                         "contacts,frames", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(fs::file_size(out), 200u);
}

TEST(RenderCommand, PngFramesIntoAFolderAtTheRequestedRate) {
  const std::string dir = test::tempDir("frames") + "/out/";
  const auto r = runCli(
      {"render", kScene, "--seconds", "0.2", "--fps", "10", "--size", "64x48", "--out", dir});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // t = 0, 0.1, 0.2: three frames.
  EXPECT_TRUE(fs::exists(dir + "frame_00000.png"));
  EXPECT_TRUE(fs::exists(dir + "frame_00002.png"));
  EXPECT_FALSE(fs::exists(dir + "frame_00003.png"));
}

TEST(RenderCommand, Mp4ThroughFfmpeg) {
  const std::string out = test::tempDir("mp4") + "/video.mp4";
  const auto r = runCli(
      {"render", kScene, "--seconds", "0.1", "--fps", "20", "--size", "65x49", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(fs::file_size(out), 500u);
}

TEST(RenderCommand, BadSize) {
  for (const char* size : {"0x10", "64", "64x", "axb", "100000x64", "64x48x2"})
    expectOneLineError(runCli({"render", kScene, "--size", size, "--out", "x.mp4"}), "--size");
}

TEST(RenderCommand, BadFps) {
  expectOneLineError(runCli({"render", kScene, "--fps", "0", "--out", "x.mp4"}), "--fps");
  expectOneLineError(runCli({"render", kScene, "--fps", "-3", "--out", "x.mp4"}), "--fps");
}

TEST(RenderCommand, UnknownLayer) {
  expectOneLineError(runCli({"render", kScene, "--layers", "contacts,sparkles", "--out", "x.mp4"}),
                     "unknown layer 'sparkles'");
}

TEST(RenderCommand, UnwritableOutput) {
  expectOneLineError(runCli({"render", kScene, "--out", "/nonexistent-folder/x.mp4"}),
                     "cannot write '/nonexistent-folder/x.mp4'");
}

TEST(RenderCommand, OutputKindMustMatch) {
  expectOneLineError(runCli({"render", kScene, "--out", "x.avi"}), "--out");
  expectOneLineError(runCli({"render", kScene, "--frame-at", "0", "--out", "x.mp4"}), ".png");
}

TEST(RenderCommand, MissingFfmpegIsNamed) {
  const std::string out = test::tempDir("noffmpeg") + "/video.mp4";
  const std::string path = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  const auto r = runCli({"render", kScene, "--seconds", "0", "--out", out});
  setenv("PATH", path.c_str(), 1);
  expectOneLineError(r, "ffmpeg is not on PATH");
}

TEST(RenderCommand, UnknownSamplerAndMissingScene) {
  expectOneLineError(runCli({"render", kScene, "--sampler", "nope", "--frame-at", "0", "--out",
                             test::tempDir("s") + "/a.png"}),
                     "nope");
  expectOneLineError(runCli({"render", "/nonexistent.json", "--frame-at", "0", "--out",
                             test::tempDir("s") + "/a.png"}),
                     "/nonexistent.json");
}

}  // namespace
}  // namespace asperity
