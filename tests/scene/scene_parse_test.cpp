// Scene files, top level: settings, joints, springs and loads; every kind of bad file names
// the file and the JSON pointer of the culprit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Writes `text` as <tempdir>/scene.json and returns its path.
std::string writeScene(const std::string& text) {
  const std::string path = test::tempDir("scene") + "/scene.json";
  std::ofstream(path) << text;
  return path;
}

// The error loading `text` gives, with the file's path replaced by "FILE".
std::string loadError(const std::string& text) {
  const std::string path = writeScene(text);
  try {
    loadScene(path);
  } catch (const Error& e) {
    std::string message = e.what();
    if (message.rfind(path, 0) == 0) message = "FILE" + message.substr(path.size());
    return message;
  }
  return "";
}

const char* kTwoBodies = R"("bodies": [
  {"name": "ground", "type": "static", "shapes": [{"type": "plane"}]},
  {"name": "box", "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]}])";

TEST(SceneParse, MinimalSceneTakesDefaults) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/minimal.json"));
  const WorldSettings defaults;
  EXPECT_EQ(scene.settings.dt, defaults.dt);
  EXPECT_EQ(scene.settings.gravity, Vec3(0.0, 0.0, -9.81));  // z up
  EXPECT_EQ(scene.friction_provider, "cone");
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].type, BodyType::Static);
  EXPECT_EQ(scene.bodies[1].type, BodyType::Dynamic);
  EXPECT_EQ(scene.bodies[1].linear_velocity, Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(scene.base_dir, test::sourcePath("scenes/examples"));
}

TEST(SceneParse, SettingsAreRead) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/settings.json"));
  EXPECT_EQ(scene.settings.limit_surface, LimitSurfaceKind::Polygon);
  EXPECT_EQ(scene.settings.frame.mode, FrameMode::World);
  EXPECT_EQ(scene.settings.friction.directions, 8);
  EXPECT_EQ(scene.settings.friction.mu0, 0.2);
  EXPECT_EQ(scene.settings.friction.mu_max, 4.0f);
  EXPECT_EQ(scene.settings.friction.patch_width, 0.02);
  EXPECT_EQ(scene.settings.friction.patch_resolution, 16);
}

TEST(SceneParse, JointsSpringsAndLoads) {
  const SceneDesc joints = loadScene(test::sourcePath("scenes/examples/joints.json"));
  ASSERT_EQ(joints.joints.size(), 3u);
  EXPECT_EQ(joints.joints[0].desc.type, JointType::Distance);
  EXPECT_EQ(joints.joints[0].body_a, "head");
  EXPECT_EQ(joints.joints[0].desc.rest_length, 0.05);
  EXPECT_EQ(joints.joints[0].desc.amplitude, 0.02);
  EXPECT_EQ(joints.joints[1].desc.rest_length, -1.0);  // absent: from the anchors
  EXPECT_EQ(joints.joints[2].desc.type, JointType::Hinge);
  const SceneDesc spring = loadScene(test::sourcePath("scenes/examples/spring.json"));
  ASSERT_EQ(spring.springs.size(), 1u);
  EXPECT_EQ(spring.springs[0].desc.stiffness, 200.0);
  EXPECT_EQ(spring.springs[0].desc.target_velocity, Vec3(0.2, 0.0, 0.0));
  const SceneDesc loads = loadScene(test::sourcePath("scenes/examples/loads.json"));
  ASSERT_EQ(loads.loads.size(), 4u);
  EXPECT_EQ(loads.loads[0].desc.kind, LoadDesc::Kind::Impulse);
  EXPECT_EQ(loads.loads[0].body, "middle");
  EXPECT_EQ(loads.loads[3].desc.kind, LoadDesc::Kind::AngularImpulse);
  EXPECT_EQ(loads.loads[1].desc.end, 1.5);
}

TEST(SceneParse, SyntaxErrorNamesLineAndColumn) {
  EXPECT_EQ(loadError("{\n  \"settings\": {\"dt\": 0.01,}\n}").rfind("FILE:2:27: syntax error", 0),
            0u);
}

