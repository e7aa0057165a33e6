// Scene files, bodies: shapes, orientations, surfaces (files and generators), OBJ meshes, and
// every kind of bad body with its exact JSON pointer.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Loads `text` written as <dir>/scene.json; returns the error with the path replaced by FILE
// and the folder by DIR ("" when it loads).
std::string loadError(const std::string& text) {
  const std::string dir = test::tempDir("bodies");
  const std::string path = dir + "/scene.json";
  std::ofstream(path) << text;
  try {
    loadScene(path);
  } catch (const Error& e) {
    std::string message = e.what();
    if (message.rfind(path, 0) == 0) message = "FILE" + message.substr(path.size());
    const size_t at = message.find(dir);
    if (at != std::string::npos) message.replace(at, dir.size(), "DIR");
    return message;
  }
  return "";
}

// Loads `text` written as <dir>/scene.json (it must load).
SceneDesc loadText(const std::string& text) {
  const std::string path = test::tempDir("bodies") + "/scene.json";
  std::ofstream(path) << text;
  return loadScene(path);
}

// An asset every test machine has (Debian's glmark2-data).
const char* kBunny = "/usr/share/glmark2/models/bunny.obj";

// A scene whose only body is a dynamic body with the given shape JSON.
std::string withShape(const std::string& shape) {
  return R"({"bodies": [{"name": "b", "shapes": [)" + shape + "]}]}";
}

TEST(BodyParse, EveryPrimitiveShape) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/shapes.json"));
  ASSERT_EQ(scene.bodies.size(), 8u);
  EXPECT_EQ(scene.bodies[1].shapes[0].type, ShapeType::Box);
  EXPECT_EQ(scene.bodies[1].shapes[0].density, 500.0);
  EXPECT_EQ(scene.bodies[2].shapes[0].type, ShapeType::Sphere);
  EXPECT_EQ(scene.bodies[3].shapes[0].type, ShapeType::Capsule);
  EXPECT_EQ(scene.bodies[4].shapes[0].type, ShapeType::Cylinder);
  EXPECT_EQ(scene.bodies[5].shapes[0].type, ShapeType::ConvexHull);
  EXPECT_EQ(scene.bodies[5].shapes[0].mesh->vertices.size(), 5u);
  EXPECT_EQ(scene.bodies[5].mass_override, 0.5);
  EXPECT_EQ(scene.bodies[6].shapes.size(), 3u);  // compound
  EXPECT_EQ(scene.bodies[6].shapes[1].local.position, Vec3(0.15, 0.0, 0.0));
  EXPECT_EQ(scene.bodies[7].type, BodyType::Kinematic);
}

TEST(BodyParse, EulerAnglesAboutFixedXThenYThenZ) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/shapes.json"));
  // The pill: 90 degrees about x takes local y to world z.
  const Vec3 y = scene.bodies[3].pose.rotation * Vec3::UnitY();
  EXPECT_TRUE(test::near(y.z(), 1.0, 0.0, 1e-15));
  // The dumbbell's bar: 90 degrees about y takes the cylinder axis (z) to x.
  const Vec3 axis = scene.bodies[6].shapes[2].local.rotation * Vec3::UnitZ();
  EXPECT_TRUE(test::near(axis.x(), 1.0, 0.0, 1e-15));
  // Both rotations at once: x first, then z (fixed axes): y -> z -> z.
  const std::string text = R"({"bodies": [{"name": "b", "euler_deg": [90, 0, 90],
      "shapes": [{"type": "sphere", "radius": 0.1}]}]})";
  const std::string path = test::tempDir("euler") + "/scene.json";
  std::ofstream(path) << text;
  const Quat q = loadScene(path).bodies[0].pose.rotation;
  EXPECT_TRUE(test::near((q * Vec3::UnitY()).z(), 1.0, 0.0, 1e-15));
  EXPECT_TRUE(test::near((q * Vec3::UnitX()).y(), 1.0, 0.0, 1e-15));
}

