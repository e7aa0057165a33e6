// instantiate(): normal maps, masks and meshes resolved and shared, bodies, joints, springs and
// loads created by name, the sampler installed, and a sliding box that stops where Coulomb says.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/texture/generators.hpp"
#include "asperity/texture/png_io.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"

namespace asperity {
namespace {

namespace fs = std::filesystem;

SceneDesc example(const std::string& name) {
  return loadScene(test::sourcePath("scenes/examples/" + name));
}

const Surface& surfaceOf(const World& world, const std::string& body, size_t shape = 0) {
  return world.body(world.findBody(body)).shapes.at(shape).surface;
}

TEST(Instantiate, EveryExampleBuildsAWorld) {
  for (const auto& e : fs::directory_iterator(test::sourcePath("scenes/examples"))) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    const SceneDesc scene = loadScene(e.path().string());
    const std::unique_ptr<World> world = instantiate(scene);
    ASSERT_EQ(world->bodies().size(), scene.bodies.size());
    for (size_t i = 0; i < scene.bodies.size(); ++i)
      EXPECT_EQ(world->findBody(scene.bodies[i].name), static_cast<BodyId>(i));
    EXPECT_EQ(world->joints().size(), scene.joints.size());
    EXPECT_EQ(world->springs().size(), scene.springs.size());
    EXPECT_EQ(world->loads().size(), scene.loads.size());
    EXPECT_EQ(world->frictionProvider().name(), scene.friction_provider);
    EXPECT_EQ(world->settings().dt, scene.settings.dt);
  }
}

TEST(Instantiate, EqualGeneratedSurfacesShareOneMap) {
  const std::unique_ptr<World> world = instantiate(example("generated_surfaces.json"));
  const Surface& a = surfaceOf(*world, "box_concrete");
  const Surface& b = surfaceOf(*world, "box_sawtooth");
  ASSERT_NE(a.normal_map, nullptr);
  EXPECT_EQ(a.normal_map.get(), b.normal_map.get());
  EXPECT_NE(a.normal_map.get(), surfaceOf(*world, "sawtooth_plane").normal_map.get());
  // The map is the generator's, texel for texel.
  const NormalMap expected = generateNormalMap(a.source.generator);
  ASSERT_EQ(a.normal_map->width(), 64);
  EXPECT_EQ(a.normal_map->texels(), expected.texels());
}

// Worlds instantiated with one SceneResources share their maps; without, each has its own,
// and either way they simulate the same bits.
TEST(Instantiate, SharedResourcesShareMapsAcrossWorlds) {
  const SceneDesc scene = example("generated_surfaces.json");
  const auto shared = std::make_shared<SceneResources>();
  const InstantiateOptions options(FrictionProviders::builtIn(), shared);
  const std::unique_ptr<World> first = instantiate(scene, options);
  const std::unique_ptr<World> second = instantiate(scene, options);
  const std::unique_ptr<World> own = instantiate(scene);
  const Surface& a = surfaceOf(*first, "sawtooth_plane");
  ASSERT_NE(a.normal_map, nullptr);
  EXPECT_EQ(a.normal_map.get(), surfaceOf(*second, "sawtooth_plane").normal_map.get());
  EXPECT_NE(a.normal_map.get(), surfaceOf(*own, "sawtooth_plane").normal_map.get());
  for (int i = 0; i < 50; ++i) {
    second->step();
    own->step();
  }
  EXPECT_EQ(second->stateHash(), own->stateHash());
}

TEST(Instantiate, PngMapsFollowTheGreenConventionAndMasksLoad) {
  const std::unique_ptr<World> world = instantiate(example("png_surface.json"));
  const Surface& ground = surfaceOf(*world, "ground");
  const Surface& puck = surfaceOf(*world, "puck");
  ASSERT_NE(ground.normal_map, nullptr);
  ASSERT_NE(puck.normal_map, nullptr);
  EXPECT_NE(ground.normal_map.get(), puck.normal_map.get());  // OpenGL vs DirectX
  const NormalMap png = loadNormalMapPng(test::sourcePath("scenes/examples/textures/ridges.png"));
  EXPECT_EQ(ground.normal_map->texels(), png.texels());
  EXPECT_EQ(puck.normal_map->at(3, 5).y(), -ground.normal_map->at(3, 5).y());
  // Mask: left half 255, right half 64 (grey levels / 255).
  ASSERT_NE(ground.mask, nullptr);
  ASSERT_EQ(ground.mask->width, 16);
  EXPECT_FLOAT_EQ(ground.mask->values[0], 1.0f);
  EXPECT_FLOAT_EQ(ground.mask->values[15], 64.0f / 255.0f);
  EXPECT_EQ(puck.mask, nullptr);
}

TEST(Instantiate, MeshesAreLoadedScaledAndSimplified) {
  const std::unique_ptr<World> world = instantiate(example("meshes.json"));
  const Shape& bunny = world->body(world->findBody("bunny")).shapes[0];
  ASSERT_NE(bunny.mesh, nullptr);
  EXPECT_LE(bunny.mesh->triangles.size(), 500u);
  EXPECT_GT(bunny.mesh->triangles.size(), 100u);
  const Shape& wedge = world->body(world->findBody("wedge")).shapes[0];
  const Shape& bump = world->body(world->findBody("bump")).shapes[0];
  ASSERT_NE(wedge.mesh, nullptr);
  ASSERT_NE(bump.mesh, nullptr);
  EXPECT_EQ(bump.mesh->triangles.size(), 8u);
  // Scale 2 doubles every coordinate of the same file.
  double wedge_max = 0.0;
  double bump_max = 0.0;
  for (const Vec3& v : wedge.mesh->vertices) wedge_max = std::max(wedge_max, v.norm());
  for (const Vec3& v : bump.mesh->vertices) bump_max = std::max(bump_max, v.norm());
  EXPECT_GT(bump_max, wedge_max);
  // Collision takes the simplified hull; renderers get the bunny as loaded.
  ASSERT_NE(bunny.display_mesh, nullptr);
  EXPECT_GT(bunny.display_mesh->triangles.size(), 10 * bunny.mesh->triangles.size());
}

TEST(Instantiate, AnAssetsBaseColourShowsUnlessTheSurfaceNamesOne) {
  // two_objects.obj's "lid" uses Kd 0.8 0.3 0.2 and map_Kd (an 8 x 8 PNG).
  const std::string asset = test::sourcePath("tests/fixtures/assets/two_objects.obj");
  auto scene_with = [&](const std::string& surface) {
    return parseScene(nlohmann::json::parse(R"({"bodies": [{"name": "lid", "type": "static",
        "shapes": [{"type": "mesh", "file": ")" +
                                            asset + R"(", "node": "lid",
        "surface": )" + surface + "}]}]}"),
                      "scene.json");
  };
  const SceneDesc plain = scene_with("{}");
  const auto world = instantiate(plain);
  const Surface& own = surfaceOf(*world, "lid");
  EXPECT_TRUE(own.base_color.isApprox(Vec3(0.8, 0.3, 0.2), 1e-6)) << own.base_color.transpose();
  ASSERT_NE(own.base_color_texture, nullptr);
  EXPECT_EQ(own.base_color_texture->width, 8);
  EXPECT_EQ(own.base_color_texture->rgba.size(), 8u * 8u * 4u);
  // Saved back, the surface still names no colour, so a reload shows the asset's again.
  EXPECT_FALSE(sceneToJson(plain)["bodies"][0]["shapes"][0]["surface"].contains("base_color"));
  // A colour in the scene wins, and the texture is then not used.
  const SceneDesc named = scene_with(R"({"base_color": [0.1, 0.2, 0.3]})");
  const auto world_named = instantiate(named);
  const Surface& mine = surfaceOf(*world_named, "lid");
  EXPECT_EQ(mine.base_color, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(mine.base_color_texture, nullptr);
  EXPECT_TRUE(sceneToJson(named)["bodies"][0]["shapes"][0]["surface"].contains("base_color"));
}

