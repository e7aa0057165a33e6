// Saving scenes: load -> save -> load gives the same description and the same JSON, generated
// surfaces keep their spec, files their relative path (rewritten when saved elsewhere).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "scene/scene_common.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> examples() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(test::sourcePath("scenes/examples")))
    if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Field-by-field equality of two bodies (what sceneToJson cannot see is left out).
void expectSameBody(const BodyDesc& a, const BodyDesc& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.pose.position, b.pose.position);
  EXPECT_EQ(a.pose.rotation.coeffs(), b.pose.rotation.coeffs());
  EXPECT_EQ(a.linear_velocity, b.linear_velocity);
  EXPECT_EQ(a.angular_velocity, b.angular_velocity);
  EXPECT_EQ(a.mass_override, b.mass_override);
  ASSERT_EQ(a.shapes.size(), b.shapes.size());
  for (size_t i = 0; i < a.shapes.size(); ++i) {
    const Shape& s = a.shapes[i];
    const Shape& t = b.shapes[i];
    EXPECT_EQ(s.type, t.type);
    EXPECT_EQ(s.local.rotation.coeffs(), t.local.rotation.coeffs());
    EXPECT_EQ(s.half_extents, t.half_extents);
    EXPECT_EQ(s.radius, t.radius);
    EXPECT_EQ(s.surface.source.generator.params, t.surface.source.generator.params);
    EXPECT_EQ(s.surface.texture_rotation, t.surface.texture_rotation);
    EXPECT_EQ(s.surface.gain, t.surface.gain);
    EXPECT_EQ(s.surface.base_color, t.surface.base_color);
  }
}

TEST(SceneWrite, EveryExampleRoundTrips) {
  const std::string dir = test::tempDir("roundtrip");
  ASSERT_GE(examples().size(), 8u);
  for (const std::string& path : examples()) {
    SCOPED_TRACE(path);
    const SceneDesc first = loadScene(path);
    // Saved elsewhere (relative paths rewritten), reloaded, saved again.
    const std::string copy = dir + "/" + fs::path(path).filename().string();
    saveScene(first, copy);
    const SceneDesc second = loadScene(copy);
    const std::string text = slurp(copy);
    saveScene(second, copy);
    EXPECT_EQ(slurp(copy), text);  // saving again gives identical JSON
    EXPECT_EQ(nlohmann::json::parse(text), sceneToJson(second));
    ASSERT_EQ(first.bodies.size(), second.bodies.size());
    for (size_t i = 0; i < first.bodies.size(); ++i)
      expectSameBody(first.bodies[i], second.bodies[i]);
    EXPECT_EQ(first.settings.dt, second.settings.dt);
    EXPECT_EQ(first.settings.friction.mu_max, second.settings.friction.mu_max);
  }
}

TEST(SceneWrite, GeneratedSurfacesSaveTheirSpec) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/generated_surfaces.json"));
  const nlohmann::json j = sceneToJson(scene);
  const nlohmann::json& map = j["bodies"][1]["shapes"][0]["surface"]["normal_map"];
  EXPECT_EQ(map["generator"], "sawtooth");
  EXPECT_EQ(map["params"]["period"], 16.0);  // numbers stay numbers
  EXPECT_EQ(map["size"], 128);
  EXPECT_EQ(j["bodies"][1]["shapes"][0]["surface"]["texture_rotation_deg"], 90.0);
}

TEST(SceneWrite, RelativePathsFollowTheNewFolder) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/png_surface.json"));
  const std::string dir = test::tempDir("rebase") + "/deeper";
  fs::create_directories(dir);
  saveScene(scene, dir + "/copy.json");
  const SceneDesc moved = loadScene(dir + "/copy.json");  // the files must still be found
  const std::string original =
      fs::weakly_canonical(test::sourcePath("scenes/examples/textures/ridges.png")).string();
  const std::string resolved =
      scene::resolvePath(moved.base_dir, moved.bodies[0].shapes[0].surface.source.normal_map_file);
  EXPECT_EQ(fs::weakly_canonical(resolved).string(), original);
  EXPECT_FALSE(fs::path(moved.bodies[0].shapes[0].surface.source.normal_map_file).is_absolute());
  // The OBJ meshes likewise; absolute paths stay absolute.
  const SceneDesc meshes = loadScene(test::sourcePath("scenes/examples/meshes.json"));
  saveScene(meshes, dir + "/meshes.json");
  const SceneDesc moved_meshes = loadScene(dir + "/meshes.json");
  EXPECT_EQ(moved_meshes.meshes[0].file, "/usr/share/glmark2/models/bunny.obj");
}