TEST(BodyParse, GeneratedAndFileSurfaces) {
  const SceneDesc gen = loadScene(test::sourcePath("scenes/examples/generated_surfaces.json"));
  const Surface& saw = gen.bodies[1].shapes[0].surface;
  EXPECT_EQ(saw.source.generator.name, "sawtooth");
  EXPECT_EQ(saw.source.generator.params.at("period"), "16");
  EXPECT_EQ(saw.source.generator.size, 128);
  EXPECT_EQ(saw.gain, 4.0);
  EXPECT_TRUE(test::near(saw.texture_rotation, kPi / 2, 1e-15));
  EXPECT_EQ(gen.bodies[0].shapes[0].surface.source.generator.seed, 7u);
  const SceneDesc png = loadScene(test::sourcePath("scenes/examples/png_surface.json"));
  const Surface& ground = png.bodies[0].shapes[0].surface;
  EXPECT_EQ(ground.source.normal_map_file, "textures/ridges.png");
  EXPECT_EQ(ground.source.mask_file, "textures/half_mask.png");
  EXPECT_EQ(ground.source.green, GreenConvention::OpenGL);
  EXPECT_EQ(png.bodies[1].shapes[0].surface.source.green, GreenConvention::DirectX);
  EXPECT_EQ(png.settings.frame.mode, FrameMode::Texture);
}

TEST(BodyParse, MeshesKeepTheirSource) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/meshes.json"));
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_EQ(scene.meshes[0].file, "/usr/share/glmark2/models/bunny.obj");
  EXPECT_EQ(scene.meshes[0].body, 1u);
  EXPECT_EQ(scene.meshes[0].simplify, 500);
  EXPECT_EQ(scene.meshes[0].scale, 0.1);
  EXPECT_EQ(scene.meshes[2].file, "meshes/wedge.obj");
  EXPECT_EQ(scene.bodies[3].shapes[0].type, ShapeType::TriangleMesh);
}

TEST(BodyParse, NegativeSize) {
  EXPECT_EQ(loadError(withShape(R"({"type": "box", "half_extents": [0.1, -0.1, 0.1]})")),
            "FILE: /bodies/0/shapes/0/half_extents/1: must be a positive number, got -0.1");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0})")),
            "FILE: /bodies/0/shapes/0/radius: must be a positive number, got 0");
  EXPECT_EQ(loadError(withShape(R"({"type": "capsule", "radius": 0.1, "half_height": 1e9})")),
            "FILE: /bodies/0/shapes/0/half_height: must be at most 1000000, got 1000000000");
  EXPECT_EQ(loadError(withShape(R"({"type": "box", "half_extents": [1, 1, 1], "density": -5})")),
            "FILE: /bodies/0/shapes/0/density: must be a positive number, got -5");
}

TEST(BodyParse, MissingAndUnknownShapeKeys) {
  EXPECT_EQ(loadError(withShape(R"({"type": "cylinder", "radius": 0.1})")),
            "FILE: /bodies/0/shapes/0: missing key \"half_height\" (a positive number)");
  EXPECT_EQ(loadError(withShape(R"({"half_extents": [1, 1, 1]})")),
            "FILE: /bodies/0/shapes/0: missing key \"type\"");
  EXPECT_EQ(loadError(withShape(R"({"type": "box", "half_extents": [1, 1, 1], "radius": 1})"))
                .rfind("FILE: /bodies/0/shapes/0/radius: unknown key", 0),
            0u);
  EXPECT_EQ(loadError(withShape(R"({"type": "cone", "radius": 1})")),
            "FILE: /bodies/0/shapes/0/type: must be one of \"box\", \"sphere\", \"capsule\", "
            "\"cylinder\", \"plane\", \"convex_hull\", \"mesh\", got string \"cone\"");
}

TEST(BodyParse, WrongType) {
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": "big"})")),
            "FILE: /bodies/0/shapes/0/radius: must be a positive number, got string \"big\"");
  EXPECT_EQ(loadError(R"({"bodies": {"name": "b"}})"),
            "FILE: /bodies: must be an array, got object {\"name\":\"b\"}");
}

TEST(BodyParse, BadQuaternion) {
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "orientation": [0, 0, 0, 0],
                "shapes": [{"type": "sphere", "radius": 0.1}]}]})"),
            "FILE: /bodies/0/orientation: must be a non-zero quaternion [w, x, y, z], got "
            "[0,0,0,0]");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "orientation": [1, 0, 0, 0],
                "euler_deg": [0, 0, 0], "shapes": [{"type": "sphere", "radius": 0.1}]}]})"),
            "FILE: /bodies/0/euler_deg: give orientation or euler_deg, not both");
}

