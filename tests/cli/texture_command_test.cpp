// `asperity texture`: the catalog listing, PNG output identical to the library's generator,
// determinism, and one test per kind of bad input (non-zero exit, one stderr line).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "asperity/texture/generators.hpp"
#include "asperity/texture/png_io.hpp"
#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;
using test::slurpBinary;

// Largest component difference between two maps of equal size.
float maxDifference(const NormalMap& a, const NormalMap& b) {
  float worst = 0.0f;
  for (size_t i = 0; i < a.texels().size(); ++i)
    worst = std::max(worst, (a.texels()[i] - b.texels()[i]).cwiseAbs().maxCoeff());
  return worst;
}

TEST(TextureCommand, ListShowsEveryGeneratorAndParameter) {
  const auto r = runCli({"texture", "--list"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_FALSE(generatorCatalog().empty());
  for (const GeneratorInfo& g : generatorCatalog()) {
    EXPECT_NE(r.out.find(g.name + "  "), std::string::npos) << g.name;
    for (const GeneratorParam& p : g.params)
      EXPECT_NE(r.out.find("--" + p.name + "  default " + p.default_value), std::string::npos)
          << g.name << " --" << p.name;
  }
}

TEST(TextureCommand, WritesTheGeneratorsMapWithItsParameters) {
  const std::string out = test::tempDir("tex") + "/g.png";
  const auto r = runCli({"texture", "gaussian", "--sx", "0.1", "--sy=0.5", "--size", "64", "--seed",
                         "7", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const NormalMap written = loadNormalMapPng(out);
  ASSERT_EQ(written.width(), 64);
  ASSERT_EQ(written.height(), 64);
  // The file holds the library's map for the same spec, up to 8-bit quantisation.
  const NormalMap expected = generateNormalMap({"gaussian", {{"sx", "0.1"}, {"sy", "0.5"}}, 64, 7});
  EXPECT_LT(maxDifference(written, expected), 0.02f);
}

TEST(TextureCommand, SixteenBitsAndDirectXRoundTrip) {
  const std::string dir = test::tempDir("tex");
  const auto r = runCli({"texture", "sawtooth", "--axis", "90", "--size", "32", "--bits", "16",
                         "--directx", "--out", dir + "/s.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const NormalMap expected = generateNormalMap({"sawtooth", {{"axis", "90"}}, 32, 1});
  // Read back with the same convention: equal to 16-bit precision.
  EXPECT_LT(maxDifference(loadNormalMapPng(dir + "/s.png", GreenConvention::DirectX), expected),
            1e-3f);
  // Read as OpenGL: the bitangent component is flipped.
  const NormalMap as_gl = loadNormalMapPng(dir + "/s.png");
  EXPECT_NEAR(as_gl.at(3, 5).y(), -expected.at(3, 5).y(), 1e-3f);
}

TEST(TextureCommand, SameSeedGivesIdenticalBytes) {
  const std::string dir = test::tempDir("tex");
  for (const char* name : {"a.png", "b.png"})
    ASSERT_EQ(
        runCli({"texture", "gaussian", "--size", "48", "--seed", "3", "--out", dir + "/" + name})
            .exit_code,
        0);
  ASSERT_EQ(runCli({"texture", "gaussian", "--size", "48", "--seed", "4", "--out", dir + "/c.png"})
                .exit_code,
            0);
  const std::string a = slurpBinary(dir + "/a.png");
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, slurpBinary(dir + "/b.png"));
  EXPECT_NE(a, slurpBinary(dir + "/c.png"));
}

TEST(TextureCommand, DefaultsAreSize256Seed1) {
  const std::string out = test::tempDir("tex") + "/d.png";
  ASSERT_EQ(runCli({"texture", "gaussian", "--out", out}).exit_code, 0);
  const NormalMap written = loadNormalMapPng(out);
  EXPECT_EQ(written.width(), 256);
  EXPECT_LT(maxDifference(written, generateNormalMap({"gaussian", {}, 256, 1})), 0.02f);
}

TEST(TextureCommand, UnknownGeneratorIsNamed) {
  const std::string out = test::tempDir("tex") + "/x.png";
  expectOneLineError(runCli({"texture", "no_such_generator", "--out", out}), "no_such_generator");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(TextureCommand, UnknownParameterIsNamed) {
  const std::string out = test::tempDir("tex") + "/x.png";
  expectOneLineError(runCli({"texture", "gaussian", "--roughnes", "1", "--out", out}), "roughnes");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(TextureCommand, BadParameterValueIsNamed) {
  const std::string out = test::tempDir("tex") + "/x.png";
  expectOneLineError(runCli({"texture", "gaussian", "--sx", "nan", "--out", out}), "sx");
  expectOneLineError(runCli({"texture", "gaussian", "--sx", "-1", "--out", out}), "sx");
  expectOneLineError(runCli({"texture", "gaussian", "--sx", "--out", out}), "sx");
}

TEST(TextureCommand, BadSizeIsNamed) {
  const std::string out = test::tempDir("tex") + "/x.png";
  for (const char* size : {"nan", "-4", "0", "100000", "12.5"})
    expectOneLineError(runCli({"texture", "gaussian", "--size", size, "--out", out}), "--size");
}

TEST(TextureCommand, BadSeedIsNamed) {
  const std::string out = test::tempDir("tex") + "/x.png";
  for (const char* seed : {"-1", "nan", "1.5"})
    expectOneLineError(runCli({"texture", "gaussian", "--seed", seed, "--out", out}), "--seed");
}

TEST(TextureCommand, BadBitsIsNamed) {
  const std::string out = test::tempDir("tex") + "/x.png";
  expectOneLineError(runCli({"texture", "gaussian", "--bits", "12", "--out", out}), "--bits");
}

TEST(TextureCommand, MissingGeneratorOrOutputIsNamed) {
  expectOneLineError(runCli({"texture", "--size", "8"}), "GENERATOR");
  expectOneLineError(runCli({"texture", "gaussian"}), "--out");
}

TEST(TextureCommand, UnwritableOutputIsNamed) {
  const std::string out = test::tempDir("tex") + "/no/such/folder/x.png";
  expectOneLineError(runCli({"texture", "gaussian", "--size", "8", "--out", out}), out);
}

TEST(TextureInspect, JsonHasEveryKeyAndTheVerdict) {
  // A generated relief saved as OpenGL reads "opengl"; saved as DirectX, "directx".
  const std::string dir = test::tempDir("inspect");
  ASSERT_EQ(runCli({"texture", "stone", "--size", "64", "--out", dir + "/gl.png"}).exit_code, 0);
  ASSERT_EQ(
      runCli({"texture", "stone", "--size", "64", "--directx", "--out", dir + "/dx.png"}).exit_code,
      0);
  const auto gl = runCli({"texture", "inspect", dir + "/gl.png", "--json"});
  ASSERT_EQ(gl.exit_code, 0) << gl.err;
  const auto j = nlohmann::json::parse(gl.out);
  for (const char* key :
       {"width", "height", "bits", "invalid_fraction", "convention", "mean_slope", "box"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["width"], 64);
  EXPECT_EQ(j["bits"], 8);
  EXPECT_EQ(j["invalid_fraction"], 0.0);
  EXPECT_EQ(j["convention"], "opengl");
  EXPECT_GT(j["mean_slope"].get<double>(), 0.0);
  EXPECT_TRUE(j["box"].contains("+t"));
  const auto dx = runCli({"texture", "inspect", dir + "/dx.png", "--json"});
  EXPECT_EQ(nlohmann::json::parse(dx.out)["convention"], "directx");
}

TEST(TextureInspect, MissingFileIsOneLineError) {
  expectOneLineError(runCli({"texture", "inspect", "/nonexistent/map.png"}),
                     "/nonexistent/map.png");
}

}  // namespace
}  // namespace asperity
