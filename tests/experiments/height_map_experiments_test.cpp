// The paper's experiments driven by height maps (SPEC 13): every generated normal map of a
// scene replaced by the generator's heights, written as a 16-bit PNG and named by the surface's
// "height_map" with its "height_scale"; the normals derived at the surface's texture_size then
// drive the paper's model as the normal maps did, and the outcomes hold.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "asperity/texture/generators.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "asperity/texture/height_map.hpp"
#include "experiments/experiment_outcomes.hpp"
#include "support/test_support.hpp"

namespace asperity::experiments {
namespace {

// A generator object of a scene ({"generator", "params", "size", "seed"}) as a spec.
GeneratorSpec specFrom(const nlohmann::json& g) {
  GeneratorSpec spec;
  spec.name = g.at("generator").get<std::string>();
  for (const auto& [key, value] : g.value("params", nlohmann::json::object()).items())
    spec.params[key] = value.is_string() ? value.get<std::string>() : value.dump();
  spec.size = g.value("size", spec.size);
  spec.seed = g.value("seed", spec.seed);
  return spec;
}

// Rewrites every surface with a generated normal map to a height map file in `dir`.
void toHeightMaps(nlohmann::json& node, const std::string& dir, int& count) {
  if (node.is_object() && node.contains("normal_map") && node["normal_map"].is_object()) {
    const double size = node.value("texture_size", 0.25);
    const std::string file = "heights_" + std::to_string(count++) + ".png";
    const double scale =
        saveHeightMapPng(generateHeightMap(specFrom(node["normal_map"]), size), dir + "/" + file);
    node.erase("normal_map");
    node["height_map"] = file;
    node["height_scale"] = scale > 0.0 ? scale : 1.0;  // a flat map reads 0 at any scale
  }
  if (node.is_structured())
    for (auto& child : node) toHeightMaps(child, dir, count);
}

// The scenes of `files` rewritten into a fresh folder; returns its path.
std::string heightMapScenes(const std::string& tag, const std::vector<std::string>& files) {
  const std::string dir = test::tempDir(tag);
  for (const std::string& file : files) {
    std::ifstream in(test::sourcePath("scenes/" + file));
    nlohmann::json scene = nlohmann::json::parse(in);
    int count = 0;
    toHeightMaps(scene, dir, count);
    EXPECT_GT(count, 0) << file;
    std::ofstream(dir + "/" + file) << scene.dump(1);
  }
  return dir;
}

RunOptions optionsIn(const std::string& dir) {
  RunOptions o;
  o.scenes_dir = dir;
  o.record_every = 5;
  return o;
}

TEST(HeightMapExperiments, BoxesOnMaterialsKeepTheirOrder) {
  const std::string dir = heightMapScenes("boxes_heights", {"boxes_on_materials.json"});
  const Outcome out = runExperiment("boxes_on_materials", optionsIn(dir));
  EXPECT_LT(out.value("slide_concrete"), out.value("slide_cast_iron"));
  EXPECT_LT(out.value("slide_cast_iron"), out.value("slide_steel"));
  EXPECT_LE(out.value("slide_steel"), out.value("slide_plastic"));
  EXPECT_LT(out.value("slide_concrete"), 0.7 * out.value("slide_plastic"));
  EXPECT_TRUE(out.passed) << out.explanation;
}

TEST(HeightMapExperiments, StackingKeepsAcrylicOutAndPvcStill) {
  const std::string dir =
      heightMapScenes("stacking_heights", {"stacking.json", "stacking_forward.json"});
  const Outcome out = runExperiment("stacking", optionsIn(dir));
  for (const std::string side : {"sideways", "forward"}) {
    EXPECT_GT(out.value(side + "_acrylic"), out.value(side + "_oak")) << side;
    EXPECT_GT(out.value(side + "_oak"), out.value(side + "_pvc")) << side;
  }
  EXPECT_TRUE(out.passed) << out.explanation;
}

}  // namespace
}  // namespace asperity::experiments