TEST(BodyParse, DuplicateBodyName) {
  EXPECT_EQ(loadError(R"({"bodies": [
      {"name": "box", "shapes": [{"type": "sphere", "radius": 0.1}]},
      {"name": "box", "shapes": [{"type": "sphere", "radius": 0.1}]}]})"),
            "FILE: /bodies/1/name: duplicate body name \"box\"");
}

TEST(BodyParse, BodyRules) {
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "", "type": "static"}]})"),
            "FILE: /bodies/0/name: must not be empty");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b"}]})"),
            "FILE: /bodies/0: a dynamic body needs at least one shape");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "shapes": [{"type": "plane"}]}]})"),
            "FILE: /bodies/0/shapes/0/type: a plane can only belong to a static body");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "type": "frozen"}]})"),
            "FILE: /bodies/0/type: must be one of \"dynamic\", \"static\", \"kinematic\", got "
            "string \"frozen\"");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "type": "static", "mass": 0}]})"),
            "FILE: /bodies/0/mass: must be a positive number, got 0");
}

// A hull takes exactly one of "points" and "file" (or the deprecated "mesh").
TEST(BodyParse, ConvexHullNeedsPointsOrFile) {
  EXPECT_EQ(loadError(withShape(R"({"type": "convex_hull"})")),
            "FILE: /bodies/0/shapes/0: a convex hull needs exactly one of \"points\" and \"file\", "
            "got neither");
  EXPECT_EQ(loadError(withShape(std::string(R"({"type": "convex_hull", "file": ")") + kBunny +
                                R"(", "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]})")),
            "FILE: /bodies/0/shapes/0: a convex hull needs exactly one of \"points\" and \"file\", "
            "got both");
  EXPECT_EQ(loadError(withShape(std::string(R"({"type": "convex_hull", "mesh": ")") + kBunny +
                                R"(", "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]})")),
            "FILE: /bodies/0/shapes/0: a convex hull needs exactly one of \"points\" and \"mesh\", "
            "got both");
  EXPECT_EQ(loadError(withShape(std::string(R"({"type": "convex_hull", "mesh": ")") + kBunny +
                                R"(", "file": ")" + kBunny + R"("})")),
            "FILE: /bodies/0/shapes/0/mesh: deprecated name of \"file\", which is also given: keep "
            "only \"file\"");
  EXPECT_EQ(loadError(withShape(R"({"type": "convex_hull", "points": [[0,0,0],[1,0,0]]})")),
            "FILE: /bodies/0/shapes/0/points: a convex hull needs at least 4 points, got 2");
  EXPECT_EQ(loadError(withShape(R"({"type": "convex_hull", "points": [[0,0,0],[1,0]]})")),
            "FILE: /bodies/0/shapes/0/points/1: must be an array of 3 numbers, got array [1,0]");
}

TEST(BodyParse, UnknownGenerator) {
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": {"generator": "velvet"}}})"))
                .rfind("FILE: /bodies/0/shapes/0/surface/normal_map/generator: unknown generator "
                       "\"velvet\" (expected one of \"gaussian\"",
                       0),
            0u);
}

TEST(BodyParse, BadGeneratorParameters) {
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": {"generator": "gaussian", "params": {"sz": 1}}}})")),
            "FILE: /bodies/0/shapes/0/surface/normal_map/params/sz: unknown parameter of "
            "generator \"gaussian\" (expected one of \"sx\", \"sy\")");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": {"generator": "gaussian", "params": {"sx": -1}}}})")),
            "FILE: /bodies/0/shapes/0/surface/normal_map/params/sx: must be a number in [0, "
            "100], got -1");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": {"generator": "gaussian", "size": 0}}})")),
            "FILE: /bodies/0/shapes/0/surface/normal_map/size: must be an integer in [1, "
            "8192], got 0");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": {"generator": "gaussian", "seed": -1}}})")),
            "FILE: /bodies/0/shapes/0/surface/normal_map/seed: must be a non-negative integer, "
            "got -1");
}

