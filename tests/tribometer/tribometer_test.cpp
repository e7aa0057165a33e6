// The tribometer's front: directions, runs side by side giving the same numbers on any thread
// count, textures named by text, and one test per kind of bad setting.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::errorOf;
using test::tribometerPair;

TEST(Tribometer, DirectionsAreEvenlySpacedFromU) {
  TribometerSettings settings = test::dragOnly(6, 0.2);
  settings.tracks = 1;
  settings.sampler = "constant";
  const TribometerResult r = runTribometer(tribometerPair("flat", "flat"), settings);
  ASSERT_EQ(r.directions.size(), 6u);
  for (int k = 0; k < 6; ++k)
    EXPECT_DOUBLE_EQ(r.directions[static_cast<size_t>(k)].angle_deg, 60.0 * k);
  // Without the tilt table there is no static coefficient; the drag gives the other two.
  EXPECT_FALSE(r.directions[0].mu_s.has_value());
  EXPECT_TRUE(r.directions[0].mu_k.has_value() && r.directions[0].mu_model.has_value());
}

TEST(Tribometer, SameNumbersOnAnyThreadCount) {
  const TribometerSurfaces surfaces = tribometerPair("gen:oak:2", "gen:sawtooth:1", 1.0, 1.0);
  TribometerSettings settings;
  settings.directions = 4;
  settings.tracks = 2;
  settings.threads = 1;
  const TribometerResult one = runTribometer(surfaces, settings);
  for (int threads : {2, 3}) {
    settings.threads = threads;
    const TribometerResult many = runTribometer(surfaces, settings);
    for (size_t k = 0; k < one.directions.size(); ++k) {
      EXPECT_EQ(one.directions[k].mu_s, many.directions[k].mu_s) << threads;
      EXPECT_EQ(one.directions[k].mu_k, many.directions[k].mu_k) << threads;
      EXPECT_EQ(one.directions[k].mu_model, many.directions[k].mu_model) << threads;
    }
  }
}

TEST(Tribometer, TextureTextNamesAFileOrAGenerator) {
  EXPECT_EQ(textureSource("maps/oak.png").normal_map_file, "maps/oak.png");
  const SurfaceSource plain = textureSource("gen:oak:7");
  EXPECT_EQ(plain.generator.name, "oak");
  EXPECT_EQ(plain.generator.seed, 7u);
  EXPECT_EQ(plain.generator.size, 256);
  EXPECT_TRUE(plain.generator.params.empty());
  const SurfaceSource with = textureSource("gen:sawtooth:3:period=16,axis=v,size=128");
  EXPECT_EQ(with.generator.params.at("period"), "16");
  EXPECT_EQ(with.generator.params.at("axis"), "v");
  EXPECT_EQ(with.generator.size, 128);
}

TEST(Tribometer, BadTextureTextsAreErrorsNamingThem) {
  EXPECT_NE(errorOf([] { textureSource("gen:oak"); }).find("'gen:oak'"), std::string::npos);
  EXPECT_NE(errorOf([] { textureSource("gen::1"); }).find("gen:NAME:SEED"), std::string::npos);
  EXPECT_NE(errorOf([] { textureSource("gen:oak:x"); }).find("seed"), std::string::npos);
  EXPECT_NE(errorOf([] { textureSource("gen:oak:1:slope"); }).find("PARAM=VALUE"),
            std::string::npos);
  Diagnostics diagnostics;
  EXPECT_NE(
      errorOf([&] { tribometerSurface("gen:nosuch:1", 1.0, 0.25, diagnostics); }).find("nosuch"),
      std::string::npos);
  EXPECT_NE(errorOf([&] {
              tribometerSurface("gen:oak:1:nosuch=1", 1.0, 0.25, diagnostics);
            }).find("nosuch"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              tribometerSurface("missing.png", 1.0, 0.25, diagnostics);
            }).find("missing.png"),
            std::string::npos);
}

TEST(Tribometer, BadSettingsAreErrorsNamingThem) {
  const TribometerSurfaces surfaces = tribometerPair("flat", "flat");
  const auto error = [&](auto change) {
    TribometerSettings settings;
    change(settings);
    return errorOf([&] { runTribometer(surfaces, settings); });
  };
  EXPECT_NE(error([](TribometerSettings& s) { s.directions = 0; }).find("directions"),
            std::string::npos);
  EXPECT_NE(error([](TribometerSettings& s) { s.load = -1.0; }).find("load"), std::string::npos);
  EXPECT_NE(error([](TribometerSettings& s) { s.block_size = std::nan(""); }).find("block_size"),
            std::string::npos);
  EXPECT_NE(error([](TribometerSettings& s) { s.tracks = 0; }).find("tracks"), std::string::npos);
  EXPECT_NE(error([](TribometerSettings& s) { s.threads = -2; }).find("threads"),
            std::string::npos);
  EXPECT_NE(error([](TribometerSettings& s) { s.sampler = "gl"; }).find("\"gl\""),
            std::string::npos);
  EXPECT_NE(error([](TribometerSettings& s) { s.spring_frequency = 100.0; }).find("spring"),
            std::string::npos);
}

}  // namespace
}  // namespace asperity
