// The tribometer's surfaces: from two bodies of a scene (their resolved surfaces, the scene's
// friction settings, errors naming an unknown body) and from a source as the CLI and Python
// give it (textures or a scene, with overrides). Texture texts: tribometer_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::errorOf;
using test::near;

TEST(SceneSurfaces, TheBodiesSurfacesAndTheScenesFriction) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/boxes_on_materials.json"));
  TribometerSettings settings;
  Diagnostics diagnostics;
  const TribometerSurfaces s =
      sceneSurfaces(scene, "box_concrete", "plane_concrete", settings, diagnostics);
  // The box's material (plaster) and the plane's concrete, with their gains and sizes.
  ASSERT_TRUE(s.block.normal_map && s.plate.normal_map);
  EXPECT_EQ(s.block.source.generator.name, "plaster");
  EXPECT_EQ(s.plate.source.generator.name, "concrete");
  EXPECT_DOUBLE_EQ(s.block.gain, 2.0);
  EXPECT_DOUBLE_EQ(s.plate.texture_size, 0.256);
  EXPECT_DOUBLE_EQ(settings.friction.mu0, 0.2);
  EXPECT_EQ(settings.sampler, "cpu");
  // They run: a drag along u gives mu0 + ploughing.
  settings.directions = 4;
  settings.tilt = false;
  settings.tracks = 1;
  const TribometerResult r = runTribometer(s, settings);
  ASSERT_TRUE(r.directions[0].mu_k.has_value());
  EXPECT_GT(*r.directions[0].mu_k, 0.3);
  EXPECT_TRUE(near(*r.directions[0].mu_k, *r.directions[0].mu_model, 0.05));
}

TEST(SceneSurfaces, AnUnknownBodyIsAnErrorListingTheBodies) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/boxes_on_materials.json"));
  TribometerSettings settings;
  Diagnostics diagnostics;
  const std::string message =
      errorOf([&] { sceneSurfaces(scene, "box_concrete", "nosuch", settings, diagnostics); });
  EXPECT_NE(message.find("'nosuch'"), std::string::npos) << message;
  EXPECT_NE(message.find("plane_steel"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(TribometerSource, TexturesTakeTheConeDefaultsAndGivenNumbers) {
  TribometerSource source;
  source.plate = "gen:sawtooth:1:size=64";
  TribometerSettings settings;
  Diagnostics diagnostics;
  TribometerSurfaces s = resolveTribometerSource(source, settings, diagnostics);
  EXPECT_TRUE(s.plate.normal_map && !s.block.normal_map);
  EXPECT_DOUBLE_EQ(s.plate.gain, 1.0);
  EXPECT_DOUBLE_EQ(settings.friction.mu0, 0.0);
  source.block = "gen:oak:2:size=64";
  source.k_a = 2.0, source.k_b = 3.0, source.mu0 = 0.25;
  s = resolveTribometerSource(source, settings, diagnostics);
  EXPECT_TRUE(s.block.normal_map);
  EXPECT_DOUBLE_EQ(s.block.gain, 2.0);
  EXPECT_DOUBLE_EQ(s.plate.gain, 3.0);
  EXPECT_DOUBLE_EQ(s.block.texture_size, 0.256);
  EXPECT_DOUBLE_EQ(settings.friction.mu0, 0.25);
}

TEST(TribometerSource, GivenNumbersOverrideTheScenes) {
  TribometerSource source;
  source.scene = test::sourcePath("scenes/boxes_on_materials.json");
  source.block_body = "box_steel", source.plate_body = "plane_steel";
  source.k_b = 5.0;
  TribometerSettings settings;
  Diagnostics diagnostics;
  const TribometerSurfaces s = resolveTribometerSource(source, settings, diagnostics);
  EXPECT_DOUBLE_EQ(s.block.gain, 2.0);
  EXPECT_DOUBLE_EQ(s.plate.gain, 5.0);
  EXPECT_DOUBLE_EQ(settings.friction.mu0, 0.2);
}

TEST(TribometerSource, BothOrNeitherOfTextureAndSceneIsAnError) {
  TribometerSettings settings;
  Diagnostics diagnostics;
  TribometerSource source;
  EXPECT_NE(errorOf([&] { resolveTribometerSource(source, settings, diagnostics); }).find("B.png"),
            std::string::npos);
  source.scene = test::sourcePath("scenes/boxes_on_materials.json");
  EXPECT_NE(
      errorOf([&] { resolveTribometerSource(source, settings, diagnostics); }).find("--bodies"),
      std::string::npos);
  source.plate = "gen:oak:1";
  EXPECT_NE(
      errorOf([&] { resolveTribometerSource(source, settings, diagnostics); }).find("not both"),
      std::string::npos);
}

}  // namespace
}  // namespace asperity
