// The contact-area friction model in the CPU sampler (SPEC 13, docs/contact-area.md): its
// coefficients against the offline contact-area solver (what `asperity contact-area`
// computes), Amontons from the model, and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/contact_area/mechanical.hpp"
#include "asperity/error.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "sampler/sampler_suite.hpp"

namespace asperity::sampler_test {
namespace {

constexpr int kR = 64;        // patch pixels per side, and the plane's texels per repeat
constexpr double kW = 0.02;   // patch width, and the plane's texture size (m)
constexpr double kDt = 0.01;  // s

GeneratorSpec plaster(uint64_t seed) {
  GeneratorSpec spec;
  spec.name = "plaster";
  spec.size = kR;
  spec.seed = seed;
  return spec;
}

// A rough acrylic plane (plaster: normals and heights from one generator) under a flat steel
// box bottom; one texel per patch pixel, texel centres on pixel centres.
Scene roughPlaneFlatBox(uint64_t seed) {
  Body plane = planeBody(std::make_shared<NormalMap>(generateNormalMap(plaster(seed))), kW, 1.5);
  plane.shapes[0].surface.source.generator = plaster(seed);
  plane.shapes[0].surface.mechanical = findMechanical("acrylic");
  Body box = boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0);
  box.shapes[0].surface.mechanical = findMechanical("steel");
  return {{plane, box}, contactAt(Vec3::Zero(), 1e-5)};
}

FrictionModelSettings areaModel() {
  FrictionModelSettings m;
  m.model = FrictionModel::ContactArea;
  m.dt = kDt;
  return m;
}

// The model's mu per direction at load W on the rough plane.
DirectionalMu modelMu(double load, uint64_t seed, PatchImages* images = nullptr) {
  Scene scene = roughPlaneFlatBox(seed);
  scene.contact.lambda_n = load * kDt;
  CpuPatchSampler sampler;
  sampler.setFrictionModels(areaModel());
  sampler.sampleContact(scene.bodies, scene.contact, settings(8, kR, kW), images);
  return scene.contact.mu;
}

// The oracle: the plane's heights (the pixel at the patch centre, x = 0, is the texel edge
// u = 0, so pixel i holds texel (i + R/2) mod R) solved offline as `asperity contact-area`
// does with the pair's materials, adhesion tau A_r / W, plus the gain times the mean of the
// plane's per-pixel Eq. 5 coefficients over the texels the offline solver has in contact.
TEST(ContactAreaModel, MatchesTheOfflineSolverPlusPloughingOverTheContact) {
  for (const uint64_t seed : {3u, 4u}) {
    for (const double load : {50.0, 500.0}) {
      const HeightMap h = generateHeightMap(plaster(seed), kW);
      HeightMap shifted(kR, kR);
      for (int j = 0; j < kR; ++j)
        for (int i = 0; i < kR; ++i) shifted.at(i, j) = h.at((i + kR / 2) % kR, (j + kR / 2) % kR);
      const SummitSet set = findSummits(shifted, nullptr, kW);
      const Mechanical& steel = findMechanical("steel");
      const Mechanical& acrylic = findMechanical("acrylic");
      const ContactArea area = solveContact(set, contactPair(steel, acrylic), load);
      const std::vector<unsigned char> mask = contactMask(set, area);
      const double adhesion = adhesionFriction(pairShear(steel, acrylic), area);

      PatchImages images;
      const DirectionalMu mu = modelMu(load, seed, &images);
      ASSERT_EQ(images.resolution, kR);
      int touching = 0;
      std::vector<double> mean(8, 0.0);
      for (size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        ++touching;
        for (size_t k = 0; k < 8; ++k) mean[k] += images.mu[1][p * 8 + k];
      }
      ASSERT_GT(touching, 0);
      ASSERT_LT(touching, kR * kR / 2) << "a light load touches a small share";
      EXPECT_EQ(images.in_patch.size(), mask.size());
      // Over the whole of P instead, the ploughing term would differ: the oracle can tell.
      std::vector<double> over_p(8, 0.0);
      for (size_t p = 0; p < mask.size(); ++p)
        for (size_t k = 0; k < 8; ++k) over_p[k] += images.mu[1][p * 8 + k];
      double worst_if_over_p = 0.0;
      for (size_t k = 0; k < 8; ++k) {
        const double expected = adhesion + 1.5 * mean[k] / touching;
        EXPECT_NEAR(mu.mu[k], expected, 1e-3 * expected) << seed << " " << load << " " << k;
        worst_if_over_p =
            std::max(worst_if_over_p,
                     std::abs(adhesion + 1.5 * over_p[k] / (kR * kR) - expected) / expected);
      }
      EXPECT_GT(worst_if_over_p, 0.01);
      EXPECT_GT(adhesion, 0.05);
      std::printf("seed %d load %.0f N: A_r/A_0 %.4f, %d of %d pixels, adhesion %.4f, mu[0] %.4f\n",
                  static_cast<int>(seed), load, area.fraction, touching, kR * kR, adhesion,
                  static_cast<double>(mu.mu[0]));
    }
  }
}

// Amontons from the model: over a decade of load the coefficient moves by far less than the
// load (A_r grows with W), and stays below the paper's mu_max cap.
TEST(ContactAreaModel, CoefficientHardlyDependsOnLoadOverADecade) {
  for (const uint64_t seed : {3u, 5u}) {
    const DirectionalMu light = modelMu(30.0, seed), heavy = modelMu(300.0, seed);
    for (size_t k = 0; k < 8; ++k) {
      EXPECT_GT(heavy.mu[k], 0.0f);
      EXPECT_NEAR(heavy.mu[k] / light.mu[k], 1.0, 0.3) << seed << " " << k;
      EXPECT_LT(heavy.mu[k], 4.0f);
    }
  }
}

// A new contact (no previous impulse) is taken at a light load: a finite coefficient.
TEST(ContactAreaModel, NewContactGetsTheLightLoadCoefficient) {
  const DirectionalMu none = modelMu(0.0, 3), light = modelMu(1.0, 3);
  for (size_t k = 0; k < 8; ++k) {
    EXPECT_GT(none.mu[k], 0.0f);
    EXPECT_NEAR(none.mu[k], light.mu[k], 0.3 * light.mu[k]);
  }
}

// A surface without mechanical values cannot take part: the error names it.
TEST(ContactAreaModel, SurfaceWithoutMechanicalValuesIsAnError) {
  Scene scene = roughPlaneFlatBox(3);
  scene.bodies[0].shapes[0].surface.mechanical.reset();
  CpuPatchSampler sampler;
  sampler.setFrictionModels(areaModel());
  try {
    sampler.sampleContact(scene.bodies, scene.contact, settings(8, kR, kW));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("body 0 shape 0 has no mechanical values"),
              std::string::npos)
        << e.what();
  }
}

// The paper's model ignores the mechanical values and the load.
TEST(ContactAreaModel, PaperModelIsUnchangedByTheAreaOptions) {
  Scene a = roughPlaneFlatBox(3), b = roughPlaneFlatBox(3);
  b.contact.lambda_n = 5.0;
  for (Body& body : a.bodies) body.shapes[0].surface.mechanical.reset();
  FrictionModelSettings paper = areaModel();
  paper.model = FrictionModel::Paper;
  CpuPatchSampler plain, with_options;
  with_options.setFrictionModels(paper);
  plain.sampleContact(a.bodies, a.contact, settings(8, kR, kW));
  with_options.sampleContact(b.bodies, b.contact, settings(8, kR, kW));
  for (size_t k = 0; k < 8; ++k) EXPECT_EQ(a.contact.mu.mu[k], b.contact.mu.mu[k]);
}

}  // namespace
}  // namespace asperity::sampler_test