TEST(Instantiate, NamesBecomeIds) {
  const SceneDesc scene = example("joints.json");
  const std::unique_ptr<World> world = instantiate(scene);
  EXPECT_EQ(world->joints()[0].body_a, world->findBody("head"));
  EXPECT_EQ(world->joints()[0].body_b, world->findBody("tail"));
  EXPECT_EQ(world->joints()[2].body_b, world->findBody("door"));
  const std::unique_ptr<World> loads = instantiate(example("loads.json"));
  EXPECT_EQ(loads->loads()[0].body, loads->findBody("middle"));
}

TEST(Instantiate, SlidingBoxStopsAtTheCoulombDistance) {
  // minimal.json: v0 = 1 m/s, mu0 = 0.2 on flat surfaces: d = v0^2 / (2 mu0 g).
  const std::unique_ptr<World> world = instantiate(example("minimal.json"));
  for (int i = 0; i < 100; ++i) world->step();
  const Body& box = world->body(world->findBody("box"));
  EXPECT_TRUE(test::near(box.descriptionPose().position.x(), 1.0 / (2 * 0.2 * 9.81), 0.03));
  EXPECT_TRUE(test::near(box.linear_velocity.norm(), 0.0, 0.0, 1e-6));
}

TEST(Instantiate, UnknownFrictionProviderNamesTheSetting) {
  SceneDesc scene = example("minimal.json");
  scene.friction_provider = "velvet";
  try {
    instantiate(scene);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind(scene.source_file + ": /settings/friction_provider: unknown "
                                                        "friction sampler "
                                                        "\"velvet\" (available: ",
                                    0),
        0u)
        << e.what();
  }
}

