// The renderer on llvmpipe: images are lit, normal maps change shading only where the texture
// is rough, debug points land where they project, frames are reproducible.
#include "asperity/render/renderer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "asperity/error.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "asperity/texture/generators.hpp"
#include "render_test_support.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// A ground plane and a 0.2 m cube resting on it, seen from the default framing.
render::RenderScene groundAndCube(std::shared_ptr<const NormalMap> ground_map) {
  render::RenderScene scene;
  Shape plane;
  plane.type = ShapeType::Plane;
  ShapeMeshOptions mesh_options;
  mesh_options.plane_size = 4.0;
  render::RenderItem ground;
  ground.mesh = std::make_shared<const ShapeMesh>(buildShapeMesh(plane, mesh_options));
  ground.normal_map = std::move(ground_map);
  ground.ground = true;
  scene.items.push_back(ground);
  Shape box;
  box.half_extents = Vec3(0.1, 0.1, 0.1);
  render::RenderItem cube;
  cube.mesh = std::make_shared<const ShapeMesh>(buildShapeMesh(box));
  cube.pose.position = Vec3(0.0, 0.0, 0.1);
  cube.base_color = Vec3(0.8, 0.3, 0.2);
  scene.items.push_back(cube);
  scene.focus = Eigen::AlignedBox3d(Vec3(-0.3, -0.3, 0.0), Vec3(0.3, 0.3, 0.2));
  return scene;
}

render::Image draw(const render::RenderScene& scene, const render::Camera& camera,
                   render::RendererOptions options = {}) {
  test::sharedContext();
  options.width = kWidth;
  options.height = kHeight;
  render::Renderer renderer(options);
  renderer.render(scene, camera);
  return renderer.readPixels();
}

render::Camera cameraFor(const render::RenderScene& scene) {
  return render::frameBox(scene.focus, double(kWidth) / kHeight, 2.0);
}

TEST(Renderer, ImageIsLitAndNotBlank) {
  const render::RenderScene scene = groundAndCube(nullptr);
  const render::Image image = draw(scene, cameraFor(scene));
  ASSERT_EQ(image.rgb.size(), size_t(kWidth) * kHeight * 3);
  EXPECT_GT(test::luminanceDeviation(image), 10.0);
  // The cube's colour (reddish) is at the image centre, where the camera looks.
  const uint8_t* centre = image.pixel(kWidth / 2, kHeight / 2);
  EXPECT_GT(int(centre[0]), int(centre[2]) + 30);
}

TEST(Renderer, BaseColourTextureTintsTheSurface) {
  // The cube in white, then with a green and a blue 2 x 2 colour texture (sRGB bytes).
  auto textured = [](uint8_t r, uint8_t g, uint8_t b) {
    render::RenderScene scene = groundAndCube(nullptr);
    scene.items[1].base_color = Vec3(1, 1, 1);
    std::vector<uint8_t> rgba;
    for (int k = 0; k < 4; ++k) rgba.insert(rgba.end(), {r, g, b, 255});
    scene.items[1].base_color_texture =
        std::make_shared<const ColorImage>(ColorImage{2, 2, std::move(rgba)});
    return scene;
  };
  const render::RenderScene green = textured(20, 220, 30);
  const render::Camera camera = cameraFor(green);
  const render::Image green_image = draw(green, camera);
  const uint8_t* g = green_image.pixel(kWidth / 2, kHeight / 2);
  EXPECT_GT(int(g[1]), int(g[0]) + 60);
  EXPECT_GT(int(g[1]), int(g[2]) + 60);
  const render::Image blue_image = draw(textured(20, 30, 220), camera);
  const uint8_t* b = blue_image.pixel(kWidth / 2, kHeight / 2);
  EXPECT_GT(int(b[2]), int(b[0]) + 60);
  // A white texture is the untextured surface.
  render::RenderScene plain = groundAndCube(nullptr);
  plain.items[1].base_color = Vec3(1, 1, 1);
  EXPECT_LT(test::meanAbsDifference(draw(plain, camera), draw(textured(255, 255, 255), camera)),
            0.5);
}

