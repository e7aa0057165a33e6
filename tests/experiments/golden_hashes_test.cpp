// Pinned determinism: every scene in scenes/ runs kGoldenSeconds and its World::stateHash()
// must equal the one recorded in tests/experiments/golden_hashes.txt for this compiler and
// build type. A change in results is then always noticed and made on purpose:
//
//   ASPERITY_UPDATE_GOLDEN=1 build/bin/asperity_experiments_tests --gtest_filter='GoldenHashes.*'
//
// rewrites the file (commit it with the change that explains the new results).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

constexpr double kGoldenSeconds = 0.5;
constexpr const char* kGoldenFile = "tests/experiments/golden_hashes.txt";
constexpr const char* kUpdateCommand =
    "ASPERITY_UPDATE_GOLDEN=1 build/bin/asperity_experiments_tests "
    "--gtest_filter='GoldenHashes.*'";

// The compiler and build type the hashes hold for (floating point differs between them).
std::string configuration() {
  return std::string(ASPERITY_COMPILER) + ", " + ASPERITY_BUILD_CONFIG;
}

// World::stateHash() of `scene` after kGoldenSeconds, as 16 hex digits.
std::string hashAfterRun(const std::string& scene) {
  const std::unique_ptr<World> world = instantiate(loadScene(test::sourcePath(scene)));
  const double dt = world->settings().dt;
  while (world->time() + 0.5 * dt < kGoldenSeconds) world->step();
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(world->stateHash()));
  return text;
}

// The golden file: its configuration line and scene -> hash.
struct Golden {
  std::string configuration;
  std::map<std::string, std::string> hashes;
};

Golden readGolden() {
  Golden golden;
  std::ifstream in(test::sourcePath(kGoldenFile));
  std::string line;
  while (std::getline(in, line)) {
    // "# configuration: GNU 12.2.0, Release" names what the hashes hold for; other # lines
    // are comments; the rest are "scene hash".
    const std::string tag = "# configuration: ";
    if (line.rfind(tag, 0) == 0) golden.configuration = line.substr(tag.size());
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string scene, hash;
    fields >> scene >> hash;
    golden.hashes[scene] = hash;
  }
  return golden;
}

void writeGolden(const std::map<std::string, std::string>& hashes) {
  std::ofstream out(test::sourcePath(kGoldenFile));
  out << "# World::stateHash() of each scene after " << kGoldenSeconds << " s simulated.\n"
      << "# Checked by tests/experiments/golden_hashes_test.cpp; to update after a deliberate\n"
      << "# change in results: " << kUpdateCommand << "\n"
      << "# configuration: " << configuration() << "\n";
  for (const auto& [scene, hash] : hashes) out << scene << " " << hash << "\n";
}

TEST(GoldenHashes, EverySceneMatchesItsPinnedHash) {
  // Run every scene first, so one update rewrites them all.
  std::map<std::string, std::string> now;
  for (const std::string& scene : test::experimentScenes()) now[scene] = hashAfterRun(scene);
  if (std::getenv("ASPERITY_UPDATE_GOLDEN") != nullptr) {
    writeGolden(now);
    GTEST_SKIP() << "rewrote " << kGoldenFile << " for " << configuration();
  }
  const Golden golden = readGolden();
  // Other compilers and build types round differently: their hashes are not pinned here.
  if (golden.configuration != configuration())
    GTEST_SKIP() << kGoldenFile << " holds hashes for " << golden.configuration << ", not for "
                 << configuration();
  for (const auto& [scene, hash] : now) {
    const auto it = golden.hashes.find(scene);
    const std::string pinned = it == golden.hashes.end() ? "(none)" : it->second;
    EXPECT_EQ(hash, pinned) << scene << ": results changed. If that is intended, run\n  "
                            << kUpdateCommand << "\nand commit " << kGoldenFile
                            << " saying why the results changed.";
  }
  EXPECT_EQ(golden.hashes.size(), now.size()) << kGoldenFile << " lists scenes that are gone; "
                                              << "run " << kUpdateCommand;
}

}  // namespace
}  // namespace asperity