TEST(BodyParse, ASeedBuiltInCodeReadsAsTheSameSeedParsed) {
  // nlohmann::json holds 3 written in code as a signed integer and "3" parsed as unsigned.
  const nlohmann::json parsed = nlohmann::json::parse(R"({"bodies": [{"name": "b", "shapes":
      [{"type": "sphere", "radius": 0.1, "surface": {"normal_map": {"generator": "gaussian",
      "seed": 3}}}]}]})");
  nlohmann::json built = parsed;
  built["bodies"][0]["shapes"][0]["surface"]["normal_map"]["seed"] = int{3};
  ASSERT_TRUE(built["bodies"][0]["shapes"][0]["surface"]["normal_map"]["seed"].is_number_integer());
  EXPECT_EQ(sceneToJson(parseScene(built, "built")), sceneToJson(parseScene(parsed, "parsed")));
}

TEST(BodyParse, MissingNormalMapFile) {
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": "textures/none.png"}})")),
            "FILE: /bodies/0/shapes/0/surface/normal_map: file not found: "
            "\"DIR/textures/none.png\"");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"normal_map": 3}})")),
            "FILE: /bodies/0/shapes/0/surface/normal_map: must be a PNG file name or a "
            "generator object, got 3");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"mask": "/no/mask.png"}})")),
            "FILE: /bodies/0/shapes/0/surface/mask: file not found: \"/no/mask.png\"");
}

TEST(BodyParse, SurfaceRanges) {
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"texture_size": 0}})")),
            "FILE: /bodies/0/shapes/0/surface/texture_size: must be a positive number, got 0");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"gain": -1}})")),
            "FILE: /bodies/0/shapes/0/surface/gain: must be a number in [0, 10000], got -1");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"directx": "yes"}})")),
            "FILE: /bodies/0/shapes/0/surface/directx: must be true or false, got string "
            "\"yes\"");
}

TEST(BodyParse, BaseColour) {
  const SceneDesc scene = loadScene(test::sourcePath("scenes/examples/looks.json"));
  EXPECT_EQ(scene.bodies[1].shapes[0].surface.base_color, Vec3(0.42, 0.24, 0.11));
  // Absent: the renderer's neutral grey.
  const SceneDesc plain = loadScene(test::sourcePath("scenes/examples/minimal.json"));
  EXPECT_EQ(plain.bodies[1].shapes[0].surface.base_color, Vec3(0.7, 0.7, 0.7));
}

TEST(BodyParse, BadBaseColour) {
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"base_color": [0.5, 1.2, 0]}})")),
            "FILE: /bodies/0/shapes/0/surface/base_color/1: must be a number in [0, 1], got 1.2");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"base_color": [0.5, -0.1, 0]}})")),
            "FILE: /bodies/0/shapes/0/surface/base_color/1: must be a number in [0, 1], got -0.1");
  const std::string short_colour = loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"base_color": [0.5, 0.5]}})"));
  EXPECT_EQ(short_colour.rfind("FILE: /bodies/0/shapes/0/surface/base_color: ", 0), 0u)
      << short_colour;
  const std::string text = loadError(withShape(R"({"type": "sphere", "radius": 0.1,
                "surface": {"base_color": "red"}})"));
  EXPECT_EQ(text.rfind("FILE: /bodies/0/shapes/0/surface/base_color: ", 0), 0u) << text;
}

// Every shape that reads an asset names it with "file"; a hull's old "mesh" still reads, with a
// warning.
TEST(BodyParse, ConvexHullFromAFile) {
  const SceneDesc scene = loadText(withShape(std::string(R"({"type": "convex_hull", "file": ")") +
                                             kBunny + R"(", "scale": 0.1})"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].file, kBunny);
  EXPECT_TRUE(scene.warnings.empty());
  const SceneDesc old = loadText(withShape(std::string(R"({"type": "convex_hull", "mesh": ")") +
                                           kBunny + R"(", "scale": 0.1})"));
  ASSERT_EQ(old.meshes.size(), 1u);
  EXPECT_EQ(old.meshes[0].file, kBunny);
  ASSERT_EQ(old.warnings.size(), 1u);
  EXPECT_EQ(old.warnings[0],
            old.source_file + ": /bodies/0/shapes/0/mesh: deprecated, use \"file\"");
  // Saved, it names the file under "file".
  const nlohmann::json saved = sceneToJson(old)["bodies"][0]["shapes"][0];
  EXPECT_EQ(saved["file"], kBunny);
  EXPECT_FALSE(saved.contains("mesh"));
}

