// Height maps at physical scale (SPEC 13): generators' heights give their own normals back,
// 16-bit files keep 16 bits, the sign convention of SPEC 6, roughness statistics, bad files.
#include <gtest/gtest.h>

#include <cmath>

#include "asperity/friction/limit_surface.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "asperity/texture/height_map.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

GeneratorSpec specOf(const std::string& name, int size, std::map<std::string, std::string> p = {}) {
  GeneratorSpec spec;
  spec.name = name;
  spec.params = std::move(p);
  spec.size = size;
  spec.seed = 7;
  return spec;
}

// Largest component difference between two maps of the same size.
double maxDifference(const NormalMap& a, const NormalMap& b) {
  double worst = 0.0;
  for (size_t k = 0; k < a.texels().size(); ++k)
    worst = std::max(worst, static_cast<double>((a.texels()[k] - b.texels()[k]).cwiseAbs().maxCoeff()));
  return worst;
}

// The generator's heights written to a 16-bit PNG and read back with the stored scale.
HeightMap throughFile(const GeneratorSpec& spec, double texture_size, double& scale) {
  const std::string path = test::tempDir("heights") + "/" + spec.name + ".png";
  scale = saveHeightMapPng(generateHeightMap(spec, texture_size), path);
  HeightMapInfo info;
  HeightMap map = loadHeightMapPng(path, 0.0, &info);
  EXPECT_EQ(info.bits, 16);
  EXPECT_TRUE(info.scale_from_file);
  EXPECT_DOUBLE_EQ(info.height_scale, scale);
  return map;
}

TEST(HeightMap, GeneratorHeightsGiveTheGeneratorsNormalsWithinQuantisation) {
  // Generators whose normals are central differences of their heights, over sizes and scales.
  const std::vector<GeneratorSpec> specs = {
      specOf("concrete", 64),       specOf("roughness", 96, {{"ra_mm", "0.05"}}),
      specOf("plaster", 128),       specOf("oak", 128),
      specOf("cut_pvc", 64),        specOf("stone", 128),
      specOf("metal", 64),          specOf("acrylic", 32),
      specOf("emboss", 128)};
  for (const GeneratorSpec& spec : specs) {
    for (double texture_size : {0.01, 0.25, 3.0}) {
      double scale = 0.0;
      const HeightMap heights = throughFile(spec, texture_size, scale);
      const NormalMap derived = normalsFromHeightMap(heights, texture_size);
      // Rounding moves a height by scale / 131070; a central difference over two texels then
      // moves a slope by at most that over one texel.
      const double texel = texture_size / spec.size;
      const double tolerance = scale / 65535.0 / texel + 1e-5;
      EXPECT_LT(maxDifference(derived, generateNormalMap(spec)), tolerance)
          << spec.name << " at " << texture_size << " m";
    }
  }
}

TEST(HeightMap, TheScalesMatter) {
  // The same file read at twice the height doubles the slopes; the same heights over twice the
  // texture size halve them.
  const GeneratorSpec spec = specOf("plaster", 64);
  const std::string path = test::tempDir("heights") + "/plaster.png";
  const double scale = saveHeightMapPng(generateHeightMap(spec, 0.1), path);
  const double reference = test::meanPloughing(generateNormalMap(spec));
  const NormalMap doubled = normalsFromHeightMap(loadHeightMapPng(path, 2.0 * scale), 0.1);
  EXPECT_NEAR(test::meanPloughing(doubled), 2.0 * reference, 0.1 * reference);
  const NormalMap wider = normalsFromHeightMap(loadHeightMapPng(path), 0.2);
  EXPECT_NEAR(test::meanPloughing(wider), 0.5 * reference, 0.05 * reference);
}

BoxLimit wholeMapBox(const NormalMap& map) {
  return BoxLimit::fromDirectional(flatPatchCone(nullptr, map, PatchConeOptions{}));
}

TEST(HeightMap, ProfileHeightsKeepTheirFacets) {
  // Thread and cones sample slopes at texel centres; central differences of their heights
  // differ at the kinks only, so the whole-map box cone stays close.
  for (const std::string name : {"thread", "cones"}) {
    const GeneratorSpec spec = specOf(name, 128);
    const BoxLimit h = wholeMapBox(normalsFromHeightMap(generateHeightMap(spec, 0.128), 0.128));
    const BoxLimit n = wholeMapBox(generateNormalMap(spec));
    EXPECT_NEAR(h.mu_pos_t, n.mu_pos_t, 0.15 * n.mu_pos_t + 0.005) << name;
    EXPECT_NEAR(h.mu_neg_t, n.mu_neg_t, 0.15 * n.mu_neg_t + 0.005) << name;
    EXPECT_NEAR(h.mu_pos_b, n.mu_pos_b, 0.15 * n.mu_pos_b + 0.005) << name;
  }
}

