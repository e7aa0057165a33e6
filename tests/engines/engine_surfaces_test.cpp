// The engine adapters' surfaces file (asperity/engines/engine_surfaces.hpp): settings and
// scene-style surfaces by name, resolved, with errors that name the file and the entry.
#include "asperity/engines/engine_surfaces.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::errorOf;

TEST(EngineSurfaces, ReadsSettingsAndResolvedSurfacesByName) {
  const nlohmann::json json = R"({
    "settings": {"patch_width": 0.03, "friction_provider": "cone", "frame_mode": "auto", "threads": 2},
    "surfaces": {"floor": {"normal_map": {"generator": "sawtooth", "size": 32}, "gain": 4,
                           "texture_size": 0.08},
                 "box": {"gain": 1}}})"_json;
  const EngineSurfaces s = parseEngineSurfaces(json, "dir/surfaces.json");
  EXPECT_EQ(s.settings.friction.mu0, 0.0);  // the engine's own coefficient is mu0
  EXPECT_EQ(s.settings.friction.patch_width, 0.03);
  EXPECT_EQ(s.settings.provider, "cone");
  EXPECT_EQ(s.settings.frame.mode, FrameMode::Auto);
  EXPECT_EQ(s.settings.threads, 2);
  ASSERT_EQ(s.surfaces.size(), 2u);
  const Surface* floor = s.find("floor");
  ASSERT_NE(floor, nullptr);
  EXPECT_EQ(floor->gain, 4.0);
  EXPECT_NE(floor->normal_map, nullptr);  // generated
  EXPECT_EQ(s.find("box")->normal_map, nullptr);
  EXPECT_EQ(s.find("wall"), nullptr);
}

// The friction model and the surfaces' mechanical values, as a scene takes them.
TEST(EngineSurfaces, ReadsTheFrictionModelAndMechanicalValues) {
  const nlohmann::json json = R"({
    "settings": {"friction_provider": "cpu", "friction_model": "contact_area"},
    "surfaces": {"floor": {"mechanical": "concrete", "gain": 2},
                 "box": {"mechanical": {"E": 2e11, "nu": 0.3, "H": 2e9, "tau": 1e8}}}})"_json;
  const EngineSurfaces s = parseEngineSurfaces(json, "s.json");
  EXPECT_EQ(s.settings.models.model, FrictionModel::ContactArea);
  ASSERT_TRUE(s.find("floor")->mechanical.has_value());
  EXPECT_EQ(s.find("floor")->mechanical->name, "concrete");
  EXPECT_EQ(s.find("floor")->gain, 2.0);
  EXPECT_EQ(s.find("box")->mechanical->modulus, 2e11);
  const std::string bad = errorOf(
      [] { parseEngineSurfaces(R"({"settings": {"friction_model": "sticky"}})"_json, "s.json"); });
  EXPECT_NE(bad.find("/settings/friction_model"), std::string::npos) << bad;
  EXPECT_NE(bad.find("contact_area"), std::string::npos) << bad;
  const std::string preset = errorOf([] {
    parseEngineSurfaces(R"({"surfaces": {"box": {"mechanical": "granite"}}})"_json, "s.json");
  });
  EXPECT_NE(preset.find("/surfaces/box/mechanical: unknown mechanical preset"), std::string::npos)
      << preset;
}

TEST(EngineSurfaces, BadInputNamesTheFileAndTheEntry) {
  const auto error = [](const char* text) {
    return errorOf([&] { parseEngineSurfaces(nlohmann::json::parse(text), "s.json"); });
  };
  EXPECT_NE(error(R"({"settings": {"mu0": 0.2}})").find("s.json: /settings/mu0"),
            std::string::npos);
  EXPECT_NE(error(R"({"surfaces": {"box": {"gian": 1}}})").find("s.json: /surfaces/box/gian"),
            std::string::npos);
  EXPECT_NE(error(R"({"surfacs": {}})").find("/surfacs: unknown key"), std::string::npos);
  // A missing normal map names its path, resolved against the file's folder.
  const std::string dir = test::tempDir("engine_surfaces");
  const std::string path = dir + "/s.json";
  std::ofstream(path) << R"({"surfaces": {"box": {"normal_map": "maps/none.png"}}})";
  const std::string missing = errorOf([&] { loadEngineSurfaces(path); });
  EXPECT_NE(missing.find(dir + "/maps/none.png"), std::string::npos) << missing;
  EXPECT_NE(missing.find("/surfaces/box/normal_map"), std::string::npos) << missing;
  // An entry the adapter cannot place.
  const EngineSurfaces s = parseEngineSurfaces(nlohmann::json::object(), "s.json");
  EXPECT_EQ(errorOf([&] { s.failAt("ghost", "no geom named \"ghost\""); }),
            "s.json: /surfaces/ghost: no geom named \"ghost\"");
}

}  // namespace
}  // namespace asperity