TEST(Renderer, FlatNormalMapMatchesNoNormalMapAndRoughOneDiffers) {
  const render::RenderScene none = groundAndCube(nullptr);
  const render::RenderScene flat = groundAndCube(std::make_shared<const NormalMap>(16, 16));
  const render::RenderScene rough = groundAndCube(test::roughMap());
  const render::Camera camera = cameraFor(none);
  const render::Image a = draw(none, camera);
  // A map of (0, 0, 1) everywhere is the macro normal: the same picture, to rounding.
  EXPECT_LT(test::meanAbsDifference(a, draw(flat, camera)), 0.5);
  // Rough texels tilt the shading normal: the ground changes visibly.
  EXPECT_GT(test::meanAbsDifference(a, draw(rough, camera)), 3.0);
  // Switching normal maps off renders the rough scene flat-shaded again.
  render::RendererOptions off;
  off.normal_maps = false;
  EXPECT_LT(test::meanAbsDifference(a, draw(rough, camera, off)), 0.5);
}

TEST(Renderer, RoughTextureAddsShadingVariationOnTheGround) {
  // Same view of the ground only (no cube): rough texels make the lit ground vary.
  render::RenderScene flat = groundAndCube(nullptr);
  render::RenderScene rough = groundAndCube(test::roughMap());
  flat.items.pop_back();
  rough.items.pop_back();
  render::Camera camera;
  camera.eye = Vec3(0.0, -0.4, 0.5);
  camera.target = Vec3::Zero();
  render::RendererOptions options;
  options.grid_step = 100.0;  // no grid lines in view
  EXPECT_GT(test::luminanceDeviation(draw(rough, camera, options)),
            2.0 * test::luminanceDeviation(draw(flat, camera, options)) + 2.0);
}

TEST(Renderer, DebugPointIsDrawnWhereItProjects) {
  render::RenderScene scene = groundAndCube(nullptr);
  const Vec3 corner(0.1, -0.1, 0.0);  // a bottom corner of the cube: where contacts sit
  const Vec3 magenta(1.0, 0.0, 1.0);
  scene.debug.points.push_back({corner, magenta, 9.0f});
  const render::Camera camera = cameraFor(scene);
  const Eigen::Vector3d p = camera.project(corner, kWidth, kHeight);
  ASSERT_GT(p.z(), 0.0);
  const int x = static_cast<int>(p.x()), y = static_cast<int>(p.y());
  ASSERT_TRUE(x >= 0 && x < kWidth && y >= 0 && y < kHeight);
  const render::Image with = draw(scene, camera);
  const uint8_t* px = with.pixel(x, y);
  EXPECT_GT(px[0], 230);
  EXPECT_LT(px[1], 25);
  EXPECT_GT(px[2], 230);
  // Without the point that pixel is not magenta.
  scene.debug.clear();
  const render::Image without = draw(scene, camera);
  const uint8_t* plain = without.pixel(x, y);
  EXPECT_FALSE(plain[0] > 230 && plain[1] < 25 && plain[2] > 230);
}

TEST(Renderer, SameFrameTwiceGivesTheSamePixels) {
  const render::RenderScene scene = groundAndCube(test::roughMap());
  const render::Camera camera = cameraFor(scene);
  test::sharedContext();
  render::RendererOptions options;
  options.width = kWidth;
  options.height = kHeight;
  render::Renderer renderer(options);
  renderer.render(scene, camera);
  const render::Image first = renderer.readPixels();
  renderer.render(scene, camera);
  EXPECT_EQ(first.rgb, renderer.readPixels().rgb);
  // A fresh renderer gives the same frame too.
  EXPECT_EQ(first.rgb, draw(scene, camera).rgb);
}