TEST(SceneParse, MissingFile) {
  try {
    loadScene("/nonexistent/scene.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.json: cannot open file");
  }
}

TEST(SceneParse, TopLevelMustBeAnObject) {
  EXPECT_EQ(loadError("[1, 2]"), "FILE: /: must be an object, got array [1,2]");
}

TEST(SceneParse, UnknownKeys) {
  EXPECT_EQ(loadError("{\"bodys\": []}").rfind("FILE: /bodys: unknown key (expected one of:", 0),
            0u);
  EXPECT_EQ(loadError("{\"settings\": {\"tiem_step\": 1}}")
                .rfind("FILE: /settings/tiem_step: unknown key", 0),
            0u);
}

TEST(SceneParse, SettingsRanges) {
  EXPECT_EQ(loadError(R"({"settings": {"dt": 0}})"),
            "FILE: /settings/dt: must be a number in (0, 1], got 0");
  EXPECT_EQ(loadError(R"({"settings": {"dt": 2}})"),
            "FILE: /settings/dt: must be a number in (0, 1], got 2");
  EXPECT_EQ(loadError(R"({"settings": {"dt": -0.01}})"),
            "FILE: /settings/dt: must be a number in (0, 1], got -0.01");
  EXPECT_EQ(loadError(R"({"settings": {"iterations": 0}})"),
            "FILE: /settings/iterations: must be an integer in [1, 10000], got 0");
  EXPECT_EQ(loadError(R"({"settings": {"substeps": 0}})"),
            "FILE: /settings/substeps: must be an integer in [1, 1000], got 0");
  EXPECT_EQ(loadError(R"({"settings": {"directions": 3}})"),
            "FILE: /settings/directions: must be an integer in [4, 64], got 3");
  EXPECT_EQ(loadError(R"({"settings": {"patch_width": 0}})"),
            "FILE: /settings/patch_width: must be a number in [1e-06, 100], got 0");
  EXPECT_EQ(loadError(R"({"settings": {"gravity": [0, 0, 1e300]}})"),
            "FILE: /settings/gravity/2: must be a number in [-1000000, 1000000], got 1e+300");
  EXPECT_EQ(loadError(R"({"settings": {"mu0": "0.2"}})"),
            "FILE: /settings/mu0: must be a finite number, got string \"0.2\"");
  EXPECT_EQ(loadError(R"({"settings": {"friction_provider": ""}})"),
            "FILE: /settings/friction_provider: must be a friction provider name, got \"\"");
  EXPECT_EQ(loadError(R"({"settings": {"sampler": ""}})"),
            "FILE: /settings/sampler: must be a friction provider name, got \"\"");
}

TEST(SceneParse, HugeNumberLiteralIsASyntaxError) {
  // 1e999 does not fit a double; the JSON reader refuses it with its position.
  EXPECT_EQ(loadError("{\"settings\":\n  {\"dt\": 1e999}}"),
            "FILE:2:10: number overflow parsing '1e999'");
}

TEST(SceneParse, BadEnumerationStrings) {
  EXPECT_EQ(loadError(R"({"settings": {"limit_surface": "cone"}})"),
            "FILE: /settings/limit_surface: must be one of \"coulomb\", \"box\", \"polygon\", "
            "got string \"cone\"");
  EXPECT_EQ(loadError(R"({"settings": {"frame_mode": "tangent"}})"),
            "FILE: /settings/frame_mode: must be one of \"world\", \"body\", \"auto\", "
            "\"texture\", got string \"tangent\"");
  // A deprecated key's bad value is named at the key it was given under.
  EXPECT_EQ(loadError(R"({"settings": {"frame": "tangent"}})")
                .rfind("FILE: /settings/frame: must be one of", 0),
            0u);
}

