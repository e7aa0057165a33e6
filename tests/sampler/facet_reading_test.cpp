// Facet-true reading (FrictionSettings::texel_reading): each patch pixel reads the facet of the
// texel its centre falls in. On a flat slab the patch sampler's mean over positions spread
// across a texture is then the whole-texture cone (each texel's Eq. 5 averaged: flatPatchCone),
// for every generator and every texture the repository's scenes use, at those scenes' patch
// settings. The blended reading, kept as an option, reads rough maps well below their facets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/texture/generators.hpp"
#include "sampler_suite.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"

namespace asperity {
namespace {

using sampler_test::boxBody;
using sampler_test::contactAt;
using sampler_test::planeBody;

// A texture as a scene lays it on a surface, and the patch settings it is sampled with.
struct Texture {
  std::string name;
  std::shared_ptr<const NormalMap> map;
  double texture_size = 0.256;  // m per repeat
  FrictionSettings settings;
};

// The mean of the plane's Eq. 8 term (mu0 0, gain 1, a flat box above) over patches whose
// centres are spread evenly over one repeat of the texture (an R2 low-discrepancy sequence:
// every offset within a texel is met, whatever the texture's period), enough of them to cover
// the repeat four times over (a sparse logo is met as often as its share of the texture).
DirectionalMu meanOverTexture(const Texture& t, TexelReading reading) {
  const double repeats = t.texture_size / t.settings.patch_width;
  const int count = std::clamp(static_cast<int>(std::ceil(4.0 * repeats * repeats)), 256, 50000);
  FrictionSettings s = t.settings;
  s.mu0 = 0.0;
  s.reuse_pixels = 0.0;
  s.texel_reading = reading;
  const double h = std::max(0.1, t.settings.patch_width);  // the box's face covers every patch
  std::vector<Body> bodies{planeBody(t.map, t.texture_size, 1.0)};
  std::vector<Contact> contacts;
  for (int n = 0; n < count; ++n) {
    const double x = std::fmod(0.5 + 0.7548776662466927 * n, 1.0) * t.texture_size;
    const double y = std::fmod(0.5 + 0.5698402909980532 * n, 1.0) * t.texture_size;
    const Vec3 point(x, y, 0.0);
    bodies.push_back(boxBody(Vec3(h, h, h), Transform{point + Vec3(0, 0, h)}, nullptr, 1.0, 0.0));
    Contact c = contactAt(point, 0.0);
    c.body_a = static_cast<BodyId>(bodies.size() - 1);
    contacts.push_back(c);
  }
  CpuPatchSampler sampler;
  sampler.computeCoefficients(bodies, contacts, s);
  std::vector<double> sums(static_cast<size_t>(s.directions), 0.0);
  for (const Contact& c : contacts) {
    EXPECT_EQ(c.covered_pixels, s.patch_resolution * s.patch_resolution) << t.name;
    for (int k = 0; k < s.directions; ++k) sums[static_cast<size_t>(k)] += c.mu.mu[k];
  }
  DirectionalMu mean;
  mean.count = s.directions;
  for (int k = 0; k < s.directions; ++k)
    mean.mu[k] = static_cast<float>(sums[static_cast<size_t>(k)] / count);
  return mean;
}

DirectionalMu wholeTextureCone(const Texture& t) {
  PatchConeOptions opt;
  opt.directions = t.settings.directions;
  opt.gains = {0.0, 1.0, 1.0};
  opt.mu_max = t.settings.mu_max;
  return flatPatchCone(nullptr, *t.map, opt);
}

// Within 3 % of the cone in every direction (1e-3 absolute for the directions in which the
// cone is nearly 0, such as along a sawtooth's ridges).
void expectFacetTrue(const Texture& t) {
  const DirectionalMu cone = wholeTextureCone(t), patch = meanOverTexture(t, TexelReading::Nearest);
  double worst = 0.0;
  for (int k = 0; k < cone.count; ++k) {
    EXPECT_TRUE(test::near(patch.mu[k], cone.mu[k], 0.03, 1e-3))
        << t.name << " direction " << k << ": patch " << patch.mu[k] << ", cone " << cone.mu[k];
    if (cone.mu[k] > 1e-3) worst = std::max(worst, std::abs(patch.mu[k] / cone.mu[k] - 1.0));
  }
  std::printf("[ facets ] %-40s cone mu_t %.4f patch %.4f (worst direction %.2f %%)\n",
              t.name.c_str(), cone.mu[0], patch.mu[0], 100.0 * worst);
}

// A grey PNG height map of a few superposed waves, for the generators that read one.
std::string heightFile() {
  const int size = 128;
  std::vector<uint16_t> grey(static_cast<size_t>(size * size));
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double a = 2.0 * kPi * i / size, b = 2.0 * kPi * j / size;
      const double h = 0.5 + 0.2 * std::sin(3 * a) * std::cos(5 * b) + 0.2 * std::sin(7 * a + 2 * b);
      grey[static_cast<size_t>(j * size + i)] = static_cast<uint16_t>(std::lround(65535.0 * h));
    }
  }
  const std::string path = test::tempDir("facets") + "/waves.png";
  png::write(path, size, size, 1, 16, grey);
  return path;
}

TEST(FacetReading, EveryGeneratorsPatchMeanIsItsWholeTextureCone) {
  // Each generator at its defaults, 256 texels over 0.256 m (1 mm texels), the default patch.
  const std::string heights = heightFile();
  for (const GeneratorInfo& info : generatorCatalog()) {
    GeneratorSpec spec;
    spec.name = info.name;
    spec.seed = 7;
    for (const GeneratorParam& p : info.params) {
      if (p.kind == "path") spec.params[p.name] = heights;
      // A physical height map's scale: 0.5 mm of relief (its default reads the file's own).
      if (p.name == "height_scale" && p.default_value == "0") spec.params[p.name] = "0.0005";
    }
    Texture t;
    t.name = "generator " + info.name;
    t.map = std::make_shared<NormalMap>(generateNormalMap(spec));
    expectFacetTrue(t);
  }
}

