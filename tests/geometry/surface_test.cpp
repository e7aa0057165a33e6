#include "asperity/geometry/surface.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "asperity/error.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"

namespace asperity {
namespace {

SurfaceSource sawtoothSource() {
  SurfaceSource source;
  source.generator.name = "sawtooth";
  source.generator.size = 64;
  return source;
}

// A surface described by its source alone resolves to exactly the generated map.
TEST(Surface, SourceWithGeneratorLoadsTheGeneratedMap) {
  const SurfaceSource source = sawtoothSource();
  Diagnostics diagnostics;
  const auto map = loadNormalMap(source, diagnostics);
  ASSERT_TRUE(map);
  const NormalMap expected = generateNormalMap(source.generator);
  ASSERT_EQ(map->width(), expected.width());
  EXPECT_EQ(map->texels(), expected.texels());
  EXPECT_FALSE(loadNormalMap(SurfaceSource{}, diagnostics));
  EXPECT_TRUE(diagnostics.warnings().empty());
}

// The world reads no files: a surface described by its source alone is refused, with a message
// naming the body, the shape and the resolver to call.
TEST(Surface, WorldRefusesAnUnresolvedSurface) {
  World world;
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source = sawtoothSource();
  EXPECT_EQ(test::errorOf([&] { world.createBody(ground); }),
            "body \"ground\" shape 0: its surface's normal map generator \"sawtooth\" is not "
            "resolved; call resolveSurfaces(desc.shapes, world.diagnostics()) "
            "(asperity/geometry/shape.hpp) before createBody");
  // A file and a mask are named the same way.
  BodyDesc box = boxDesc("box", Vec3::Constant(0.1), {});
  box.shapes.push_back(box.shapes[0]);
  box.shapes[1].surface.source.mask_file = "mask.png";
  EXPECT_EQ(test::errorOf([&] { world.createBody(box); }).substr(0, 55),
            "body \"box\" shape 1: its surface's mask \"mask.png\" is no");
  EXPECT_TRUE(world.bodies().empty());
}

// The resolver, called before createBody, gives the world the generated map.
TEST(Surface, ResolvedSurfacesReachTheWorld) {
  World world;
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source = sawtoothSource();
  resolveSurfaces(ground.shapes, world.diagnostics());
  const BodyId id = world.createBody(ground);
  const Surface& s = world.body(id).shapes[0].surface;
  ASSERT_TRUE(s.normal_map);
  EXPECT_EQ(s.normal_map->width(), 64);
  EXPECT_EQ(unresolvedPart(s), "");
}

// A missing file is an error naming the shape and the file, not a flat surface.
TEST(Surface, MissingFileIsAnErrorNamingIt) {
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source.normal_map_file = "no/such/map.png";
  Diagnostics diagnostics;
  const std::string message = test::errorOf([&] { resolveSurfaces(ground.shapes, diagnostics); });
  EXPECT_EQ(message.rfind("shape 0: ", 0), 0u) << message;
  EXPECT_NE(message.find("no/such/map.png"), std::string::npos) << message;
}

// Warnings go to the diagnostics handed in, never to stderr: a PNG with texels that are not
// normals, read through the resolver.
TEST(Surface, WarningsGoToTheDiagnostics) {
  const std::string path = test::tempDir("surface") + "/grey.png";
  png::write(path, 2, 1, 3, 8, {128, 128, 128, 128, 128, 255});
  Surface surface;
  surface.source.normal_map_file = path;
  Diagnostics diagnostics;
  std::vector<std::string> seen;
  diagnostics.setSink([&](const std::string& w) { seen.push_back(w); });
  testing::internal::CaptureStderr();
  resolveSurface(surface, diagnostics);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  ASSERT_EQ(diagnostics.warnings().size(), 1u);
  EXPECT_EQ(diagnostics.warnings()[0],
            path + ": 50 % of texels are not unit normals; treated as flat");
  EXPECT_EQ(seen, diagnostics.warnings());
}

// One default sampler: a world built in code uses the provider a scene gets by default.
TEST(Surface, CodeAndScenesShareTheDefaultSampler) {
  World world;
  EXPECT_EQ(world.frictionProvider().name(), std::string(kDefaultFrictionProvider));
}

}  // namespace
}  // namespace asperity