// Shapes that name one material share one resolved map.
TEST(Instantiate, ShapesOfOneMaterialShareOneMap) {
  const std::unique_ptr<World> world = instantiate(example("materials.json"));
  const Surface& a = surfaceOf(*world, "crate_a");
  ASSERT_NE(a.normal_map, nullptr);
  EXPECT_EQ(a.normal_map.get(), surfaceOf(*world, "crate_b").normal_map.get());
  EXPECT_EQ(a.base_color, Vec3(0.55, 0.36, 0.2));
  EXPECT_NE(surfaceOf(*world, "ground").normal_map, nullptr);
}

// The world's diagnostics get the scene's warnings first, then what resolving found (a map
// loaded once for shared resources is warned about once); nothing is printed.
TEST(Instantiate, WarningsReachTheWorldsDiagnostics) {
  const std::string dir = test::tempDir("warnings");
  png::write(dir + "/grey.png", 2, 1, 3, 8, {128, 128, 128, 128, 128, 255});
  const std::string path = dir + "/scene.json";
  std::ofstream(path) << R"({"settings": {"frame": "world"}, "bodies": [{"name": "b",
      "shapes": [{"type": "sphere", "radius": 0.1, "surface": {"normal_map": "grey.png"}}]}]})";
  const SceneDesc scene = loadScene(path);
  const auto shared = std::make_shared<SceneResources>();
  testing::internal::CaptureStderr();
  const auto first = instantiate(scene, {FrictionProviders::builtIn(), shared});
  const auto second = instantiate(scene, {FrictionProviders::builtIn(), shared});
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  const std::string deprecated = path + ": /settings/frame: deprecated, use \"frame_mode\"";
  EXPECT_EQ(
      first->diagnostics().warnings(),
      (std::vector<std::string>{
          deprecated, dir + "/grey.png: 50 % of texels are not unit normals; treated as flat"}));
  EXPECT_EQ(second->diagnostics().warnings(), std::vector<std::string>{deprecated});
}

TEST(Instantiate, CorruptPngNamesShapeAndFile) {
  const std::string dir = test::tempDir("corrupt");
  std::ofstream(dir + "/bad.png") << "not a png";
  const std::string path = dir + "/scene.json";
  std::ofstream(path) << R"({"bodies": [{"name": "b", "shapes": [{"type": "sphere",
      "radius": 0.1, "surface": {"normal_map": "bad.png"}}]}]})";
  const SceneDesc scene = loadScene(path);  // the file exists: loading succeeds
  try {
    instantiate(scene);
    FAIL();
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": /bodies/0/shapes/0/surface/normal_map: ", 0), 0u) << message;
    EXPECT_NE(message.find("bad.png"), std::string::npos) << message;
  }
}

TEST(Instantiate, CodeBuiltSceneWithUnknownJointBody) {
  SceneDesc scene = example("minimal.json");
  scene.joints.push_back({"box", "lid", JointDesc{}});
  try {
    instantiate(scene);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              scene.source_file + ": /joints/0: body_b: unknown body \"lid\"");
  }
}

TEST(Instantiate, GlbMaterialSuppliesTheNormalMapWhenTheSurfaceNamesNone) {
  // glb_asset.json: the ground's surface names no normal_map; the .glb embeds a 64 x 64
  // sawtooth (period 16), which must arrive as the generator makes it (8-bit quantised).
  const auto world = instantiate(example("glb_asset.json"));
  const Surface& ground = surfaceOf(*world, "ground");
  ASSERT_NE(ground.normal_map, nullptr);
  GeneratorSpec spec;
  spec.name = "sawtooth";
  spec.size = 64;
  spec.params = {{"period", "16"}};
  const NormalMap expected = generateNormalMap(spec);
  ASSERT_EQ(ground.normal_map->width(), 64);
  for (size_t k = 0; k < expected.texels().size(); ++k)
    ASSERT_LT((ground.normal_map->texels()[k] - expected.texels()[k]).norm(), 0.02f) << k;
  // The box's own surface stays flat.
  EXPECT_EQ(surfaceOf(*world, "slider").normal_map, nullptr);
}

}  // namespace
}  // namespace asperity
