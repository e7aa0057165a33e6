// The viewer under Xvfb: a few frames of a scene, then a screenshot that is not blank.
#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/test_support.hpp"

namespace asperity {
namespace {

namespace fs = std::filesystem;

// Runs a shell command line; returns its exit status.
int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

TEST(Viewer, RendersFramesUnderXvfbAndTakesAScreenshot) {
  // Xvfb is part of the dependencies (scripts/install-deps.sh): its absence is a failure.
  ASSERT_EQ(shell("command -v xvfb-run >/dev/null"), 0) << "xvfb-run is missing (package xvfb)";
  const std::string dir = test::tempDir("viewer");
  const std::string shot = dir + "/shot.png";
  // Under LeakSanitizer (make sanitize) the GLX driver, unloaded when the window closes, leaves
  // allocations whose stacks name no module and so cannot be suppressed by name; leak checking
  // is off for this one process (the renderer's own tests check it through EGL).
  const std::string command = "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" "
                              "xvfb-run -a -s '-screen 0 640x480x24' '" +
                              std::string(ASPERITY_BIN_DIR) + "/asperity-viewer' '" +
                              test::sourcePath("scenes/examples/minimal.json") +
                              "' --width 320 --height 240 --frames 5 --screenshot '" + shot +
                              "' >" + dir + "/out 2>" + dir + "/err";
  ASSERT_EQ(shell(command), 0) << "viewer failed; see " << dir << "/err";
  // A lit scene with panels: many distinct grey levels, not one flat colour.
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr) << shot;
  EXPECT_EQ(w, 320);
  EXPECT_EQ(h, 240);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < w * h; ++i) {
    const double y = 0.3 * pixels[3 * i] + 0.59 * pixels[3 * i + 1] + 0.11 * pixels[3 * i + 2];
    sum += y;
    sum2 += y * y;
  }
  stbi_image_free(pixels);
  const double mean = sum / (w * h);
  EXPECT_GT(std::sqrt(sum2 / (w * h) - mean * mean), 10.0);
}

TEST(Viewer, MissingSceneIsAOneLineError) {
  ASSERT_EQ(shell("command -v xvfb-run >/dev/null"), 0) << "xvfb-run is missing (package xvfb)";
  const std::string dir = test::tempDir("viewer");
  // The viewer's stderr alone: xvfb-run may add its own line on the same stream ("problem
  // while cleaning up temporary directory" when parallel tests share /tmp).
  const std::string command = "xvfb-run -a sh -c \"exec '" + std::string(ASPERITY_BIN_DIR) +
                              "/asperity-viewer' /nonexistent.json --frames 1 2>'" + dir +
                              "/err'\" >" + dir + "/out 2>" + dir + "/xvfb_err";
  EXPECT_NE(shell(command), 0);
  // One line on stderr, naming the program and the missing file.
  std::ifstream err(dir + "/err");
  const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.rfind("asperity-viewer: error: ", 0), 0u) << text;
  EXPECT_NE(text.find("/nonexistent.json"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

}  // namespace
}  // namespace asperity