TEST(SceneWrite, DegreesConvertBackExactly) {
  for (double deg : {0.1, 1.0, 33.3, 45.0, 90.0, -17.25, 359.9, 1e-7}) {
    const double rad = scene::radiansFromDegrees(deg);
    EXPECT_EQ(scene::radiansFromDegrees(scene::degreesFromRadians(rad)), rad) << deg;
  }
}

TEST(SceneWrite, CameraAndColoursRoundTrip) {
  const SceneDesc first = loadScene(test::sourcePath("scenes/examples/looks.json"));
  const std::string copy = test::tempDir("looks") + "/looks.json";
  saveScene(first, copy);
  const SceneDesc second = loadScene(copy);
  ASSERT_TRUE(second.camera.has_value());
  EXPECT_EQ(second.camera->eye, first.camera->eye);
  EXPECT_EQ(second.camera->target, first.camera->target);
  EXPECT_EQ(second.camera->fov_y, first.camera->fov_y);  // bit for bit through degrees
  EXPECT_NEAR(sceneToJson(second)["camera"]["fov_deg"].get<double>(), 30.0, 1e-9);
  for (size_t i = 0; i < first.bodies.size(); ++i)
    EXPECT_EQ(second.bodies[i].shapes[0].surface.base_color,
              first.bodies[i].shapes[0].surface.base_color);
  // A scene without a camera saves none.
  EXPECT_FALSE(
      sceneToJson(loadScene(test::sourcePath("scenes/examples/minimal.json"))).contains("camera"));
}

// Named materials: saving writes the table and each reference by name, with relative files
// rewritten in both; load -> save -> load gives the same scene. A shape whose surface was
// changed in code no longer equals its material and is written out in full.
TEST(SceneWrite, MaterialsRoundTripByName) {
  const SceneDesc first = loadScene(test::sourcePath("scenes/examples/materials.json"));
  const std::string dir = test::tempDir("materials") + "/deeper";
  fs::create_directories(dir);
  saveScene(first, dir + "/materials.json");
  const SceneDesc second = loadScene(dir + "/materials.json");
  const nlohmann::json saved = nlohmann::json::parse(slurp(dir + "/materials.json"));
  EXPECT_EQ(saved["materials"].size(), 2u);
  EXPECT_EQ(saved["bodies"][0]["shapes"][0]["surface"], "ridges");
  EXPECT_EQ(saved["bodies"][1]["shapes"][0]["surface"], "oak");
  EXPECT_EQ(saved["bodies"][2]["shapes"][0]["surface"], "oak");
  // The reloaded scene equals the first: table, references, bodies.
  ASSERT_EQ(second.materials.size(), first.materials.size());
  for (const auto& [name, material] : first.materials) {
    EXPECT_EQ(second.materials.at(name).names_base_color, material.names_base_color) << name;
    EXPECT_EQ(second.materials.at(name).surface.gain, material.surface.gain) << name;
  }
  ASSERT_EQ(second.bodies.size(), first.bodies.size());
  for (size_t i = 0; i < first.bodies.size(); ++i) {
    expectSameBody(first.bodies[i], second.bodies[i]);
    EXPECT_EQ(second.bodies[i].shapes[0].surface.source.material,
              first.bodies[i].shapes[0].surface.source.material);
  }
  saveScene(second, dir + "/again.json");
  EXPECT_EQ(slurp(dir + "/again.json"), slurp(dir + "/materials.json"));
  // The PNG of "ridges" is still found from the new folder.
  const std::string png = second.materials.at("ridges").surface.source.normal_map_file;
  EXPECT_TRUE(fs::is_regular_file(scene::resolvePath(second.base_dir, png))) << png;
  // Changed in code: written in full, the others still by name.
  SceneDesc changed = first;
  changed.bodies[1].shapes[0].surface.gain = 7.0;
  const nlohmann::json j = sceneToJson(changed);
  EXPECT_EQ(j["bodies"][1]["shapes"][0]["surface"]["gain"], 7.0);
  EXPECT_EQ(j["bodies"][2]["shapes"][0]["surface"], "oak");
}

TEST(SceneWrite, UnwritableFile) {
  SceneDesc scene;
  try {
    saveScene(scene, "/nonexistent/folder/x.json");
    FAIL() << "a scene was written into a folder that does not exist";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/x.json"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace asperity