// The old names of renamed keys are still read, each with a warning naming the new key; saving
// writes the new names only, which read back without a warning.
TEST(SceneParse, DeprecatedKeysAreReadWithAWarning) {
  const std::string path =
      writeScene(std::string("{") + kTwoBodies +
                 R"(, "settings": {"friction": "polygon", "frame": "auto", "sampler": "cpu"},
          "loads": [{"body": "box", "point": [0.1, 0, 0]}]})");
  const SceneDesc scene = loadScene(path);
  EXPECT_EQ(scene.settings.limit_surface, LimitSurfaceKind::Polygon);
  EXPECT_EQ(scene.settings.frame.mode, FrameMode::Auto);
  EXPECT_EQ(scene.friction_provider, "cpu");
  ASSERT_EQ(scene.loads.size(), 1u);
  EXPECT_EQ(scene.loads[0].desc.local_point, Vec3(0.1, 0.0, 0.0));
  EXPECT_EQ(scene.warnings, (std::vector<std::string>{
                                path + ": /settings/friction: deprecated, use \"limit_surface\"",
                                path + ": /settings/frame: deprecated, use \"frame_mode\"",
                                path + ": /settings/sampler: deprecated, use \"friction_provider\"",
                                path + ": /loads/0/point: deprecated, use \"local_point\""}));
  const nlohmann::json saved = sceneToJson(scene);
  for (const char* old_key : {"friction", "frame", "sampler"})
    EXPECT_FALSE(saved["settings"].contains(old_key)) << old_key;
  EXPECT_EQ(saved["settings"]["frame_mode"], "auto");
  EXPECT_FALSE(saved["loads"][0].contains("point"));
  const SceneDesc again = parseScene(saved, path);
  EXPECT_TRUE(again.warnings.empty());
  EXPECT_EQ(again.settings.limit_surface, LimitSurfaceKind::Polygon);
  EXPECT_EQ(again.friction_provider, "cpu");
  EXPECT_EQ(again.loads[0].desc.local_point, Vec3(0.1, 0.0, 0.0));
  // Only the new names are offered for a misspelt key.
  const std::string unknown = loadError(R"({"settings": {"dtt": 1}})");
  EXPECT_NE(unknown.find("frame_mode"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find(" frame,"), std::string::npos) << unknown;
}

// An old and a new name of one key together are an error at the old one.
TEST(SceneParse, OldAndNewKeyTogetherIsAnError) {
  EXPECT_EQ(loadError(R"({"settings": {"frame": "auto", "frame_mode": "world"}})"),
            "FILE: /settings/frame: deprecated name of \"frame_mode\", which is also given: keep "
            "only \"frame_mode\"");
  EXPECT_EQ(loadError(R"({"settings": {"friction": "box", "limit_surface": "box"}})"),
            "FILE: /settings/friction: deprecated name of \"limit_surface\", which is also given: "
            "keep only \"limit_surface\"");
  EXPECT_EQ(loadError(R"({"settings": {"sampler": "cpu", "friction_provider": "cpu"}})"),
            "FILE: /settings/sampler: deprecated name of \"friction_provider\", which is also "
            "given: keep only \"friction_provider\"");
  EXPECT_EQ(
      loadError(std::string("{") + kTwoBodies +
                R"(, "loads": [{"body": "box", "point": [0, 0, 0], "local_point": [0, 0, 0]}]})"),
      "FILE: /loads/0/point: deprecated name of \"local_point\", which is also given: keep "
      "only \"local_point\"");
}

TEST(SceneParse, ZeroAxis) {
  EXPECT_EQ(loadError(R"({"settings": {"world_axis": [0, 0, 0]}})"),
            "FILE: /settings/world_axis: must be a non-zero vector, got [0, 0, 0]");
}

TEST(SceneParse, JointToUnknownBody) {
  EXPECT_EQ(loadError(std::string("{") + kTwoBodies +
                      R"(, "joints": [{"type": "ball", "body_a": "box", "body_b": "lid"}]})"),
            "FILE: /joints/0/body_b: unknown body \"lid\"");
  EXPECT_EQ(loadError(std::string("{") + kTwoBodies + R"(, "joints": [{"body_a": "box"}]})"),
            "FILE: /joints/0: missing key \"body_b\" (a string)");
  EXPECT_EQ(loadError(std::string("{") + kTwoBodies +
                      R"(, "joints": [{"body_a": "box", "body_b": "box"}]})"),
            "FILE: /joints/0/body_b: must differ from body_a (\"box\")");
}

