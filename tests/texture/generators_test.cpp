// Generator catalog: every generator documented, deterministic for a seed, and every kind of bad
// request rejected with a message naming the generator and parameter.
#include "asperity/texture/generators.hpp"

#include <gtest/gtest.h>

#include <set>

#include "asperity/texture/png_io.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

using test::expectErrorContaining;
using test::generate;

// Generators whose output does not depend on the seed.
const std::set<std::string> kDeterministic = {"sawtooth", "thread",    "cones",
                                              "heightmap", "height_map", "emboss"};

// A small grayscale height map for the heightmap generator.
std::string heightmapFile() {
  const std::string path = test::tempDir("gen") + "/bump.png";
  std::vector<uint16_t> grey(16 * 16);
  for (size_t k = 0; k < grey.size(); ++k) grey[k] = static_cast<uint16_t>((k * 37) % 256);
  png::write(path, 16, 16, 1, 8, grey);
  return path;
}

GeneratorSpec specFor(const GeneratorInfo& info, uint64_t seed, const std::string& file) {
  GeneratorSpec spec;
  spec.name = info.name;
  spec.size = 64;
  spec.seed = seed;
  if (info.name == "heightmap" || info.name == "height_map") spec.params["file"] = file;
  if (info.name == "height_map") spec.params["height_scale"] = "0.001";  // 8 bits store none
  return spec;
}

TEST(Generators, CatalogHoldsEveryGeneratorOfSpec6WithDocumentedParameters) {
  std::set<std::string> names;
  for (const GeneratorInfo& info : generatorCatalog()) {
    names.insert(info.name);
    EXPECT_FALSE(info.doc.empty()) << info.name;
    for (const GeneratorParam& p : info.params) {
      EXPECT_FALSE(p.doc.empty()) << info.name << "." << p.name;
      EXPECT_TRUE(p.kind == "number" || p.kind == "path") << info.name << "." << p.name;
      if (p.kind == "number") {
        // Defaults are valid numbers inside their own range.
        const double d = std::stod(p.default_value);
        EXPECT_GE(d, p.min) << info.name << "." << p.name;
        EXPECT_LE(d, p.max) << info.name << "." << p.name;
      }
    }
  }
  for (const char* expected : {"gaussian", "sawtooth", "roughness", "concrete", "cast_iron",
                               "steel", "heightmap", "emboss", "thread", "cones", "acrylic", "oak",
                               "cut_pvc", "plaster", "stone", "metal", "plastic"}) {
    EXPECT_TRUE(names.count(expected)) << expected;
  }
}

TEST(Generators, EveryGeneratorIsDeterministicForASeed) {
  const std::string file = heightmapFile();
  for (const GeneratorInfo& info : generatorCatalog()) {
    const NormalMap a = generateNormalMap(specFor(info, 5, file));
    const NormalMap b = generateNormalMap(specFor(info, 5, file));
    const NormalMap c = generateNormalMap(specFor(info, 6, file));
    ASSERT_FALSE(a.empty()) << info.name;
    EXPECT_EQ(a.texels(), b.texels()) << info.name << ": same seed, different texels";
    if (kDeterministic.count(info.name)) {
      EXPECT_EQ(a.texels(), c.texels()) << info.name << " has no randomness";
    } else {
      EXPECT_NE(a.texels(), c.texels()) << info.name << ": seed has no effect";
    }
    // Every texel is a unit vector facing out of the surface.
    for (const Vec3f& m : a.texels()) {
      ASSERT_TRUE(test::near(m.norm(), 1.0, 1e-5)) << info.name;
      ASSERT_GT(m.z(), 0.0f) << info.name;
    }
  }
}

TEST(Generators, SizeSetsTheMapSize) {
  const NormalMap map = generate("gaussian", {}, 37);
  EXPECT_EQ(map.width(), 37);
  EXPECT_EQ(map.height(), 37);
  EXPECT_EQ(generate("emboss", {}, 1).texels().size(), 1u);
}

TEST(GeneratorErrors, UnknownGenerator) {
  expectErrorContaining([] { generate("velvet"); },
                        {"texture generator 'velvet'", "unknown generator", "gaussian"});
}

TEST(GeneratorErrors, UnknownParameter) {
  expectErrorContaining(
      [] {
        generate("gaussian", {{"sz", "1"}});
      },
      {"texture generator 'gaussian'", "unknown parameter 'sz'", "sx, sy"});
}

TEST(GeneratorErrors, NonNumber) {
  expectErrorContaining(
      [] {
        generate("gaussian", {{"sx", "abc"}});
      },
      {"texture generator 'gaussian': parameter 'sx' must be a number in [0, 100], got 'abc'"});
  for (const char* bad : {"", " 1", "1 ", "1.5x", "0x10", "1,5", "--1"}) {
    expectErrorContaining(
        [&] {
          generate("gaussian", {{"sy", bad}});
        },
        {"'gaussian'", "parameter 'sy'", std::string("got '") + bad + "'"});
  }
}

TEST(GeneratorErrors, NaNAndInfinity) {
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e999"}) {
    expectErrorContaining(
        [&] {
          generate("sawtooth", {{"period", bad}});
        },
        {"'sawtooth'", "parameter 'period'", bad});
  }
}

TEST(GeneratorErrors, NegativeAndOutOfRange) {
  expectErrorContaining(
      [] {
        generate("gaussian", {{"sx", "-0.5"}});
      },
      {"parameter 'sx' must be a number in [0, 100], got '-0.5'"});
  expectErrorContaining(
      [] {
        generate("gaussian", {{"sx", "100.5"}});
      },
      {"parameter 'sx'", "got '100.5'"});
  expectErrorContaining(
      [] {
        generate("roughness", {{"texel_mm", "0"}});
      },
      {"'roughness'", "parameter 'texel_mm'", "got '0'"});
  expectErrorContaining(
      [] {
        generate("sawtooth", {{"ramp_angle", "90"}});
      },
      {"'sawtooth'", "parameter 'ramp_angle'", "[0, 89]"});
  expectErrorContaining(
      [] {
        generate("stone", {{"octaves", "2.5"}});
      },
      {"'stone'", "parameter 'octaves'", "whole number", "got '2.5'"});
}

TEST(GeneratorErrors, BadAxis) {
  expectErrorContaining(
      [] {
        generate("sawtooth", {{"axis", "w"}});
      },
      {"'sawtooth'", "parameter 'axis'", "'u', 'v'", "got 'w'"});
  expectErrorContaining(
      [] {
        generate("thread", {{"axis", "400"}});
      },
      {"'thread'", "parameter 'axis'", "got '400'"});
}

TEST(GeneratorErrors, BadSize) {
  for (int size : {0, -3, kMaxTextureSize + 1}) {
    expectErrorContaining(
        [&] { generate("gaussian", {}, size); },
        {"'gaussian'", "size must be in [1, 8192]", "got " + std::to_string(size)});
  }
}

TEST(GeneratorErrors, HeightmapFile) {
  expectErrorContaining([] { generate("heightmap"); },
                        {"'heightmap'", "parameter 'file' is required"});
  expectErrorContaining(
      [] {
        generate("heightmap", {{"file", "/nonexistent/h.png"}});
      },
      {"'heightmap'", "parameter 'file'", "/nonexistent/h.png", "cannot open"});
}

}  // namespace
}  // namespace asperity