// Named materials: a shape's "surface" may name an entry of "materials" and gets a copy of it.
TEST(BodyParse, NamedMaterials) {
  const SceneDesc scene = loadText(R"({"materials": {
      "oak": {"normal_map": {"generator": "oak", "size": 32}, "gain": 2},
      "ice": {"gain": 0, "base_color": [0.8, 0.9, 1]}},
    "bodies": [{"name": "a", "shapes": [{"type": "sphere", "radius": 0.1, "surface": "oak"}]},
               {"name": "b", "shapes": [{"type": "sphere", "radius": 0.1, "surface": "ice"},
                                        {"type": "sphere", "radius": 0.1,
                                         "surface": {"gain": 3}}]}]})");
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_TRUE(scene.materials.at("ice").names_base_color);
  EXPECT_FALSE(scene.materials.at("oak").names_base_color);
  const Surface& oak = scene.bodies[0].shapes[0].surface;
  EXPECT_EQ(oak.source.material, "oak");
  EXPECT_EQ(oak.source.generator.name, "oak");
  EXPECT_EQ(oak.gain, 2.0);
  EXPECT_EQ(scene.bodies[1].shapes[0].surface.base_color, Vec3(0.8, 0.9, 1.0));
  EXPECT_EQ(scene.bodies[1].shapes[1].surface.source.material, "");
  EXPECT_EQ(scene.bodies[1].shapes[1].surface.gain, 3.0);
}

// A name that is not in the table is an error naming the pointer and the known names.
TEST(BodyParse, UnknownMaterial) {
  EXPECT_EQ(loadError(R"({"materials": {"oak": {}, "acrylic": {}},
      "bodies": [{"name": "b",
                  "shapes": [{"type": "sphere", "radius": 0.1, "surface": "teak"}]}]})"),
            "FILE: /bodies/0/shapes/0/surface: unknown material \"teak\" (one of \"acrylic\", "
            "\"oak\")");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1, "surface": "teak"})")),
            "FILE: /bodies/0/shapes/0/surface: unknown material \"teak\" (the scene has no "
            "\"materials\")");
  EXPECT_EQ(loadError(withShape(R"({"type": "sphere", "radius": 0.1, "surface": 3})")),
            "FILE: /bodies/0/shapes/0/surface: must be an object or the name of a material, got 3");
  EXPECT_EQ(loadError(R"({"materials": {"oak": "teak"}})"),
            "FILE: /materials/oak: must be an object, got string \"teak\"");
  EXPECT_EQ(loadError(R"({"materials": {"oak": {"gain": -1}}})"),
            "FILE: /materials/oak/gain: must be a number in [0, 10000], got -1");
  EXPECT_EQ(loadError(R"({"materials": {"oak": {"grain": 1}}})")
                .rfind("FILE: /materials/oak/grain: unknown key", 0),
            0u);
}

TEST(BodyParse, MissingMesh) {
  EXPECT_EQ(loadError(withShape(R"({"type": "convex_hull", "file": "rock.obj"})")),
            "FILE: /bodies/0/shapes/0/file: file not found: \"DIR/rock.obj\"");
  EXPECT_EQ(loadError(withShape(R"({"type": "convex_hull", "mesh": "rock.obj"})")),
            "FILE: /bodies/0/shapes/0/mesh: file not found: \"DIR/rock.obj\"");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "type": "static",
                "shapes": [{"type": "mesh", "file": "/no/such.obj", "simplify": 10}]}]})"),
            "FILE: /bodies/0/shapes/0/file: file not found: \"/no/such.obj\"");
  EXPECT_EQ(loadError(R"({"bodies": [{"name": "b", "type": "static",
                "shapes": [{"type": "mesh", "file": "/usr/share/glmark2/models/bunny.obj",
                            "simplify": -1}]}]})"),
            "FILE: /bodies/0/shapes/0/simplify: must be an integer in [0, 10000000], got -1");
}

}  // namespace
}  // namespace asperity
