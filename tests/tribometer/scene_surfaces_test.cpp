// The tribometer's surfaces from two bodies of a scene: the bodies' resolved surfaces, the
// scene's friction settings, and errors naming an unknown body.
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

}  // namespace
}  // namespace asperity