TEST(HeightMap, ATilingHeightFieldGripsAlikeBothWaysOverWholePeriods) {
  // mu_d = (2/pi) mean max(0, -grad h . d) below mu_max, and a tiling field's slopes average
  // to zero, so mu_d = mu_-d over the whole map: the sawtooth's asymmetry (Fig. 8) needs its
  // normal map, whose facets close no height profile. Same facet angles, as a height field:
  const GeneratorSpec spec = specOf("sawtooth", 128);
  const BoxLimit h = wholeMapBox(normalsFromHeightMap(generateHeightMap(spec, 0.1), 0.1));
  EXPECT_NEAR(h.mu_pos_t, h.mu_neg_t, 0.03 * h.mu_neg_t);
  const BoxLimit n = wholeMapBox(generateNormalMap(spec));
  EXPECT_GT(n.mu_pos_t, 2.0 * n.mu_neg_t);
}

TEST(HeightMap, SignConventionMatchesNormalMaps) {
  // Heights rising toward +u tilt the normals toward -u; rising toward +v, toward -v (SPEC 6).
  HeightMap ramp(16, 16);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) ramp.at(i, j) = static_cast<float>(0.001 * std::min(i, 15 - i) + 0.003 * std::min(j, 15 - j));
  const NormalMap n = normalsFromHeightMap(ramp, 0.016);  // 1 mm texels
  // At (4, 4) the heights rise 1 mm per texel along u and 3 mm per texel along v.
  EXPECT_NEAR(n.at(4, 4).x() / n.at(4, 4).z(), -1.0, 1e-5);
  EXPECT_NEAR(n.at(4, 4).y() / n.at(4, 4).z(), -3.0, 1e-5);
  EXPECT_NEAR(n.at(11, 4).x() / n.at(11, 4).z(), 1.0, 1e-5);
}

TEST(HeightMap, SixteenBitFilesKeepSixteenBits) {
  // Levels 0..65535 step 1 along a row: every one read back distinct, in order.
  const std::string path = test::tempDir("heights") + "/levels.png";
  std::vector<uint16_t> grey(256 * 256);
  for (size_t k = 0; k < grey.size(); ++k) grey[k] = static_cast<uint16_t>(k);
  png::write(path, 256, 256, 1, 16, grey);
  const HeightMap map = loadHeightMapPng(path, 65535.0);
  for (int r = 0; r < 256; ++r)
    for (int i = 0; i < 256; ++i)
      ASSERT_FLOAT_EQ(map.at(i, 255 - r), static_cast<float>(r * 256 + i)) << i << " " << r;
}

TEST(HeightMap, EightBitFilesNeedAScale) {
  const std::string path = test::tempDir("heights") + "/eight.png";
  png::write(path, 4, 4, 1, 8, std::vector<uint16_t>(16, 51));
  EXPECT_FLOAT_EQ(loadHeightMapPng(path, 0.002).at(0, 0), 0.0004f);
  test::expectErrorContaining([&] { loadHeightMapPng(path); }, {"eight.png", "height_scale"});
}

TEST(HeightMap, BadFilesAreRefusedByName) {
  const std::string dir = test::tempDir("heights");
  png::write(dir + "/rgb.png", 4, 4, 3, 8, std::vector<uint16_t>(48, 100));
  test::expectErrorContaining([&] { loadHeightMapPng(dir + "/rgb.png", 1.0); },
                              {"rgb.png", "greyscale"});
  test::expectErrorContaining([&] { loadHeightMapPng(dir + "/missing.png", 1.0); },
                              {"missing.png"});
  test::expectErrorContaining([] { generateHeightMap(specOf("gaussian", 8), 0.1); },
                              {"gaussian", "no height field"});
}

TEST(HeightStats, SinusoidMatchesItsClosedForms) {
  // h = A cos(2 pi k i / N) along u: Ra = 2A / pi, Rq = A / sqrt 2, rms slope from the central
  // difference sin(w) / w of the true A w / sqrt 2, correlation 1/e at acos(1/e) / w.
  for (int k : {2, 5}) {
    const int n = 512;
    const double size = 0.5, amp = 1e-4;
    HeightMap map(n, 8);
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < n; ++i)
        map.at(i, j) = static_cast<float>(amp * std::cos(2 * kPi * k * i / n));
    const HeightStats s = heightStats(map, size);
    const double w = 2 * kPi * k / n;          // radians per texel
    const double texel = size / n;
    EXPECT_NEAR(s.ra, 2 * amp / kPi, 1e-3 * amp);
    EXPECT_NEAR(s.rq, amp / std::sqrt(2.0), 1e-3 * amp);
    EXPECT_NEAR(s.rms_slope, amp * std::sin(w) / texel / std::sqrt(2.0), 1e-3 * s.rms_slope);
    // v is constant: its autocorrelation is 1, so the mean of u and v falls to 1/e where
    // cos(w lag) = 2/e - 1.
    EXPECT_NEAR(s.correlation_length, std::acos(2.0 / std::exp(1.0) - 1.0) / w * texel,
                0.02 * s.correlation_length);
  }
}

}  // namespace
}  // namespace asperity
