// Replays every fuzz seed and every input a fuzzer once failed on (tests/fuzz/regressions/)
// through the fuzz targets' own entry points, in the normal and the sanitizer builds. Each
// input must come back (a crash or sanitizer report ends the test program).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/test_support.hpp"

// The targets' LLVMFuzzerTestOneInput, renamed per file by tests/CMakeLists.txt.
extern "C" int fuzzScene(const uint8_t* data, size_t size);
extern "C" int fuzzPng(const uint8_t* data, size_t size);
extern "C" int fuzzObj(const uint8_t* data, size_t size);
extern "C" int fuzzGenerators(const uint8_t* data, size_t size);
extern "C" int fuzzAsset(const uint8_t* data, size_t size);
extern "C" int fuzzCli(const uint8_t* data, size_t size);
extern "C" int fuzzState(const uint8_t* data, size_t size);

namespace asperity {
namespace {

using Target = int (*)(const uint8_t*, size_t);

// Every file under tests/fuzz/{corpus,regressions}/<target>/, sorted.
std::vector<std::filesystem::path> inputsOf(const std::string& target) {
  std::vector<std::filesystem::path> out;
  for (const char* folder : {"corpus", "regressions"}) {
    const std::filesystem::path dir =
        test::sourcePath("tests/fuzz/" + std::string(folder) + "/" + target);
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Feeds each input to the target; returns how many were replayed.
size_t replay(const std::string& target, Target run) {
  const auto inputs = inputsOf(target);
  for (const auto& path : inputs) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
    SCOPED_TRACE(path.string());
    EXPECT_EQ(run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), 0);
  }
  return inputs.size();
}

TEST(FuzzReplay, SceneInputs) {
  EXPECT_GT(replay("scene", fuzzScene), 0u);
}
TEST(FuzzReplay, PngInputs) {
  EXPECT_GT(replay("png", fuzzPng), 0u);
}
TEST(FuzzReplay, ObjInputs) {
  EXPECT_GT(replay("obj", fuzzObj), 0u);
}
TEST(FuzzReplay, GeneratorInputs) {
  EXPECT_GT(replay("generators", fuzzGenerators), 0u);
}
TEST(FuzzReplay, AssetInputs) {
  EXPECT_GT(replay("asset", fuzzAsset), 0u);
}
TEST(FuzzReplay, CliInputs) {
  EXPECT_GT(replay("cli", fuzzCli), 0u);
}
TEST(FuzzReplay, StateInputs) {
  EXPECT_GT(replay("state", fuzzState), 0u);
}

}  // namespace
}  // namespace asperity
