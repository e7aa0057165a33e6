// Surfaces files: names to surfaces read as a scene's, paths beside the file, and errors that
// name the file, the entry and the missing texture.
#include "asperity/engines/surfaces_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/test_support.hpp"

namespace asperity {
namespace {

// Writes `text` to dir/name and returns its path.
std::string writeFile(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(SurfacesFile, ReadsEachNamesSurfaceAsAScenesAndResolvesIt) {
  const std::string dir = test::tempDir("surfaces_file");
  const std::string path = writeFile(dir, "surfaces.json", R"({"surfaces": {
    "ground": {"normal_map": {"generator": "sawtooth", "params": {"period": 16}, "size": 64},
               "gain": 4, "texture_size": 0.08},
    "box": {"gain": 1}}})");
  const SurfacesFile file = loadSurfacesFile(path);
  EXPECT_EQ(file.path, path);
  ASSERT_EQ(file.surfaces.size(), 2u);
  const Surface& ground = file.surfaces.at("ground");
  ASSERT_TRUE(ground.normal_map);
  EXPECT_EQ(ground.normal_map->width(), 64);
  EXPECT_EQ(ground.gain, 4.0);
  EXPECT_EQ(ground.texture_size, 0.08);
  EXPECT_FALSE(file.surfaces.at("box").normal_map);  // flat
}

TEST(SurfacesFile, AMissingTextureNamesItsPath) {
  const std::string dir = test::tempDir("surfaces_file");
  const std::string path =
      writeFile(dir, "surfaces.json", R"({"surfaces": {"crate": {"normal_map": "oak.png"}}})");
  const std::string error = test::errorOf([&] { loadSurfacesFile(path); });
  EXPECT_NE(error.find(path + ": /surfaces/crate/normal_map"), std::string::npos) << error;
  EXPECT_NE(error.find(dir + "/oak.png"), std::string::npos) << error;
}

TEST(SurfacesFile, BadEntriesAreErrorsNamingTheFileAndPointer) {
  const std::string dir = test::tempDir("surfaces_file");
  const std::string path =
      writeFile(dir, "surfaces.json", R"({"surfaces": {"box": {"gain": -1}}, "extra": 1})");
  EXPECT_NE(test::errorOf([&] { loadSurfacesFile(path); }).find(path + ": /surfaces/box/gain"),
            std::string::npos);
  const std::string extra = writeFile(dir, "extra.json", R"({"surfaces": {}, "extra": 1})");
  EXPECT_NE(test::errorOf([&] { loadSurfacesFile(extra); }).find("/extra: unknown key"),
            std::string::npos);
  EXPECT_NE(test::errorOf([&] { loadSurfacesFile(dir + "/none.json"); }).find("none.json"),
            std::string::npos);
}

TEST(SurfacesFile, AnUnknownObjectsErrorNamesTheNameAndTheFile) {
  SurfacesFile file;
  file.path = "robot/surfaces.json";
  const std::string error = unknownObjectError(file, "gripper", {"base", "arm"}).what();
  EXPECT_EQ(error,
            "robot/surfaces.json: /surfaces/gripper: unknown object \"gripper\" (\"base\", "
            "\"arm\")");
}

}  // namespace
}  // namespace asperity
