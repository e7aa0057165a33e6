// World -> render scene: items per shape, the default camera, picking, and contact points
// drawn where the step put them.
#include "asperity/render/world_view.hpp"

#include <gtest/gtest.h>

#include "asperity/render/renderer.hpp"
#include "render_test_support.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// A 0.2 m cube resting on the ground plane z = 0.
std::unique_ptr<World> cubeOnGround() {
  auto world = std::make_unique<World>();
  BodyDesc ground;
  ground.name = "ground";
  ground.type = BodyType::Static;
  Shape plane;
  plane.type = ShapeType::Plane;
  ground.shapes.push_back(plane);
  world->createBody(ground);
  BodyDesc cube;
  cube.name = "cube";
  cube.pose.position = Vec3(0.0, 0.0, 0.1);
  Shape box;
  box.half_extents = Vec3(0.1, 0.1, 0.1);
  box.surface.base_color = Vec3(0.2, 0.4, 0.8);
  cube.shapes.push_back(box);
  world->createBody(cube);
  for (int i = 0; i < 5; ++i) world->step();
  return world;
}

TEST(WorldView, OneItemPerShapeWithSurfaceColourAndGround) {
  const auto world = cubeOnGround();
  const render::RenderScene scene = render::renderWorld(*world);
  ASSERT_EQ(scene.items.size(), 2u);
  EXPECT_TRUE(scene.items[0].ground);
  EXPECT_FALSE(scene.items[1].ground);
  EXPECT_EQ(scene.items[1].base_color, Vec3(0.2, 0.4, 0.8));
  EXPECT_EQ(scene.items[1].id, 1u);
  // The focus is the cube alone, not the infinite plane.
  EXPECT_TRUE(test::near(scene.focus.sizes().x(), 0.2, 1e-3));
}

TEST(WorldView, AHullDrawsItsAssetsFullMeshAndColourTexture) {
  // A tetrahedron hull standing in for a simplified asset, whose display mesh is a finer one.
  auto hull = std::make_shared<TriangleMeshData>();
  hull->vertices = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0, 0.1)};
  auto shown = std::make_shared<TriangleMeshData>();
  for (int k = 0; k < 20; ++k) {  // a strip of 20 triangles
    shown->vertices.push_back(Vec3(0.005 * k, 0, 0));
    shown->vertices.push_back(Vec3(0.005 * k, 0.05, 0.05));
  }
  for (int k = 0; k + 2 < 40; k += 2) {
    shown->triangles.push_back({k, k + 2, k + 1});
    shown->triangles.push_back({k + 1, k + 2, k + 3});
  }
  World world;
  BodyDesc rock;
  rock.name = "rock";
  Shape shape;
  shape.type = ShapeType::ConvexHull;
  shape.mesh = hull;
  shape.display_mesh = shown;
  shape.surface.base_color_texture =
      std::make_shared<const ColorImage>(ColorImage{1, 1, std::vector<uint8_t>{10, 200, 30, 255}});
  rock.shapes.push_back(shape);
  world.createBody(rock);
  const render::RenderScene scene = render::renderWorld(world);
  ASSERT_EQ(scene.items.size(), 1u);
  EXPECT_EQ(scene.items[0].mesh->triangles.size(), shown->triangles.size());
  EXPECT_EQ(scene.items[0].base_color_texture, shape.surface.base_color_texture);
  // Without a display mesh the hull itself is drawn (4 faces).
  world.body(0).shapes[0].display_mesh = nullptr;
  EXPECT_EQ(render::renderWorld(world).items[0].mesh->triangles.size(), 4u);
}

TEST(WorldView, PickFindsTheCubeFromAbove) {
  const auto world = cubeOnGround();
  render::WorldView view;
  const auto hit = view.pick(*world, Vec3(0.03, 0.02, 1.0), -Vec3::UnitZ());
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->body, 1u);
  EXPECT_TRUE(test::near(hit->point.z(), world->body(1).pose.position.z() + 0.1, 0.0, 1e-6));
  // Beside the cube only the static ground is there: no dynamic body.
  EXPECT_FALSE(view.pick(*world, Vec3(1.0, 1.0, 1.0), -Vec3::UnitZ()).has_value());
}

TEST(WorldView, ContactPointsAreDrawnWhereTheyProject) {
  const auto world = cubeOnGround();
  ASSERT_FALSE(world->contacts().empty());
  render::WorldViewOptions options;
  options.debug.layers = kLayerContacts;
  render::WorldView view;
  render::RenderScene scene;
  view.update(*world, options, scene);
  ASSERT_EQ(scene.debug.points.size(), world->contacts().size());
  // Draw, then look at each contact's pixel: the contact colour (debug points are on top).
  const int w = 320, h = 240;
  test::sharedContext();
  render::RendererOptions ro;
  ro.width = w;
  ro.height = h;
  render::Renderer renderer(ro);
  const render::Camera camera = view.defaultCamera(*world, double(w) / h);
  renderer.render(scene, camera);
  const render::Image image = renderer.readPixels();
  const Vec3 expected = options.debug.contact_color * 255.0;
  for (const Contact& c : world->contacts()) {
    const Eigen::Vector3d p = camera.project(c.point, w, h);
    const uint8_t* px = image.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
    EXPECT_NEAR(px[0], expected.x(), 12.0);
    EXPECT_NEAR(px[1], expected.y(), 12.0);
    EXPECT_NEAR(px[2], expected.z(), 12.0);
  }
}

}  // namespace
}  // namespace asperity