TEST(FacetReading, EveryScenesTexturesPatchMeanIsItsWholeTextureCone) {
  // Every normal map of every scene in the repository, on a slab at its surface's texture size,
  // sampled with that scene's N, w and R.
  std::vector<std::string> scenes;
  for (const char* folder : {"scenes", "scenes/examples"}) {
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath(folder)))
      if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
  }
  std::sort(scenes.begin(), scenes.end());
  int textures = 0;
  for (const std::string& path : scenes) {
    SCOPED_TRACE(path);
    std::unique_ptr<World> world;
    ASSERT_NO_THROW(world = instantiate(loadScene(path)));
    std::map<const NormalMap*, bool> seen;
    for (const Body& body : world->bodies()) {
      for (const Shape& shape : body.shapes) {
        const auto& map = shape.surface.normal_map;
        if (!map || map->empty() || seen[map.get()]) continue;
        seen[map.get()] = true;
        Texture t;
        t.name = std::filesystem::path(path).filename().string() + " " + body.name;
        t.map = map;
        t.texture_size = shape.surface.texture_size > 0.0 ? shape.surface.texture_size : 1.0;
        t.settings = world->settings().friction;
        expectFacetTrue(t);
        ++textures;
      }
    }
  }
  EXPECT_GE(textures, 20);
}

TEST(FacetReading, TheBlendedReadingReadsRoughMapsLow) {
  // The option keeps the blend to show its bias: on concrete (1 mm texels of Ra 1 mm) a
  // bilinear blend flattens the facets before Eq. 5 and reads about 40 % low.
  GeneratorSpec spec;
  spec.name = "concrete";
  Texture t;
  t.name = "concrete";
  t.map = std::make_shared<NormalMap>(generateNormalMap(spec));
  const DirectionalMu cone = wholeTextureCone(t);
  const DirectionalMu blended = meanOverTexture(t, TexelReading::Bilinear);
  for (int k = 0; k < cone.count; ++k) {
    EXPECT_LT(blended.mu[k], 0.75 * cone.mu[k]) << "direction " << k;
    EXPECT_GT(blended.mu[k], 0.4 * cone.mu[k]) << "direction " << k;
  }
}

TEST(FacetReading, EachPixelReadsTheTexelItsCentreFallsIn) {
  // A 4 x 4 map of distinct facets over a 4 mm repeat, a 4 x 4 patch of 1 mm pixels whose
  // centres sit 0.3 mm past each texel's lower corner: nearest gives each texel's own normal;
  // the blend mixes in the neighbours.
  auto map = std::make_shared<NormalMap>(4, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      map->at(i, j) = Vec3f(0.2f * static_cast<float>(i) - 0.3f,
                            0.15f * static_cast<float>(j) - 0.2f, 1.0f)
                          .normalized();
  const double size = 0.004, h = 0.1;
  // Pixel (i, j) centre at x = -2 mm + (i + 0.5) mm from the contact point, so the contact
  // point at 1.8 mm puts it at (i + 0.3) mm: texel i.
  const Vec3 point(0.0018, 0.0018, 0.0);
  std::vector<Body> bodies{planeBody(map, size, 1.0),
                           boxBody(Vec3(h, h, h), Transform{point + Vec3(0, 0, h)}, nullptr, 1.0,
                                   0.0)};
  Contact contact = contactAt(point, 0.0);
  for (const TexelReading reading : {TexelReading::Nearest, TexelReading::Bilinear}) {
    FrictionSettings s = sampler_test::settings(4, 4, size, 0.0);
    s.texel_reading = reading;
    CpuPatchSampler sampler;
    PatchImages images;
    sampler.sampleContact(bodies, contact, s, &images);
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        const Vec3f got = images.normals[1][static_cast<size_t>(j * 4 + i)];
        const double apart = (got - map->at(i, j)).norm();
        if (reading == TexelReading::Nearest) {
          EXPECT_LT(apart, 1e-6) << "pixel " << i << ", " << j;
        } else {
          EXPECT_GT(apart, 1e-3) << "pixel " << i << ", " << j;
        }
      }
    }
  }
}

TEST(FacetReading, SceneKeyRejectsUnknownReadings) {
  const nlohmann::json scene = nlohmann::json::parse(R"({"settings": {"texel_reading": "trilinear"},
    "bodies": [{"name": "ground", "type": "static", "shapes": [{"type": "plane"}]}]})");
  try {
    parseScene(scene, "reading.json");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("texel_reading"), std::string::npos) << what;
    EXPECT_NE(what.find("trilinear"), std::string::npos) << what;
    EXPECT_NE(what.find("nearest"), std::string::npos) << what;
    EXPECT_NE(what.find("bilinear"), std::string::npos) << what;
  }
  const SceneDesc blended = parseScene(nlohmann::json::parse(R"({
    "settings": {"texel_reading": "bilinear"},
    "bodies": [{"name": "ground", "type": "static", "shapes": [{"type": "plane"}]}]})"),
                                       "reading.json");
  EXPECT_EQ(blended.settings.friction.texel_reading, TexelReading::Bilinear);
  EXPECT_EQ(FrictionSettings{}.texel_reading, TexelReading::Nearest);
}

}  // namespace
}  // namespace asperity