// Edge energy: the sum of squared luminance steps between horizontal and vertical neighbours.
// Smoothing a step of height h over two pixels halves its energy (2 (h/2)^2 = h^2 / 2), so
// anti-aliased silhouettes have less of it than aliased ones of the same picture.
double edgeEnergy(const render::Image& image) {
  auto luminance = [&](int x, int y) {
    const uint8_t* p = image.pixel(x, y);
    return 0.3 * p[0] + 0.59 * p[1] + 0.11 * p[2];
  };
  double energy = 0.0;
  for (int y = 0; y + 1 < image.height; ++y)
    for (int x = 0; x + 1 < image.width; ++x) {
      const double here = luminance(x, y);
      energy += std::pow(luminance(x + 1, y) - here, 2) + std::pow(luminance(x, y + 1) - here, 2);
    }
  return energy;
}

TEST(Renderer, MsaaSmoothsEdges) {
  const render::RenderScene scene = groundAndCube(nullptr);
  const render::Camera camera = cameraFor(scene);
  render::RendererOptions one, four;
  one.samples = 1;
  four.samples = 4;
  const render::Image aliased = draw(scene, camera, one), smooth = draw(scene, camera, four);
  // The same picture (the cube and ground where they were) ...
  EXPECT_LT(test::meanAbsDifference(aliased, smooth), 3.0);
  // ... with softer edges.
  EXPECT_LT(edgeEnergy(smooth), 0.9 * edgeEnergy(aliased))
      << edgeEnergy(smooth) << " against " << edgeEnergy(aliased);
}

// The top face of stacking_forward.json's top oak cube at 1 s, seen almost exactly edge-on
// (the camera 2 mm above its plane), with a normal map and 4x MSAA: Mesa 22's llvmpipe spent
// minutes on this one face with anisotropic filtering on. It must draw like any other frame.
TEST(Renderer, EdgeOnNormalMappedFaceDrawsPromptly) {
  render::RenderScene scene;
  Shape box;
  box.half_extents = Vec3(0.1, 0.1, 0.1);
  box.surface.texture_size = 0.2;
  box.surface.texture_rotation = 45.0 * kPi / 180.0;
  render::RenderItem cube;
  cube.mesh = std::make_shared<const ShapeMesh>(buildShapeMesh(box));
  cube.normal_map =
      std::make_shared<const NormalMap>(generateNormalMap(GeneratorSpec{"oak", {}, 160, 12}));
  cube.pose.position = Vec3(0.0093278391032693871, -0.048882016869500014, 0.89813298584315593);
  cube.pose.rotation = Quat(0.99997998070238736, 0.0010419960130041723, -0.00053720170515549569,
                            0.0062180264626378653);
  scene.items.push_back(cube);
  scene.focus = Eigen::AlignedBox3d(Vec3(-0.1, -0.15, 0.8), Vec3(0.1, 0.05, 1.0));
  render::Camera camera;
  camera.eye = Vec3(0.75, -2.7, 1.0);
  camera.target = Vec3(0.15, 0.0, 0.38);
  test::sharedContext();
  render::RendererOptions options;
  options.width = 960;
  options.height = 540;
  options.samples = 4;
  render::Renderer renderer(options);
  const auto t0 = std::chrono::steady_clock::now();
  renderer.render(scene, camera);
  const render::Image image = renderer.readPixels();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_GT(test::luminanceDeviation(image), 1.0);
  // Normally a few tens of milliseconds; the bad case took minutes.
  EXPECT_LT(seconds, 30.0);
}

TEST(Renderer, BadSizesAreErrors) {
  test::sharedContext();
  render::RendererOptions options;
  options.width = 0;
  EXPECT_THROW(render::Renderer{options}, Error);
  options.width = 64;
  options.height = 20000;
  EXPECT_THROW(render::Renderer{options}, Error);
  options.height = 64;
  options.samples = 0;
  EXPECT_THROW(render::Renderer{options}, Error);
}

TEST(Renderer, SavePngWritesAndNamesUnwritablePaths) {
  const render::RenderScene scene = groundAndCube(nullptr);
  const render::Image image = draw(scene, cameraFor(scene));
  const std::string path = test::tempDir("png") + "/frame.png";
  render::savePng(image, path);
  EXPECT_GT(std::filesystem::file_size(path), 100u);
  try {
    render::savePng(image, "/nonexistent-folder/frame.png");
    FAIL() << "wrote into a missing folder";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/frame.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace asperity
