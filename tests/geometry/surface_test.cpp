#include "asperity/geometry/surface.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "asperity/error.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

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
  const auto map = loadNormalMap(source);
  ASSERT_TRUE(map);
  const NormalMap expected = generateNormalMap(source.generator);
  ASSERT_EQ(map->width(), expected.width());
  EXPECT_EQ(map->texels(), expected.texels());
  EXPECT_FALSE(loadNormalMap(SurfaceSource{}));
}

// Code that sets only the source must not get a flat surface: createBody resolves it.
TEST(Surface, WorldResolvesASurfaceDescribedInCode) {
  World world;
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source = sawtoothSource();
  const BodyId id = world.createBody(ground);
  const Surface& s = world.body(id).shapes[0].surface;
  ASSERT_TRUE(s.normal_map);
  EXPECT_EQ(s.normal_map->width(), 64);
  EXPECT_TRUE(world.bodyDesc(id).shapes[0].surface.normal_map);
}

// A missing file in a code-built surface is an error naming it, not a flat surface.
TEST(Surface, MissingFileInCodeIsAnErrorNamingIt) {
  World world;
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.source.normal_map_file = "no/such/map.png";
  EXPECT_THROW(
      {
        try {
          world.createBody(ground);
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("no/such/map.png"), std::string::npos) << e.what();
          throw;
        }
      },
      Error);
}

// One default sampler: a world built in code uses the provider a scene gets by default.
TEST(Surface, CodeAndScenesShareTheDefaultSampler) {
  World world;
  EXPECT_EQ(world.frictionProvider().name(), std::string(kDefaultSampler));
}

}  // namespace
}  // namespace asperity