TEST(SceneParse, BadJointType) {
  EXPECT_EQ(
      loadError(std::string("{") + kTwoBodies +
                R"(, "joints": [{"type": "slider", "body_a": "ground", "body_b": "box"}]})"),
      "FILE: /joints/0/type: must be one of \"distance\", \"ball\", \"hinge\", \"fixed\", got "
      "string \"slider\"");
}

TEST(SceneParse, SpringAndLoadErrors) {
  EXPECT_EQ(loadError(std::string("{") + kTwoBodies + R"(, "springs": [{"body": "crate"}]})"),
            "FILE: /springs/0/body: unknown body \"crate\"");
  EXPECT_EQ(loadError(std::string("{") + kTwoBodies +
                      R"(, "springs": [{"body": "box", "stiffness": -1}]})"),
            "FILE: /springs/0/stiffness: must be a non-negative number, got -1");
  EXPECT_EQ(
      loadError(std::string("{") + kTwoBodies + R"(, "loads": [{"body": "box", "kind": "push"}]})"),
      "FILE: /loads/0/kind: must be one of \"force\", \"torque\", \"impulse\", "
      "\"angular_impulse\", got string \"push\"");
  EXPECT_EQ(loadError(std::string("{") + kTwoBodies +
                      R"(, "loads": [{"body": "box", "start": 2, "end": 1}]})"),
            "FILE: /loads/0/end: must be a number in [2, 1e+30], got 1");
}

TEST(SceneParse, Camera) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/looks.json"));
  ASSERT_TRUE(scene.camera.has_value());
  EXPECT_EQ(scene.camera->eye, Vec3(0.45, -0.55, 0.3));
  EXPECT_EQ(scene.camera->target, Vec3(0.0, 0.0, 0.05));
  EXPECT_TRUE(test::near(scene.camera->fov_y, kPi / 6.0, 1e-15));
  // No "camera": none; one without fov_deg: 35 degrees.
  EXPECT_FALSE(loadScene(test::sourcePath("scenes/examples/minimal.json")).camera.has_value());
  const SceneDesc plain = loadScene(writeScene(
      std::string("{") + kTwoBodies + R"(, "camera": {"eye": [1, 0, 1], "target": [0, 0, 0]}})"));
  ASSERT_TRUE(plain.camera.has_value());
  EXPECT_TRUE(test::near(plain.camera->fov_y, 35.0 * kPi / 180.0, 1e-15));
}

TEST(SceneParse, BadCamera) {
  const std::string scene = std::string("{") + kTwoBodies + R"(, "camera": )";
  EXPECT_EQ(loadError(scene + R"({"target": [0, 0, 0]}})"),
            "FILE: /camera: missing key \"eye\" (an array of 3 numbers)");
  EXPECT_EQ(loadError(scene + R"({"eye": [1, 1, 1], "target": [1, 1, 1]}})"),
            "FILE: /camera/target: must differ from eye");
  EXPECT_EQ(loadError(scene + R"({"eye": [1, 0, 0], "target": [0, 0, 0], "fov_deg": 180}})"),
            "FILE: /camera/fov_deg: must be a number in (0, 180), got 180");
  EXPECT_EQ(loadError(scene + R"({"eye": [1, 0, 0], "target": [0, 0, 0], "fov_deg": 0}})"),
            "FILE: /camera/fov_deg: must be a number in (0, 180), got 0");
  EXPECT_EQ(loadError(scene + R"({"eye": [1, 0, "x"], "target": [0, 0, 0]}})")
                .rfind("FILE: /camera/eye/2: ", 0),
            0u);
  EXPECT_EQ(loadError(scene + R"({"eye": [1, 0, 0], "target": [0, 0, 0], "up": [0, 0, 1]}})")
                .rfind("FILE: /camera/up: unknown key", 0),
            0u);
  EXPECT_EQ(loadError(scene + R"([1, 2]})").rfind("FILE: /camera: ", 0), 0u);
}

}  // namespace
}  // namespace asperity
