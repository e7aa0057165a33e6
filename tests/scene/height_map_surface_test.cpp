// A surface's "height_map" and "height_scale" (SPEC 13): the heights' normals at the surface's
// texture_size are the generator's own, the keys save back as written, and mistakes are named.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// A scene of one static box whose surface is `surface`, written beside `dir`'s files.
std::string sceneWith(const std::string& dir, const nlohmann::json& surface) {
  const nlohmann::json scene = {
      {"bodies",
       {{{"name", "plate"},
         {"type", "static"},
         {"shapes", {{{"type", "box"}, {"half_extents", {0.5, 0.5, 0.05}}, {"surface", surface}}}}}}}};
  const std::string path = dir + "/scene.json";
  std::ofstream(path) << scene.dump();
  return path;
}

GeneratorSpec stone() {
  GeneratorSpec spec;
  spec.name = "stone";
  spec.size = 64;
  spec.seed = 3;
  return spec;
}

TEST(HeightMapSurface, NormalsAreTheGeneratorsAtTheSurfacesTextureSize) {
  const std::string dir = test::tempDir("height_surface");
  const double scale = saveHeightMapPng(generateHeightMap(stone(), 0.08), dir + "/h.png");
  // With the stored scale, and with it given explicitly.
  for (const nlohmann::json& surface :
       {nlohmann::json{{"height_map", "h.png"}, {"texture_size", 0.08}},
        nlohmann::json{{"height_map", "h.png"}, {"height_scale", scale}, {"texture_size", 0.08}}}) {
    const std::unique_ptr<World> world = instantiate(loadScene(sceneWith(dir, surface)));
    const Surface& s = world->body(world->findBody("plate")).shapes.at(0).surface;
    ASSERT_TRUE(s.normal_map);
    const NormalMap expected = generateNormalMap(stone());
    float worst = 0.0f;
    for (size_t k = 0; k < expected.texels().size(); ++k)
      worst = std::max(worst, (s.normal_map->texels()[k] - expected.texels()[k]).cwiseAbs().maxCoeff());
    EXPECT_LT(worst, scale / 65535.0 / (0.08 / 64) + 1e-5);
  }
}

TEST(HeightMapSurface, SavesBackAsWritten) {
  const std::string dir = test::tempDir("height_surface");
  saveHeightMapPng(generateHeightMap(stone(), 0.08), dir + "/h.png");
  const SceneDesc scene = loadScene(
      sceneWith(dir, {{"height_map", "h.png"}, {"height_scale", 0.002}, {"texture_size", 0.08}}));
  const nlohmann::json surface = sceneToJson(scene)["bodies"][0]["shapes"][0]["surface"];
  EXPECT_EQ(surface["height_map"], "h.png");
  EXPECT_DOUBLE_EQ(surface["height_scale"].get<double>(), 0.002);
  EXPECT_DOUBLE_EQ(surface["texture_size"].get<double>(), 0.08);
  EXPECT_FALSE(surface.contains("normal_map"));
}

TEST(HeightMapSurface, MistakesAreNamed) {
  const std::string dir = test::tempDir("height_surface");
  saveHeightMapPng(generateHeightMap(stone(), 0.08), dir + "/h.png");
  const auto message = [&](const nlohmann::json& surface) {
    try {
      instantiate(loadScene(sceneWith(dir, surface)));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{"height_map", "h.png"}, {"normal_map", "h.png"}}).find("not both"),
            std::string::npos);
  EXPECT_NE(message({{"height_scale", 0.1}}).find("height_scale"), std::string::npos);
  EXPECT_NE(message({{"height_map", "missing.png"}}).find("missing.png"), std::string::npos);
  EXPECT_NE(message({{"height_map", "h.png"}, {"height_scale", -1}}).find("height_scale"),
            std::string::npos);
}

}  // namespace
}  // namespace asperity

namespace asperity {
namespace {

TEST(HeightMapSurface, AGltfAssetTakesTheHeightMapItsSurfaceNames) {
  // The height map named beside a glTF asset replaces the asset's own normal map.
  const std::string dir = test::tempDir("height_surface");
  saveHeightMapPng(generateHeightMap(stone(), 0.08), dir + "/h.png");
  const nlohmann::json scene = {
      {"bodies",
       {{{"name", "plate"},
         {"type", "static"},
         {"shapes",
          {{{"type", "mesh"},
            {"file", test::sourcePath("tests/fixtures/assets/plate.gltf")},
            {"surface", {{"height_map", "h.png"}, {"texture_size", 0.08}}}}}}}}}};
  std::ofstream(dir + "/asset.json") << scene.dump();
  const std::unique_ptr<World> world = instantiate(loadScene(dir + "/asset.json"));
  const Surface& s = world->body(world->findBody("plate")).shapes.at(0).surface;
  ASSERT_TRUE(s.normal_map);
  EXPECT_EQ(s.normal_map->texels(), normalsFromHeightMap(loadHeightMapPng(dir + "/h.png"), 0.08).texels());
}

}  // namespace
}  // namespace asperity
