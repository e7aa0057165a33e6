// The real area of contact against SPEC 13: Gaussian random surfaces of known rms slope, light
// loads (A_r / A_0 = kappa p / (E* h'_rms), kappa in [1.6, 2.5]), proportionality to load,
// the plasticity index, full contact above H A_0, bad input, and speed.
#include <gtest/gtest.h>

#include <cmath>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/error.hpp"
#include "asperity/math/types.hpp"
#include "contact_area/gaussian_surface.hpp"

namespace asperity {
namespace {

using test::gaussianSurface;

constexpr double kSize = 1e-3;     // 1 mm patch
constexpr double kModulus = 1e11;  // E* (Pa)
constexpr double kSlope = 0.1;     // h'_rms

// kappa = (A_r / A_0) E* h'_rms / p.
double kappaAt(const SummitSet& set, double fraction_target) {
  // The load at which the fraction is about the target, from the light-load relation with
  // kappa = 2, then kappa measured there.
  const double pressure = fraction_target * kModulus * kSlope / 2.0;
  const ContactArea r = solveContact(set, {kModulus, 0.0}, pressure * set.apparent_area);
  return r.fraction * kModulus * kSlope / pressure;
}

class GaussianSurfaces : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    for (unsigned seed : {1u, 2u, 3u}) {
      surfaces_.push_back(gaussianSurface(256, kSize, kSlope, seed, 4.0, 32.0));
    }
  }
  static std::vector<HeightMap> surfaces_;
};
std::vector<HeightMap> GaussianSurfaces::surfaces_;

TEST_F(GaussianSurfaces, LightLoadsFollowKappaBetweenPerssonAndBush) {
  for (const HeightMap& h : surfaces_) {
    const SummitSet set = findSummits(h, nullptr, kSize);
    for (double fraction : {0.005, 0.01, 0.02}) {
      const double kappa = kappaAt(set, fraction);
      EXPECT_GE(kappa, std::sqrt(8.0 / kPi)) << "fraction " << fraction;
      EXPECT_LE(kappa, std::sqrt(2.0 * kPi)) << "fraction " << fraction;
    }
  }
}

TEST_F(GaussianSurfaces, RealAreaIsProportionalToLoadOverTwoDecades) {
  for (const HeightMap& h : surfaces_) {
    const SummitSet set = findSummits(h, nullptr, kSize);
    const double w0 = 1e-4 * kModulus * kSlope * set.apparent_area;  // A_r / A_0 ~ 2e-4
    const ContactArea light = solveContact(set, {kModulus, 0.0}, w0);
    const ContactArea heavy = solveContact(set, {kModulus, 0.0}, 100.0 * w0);
    ASSERT_GT(light.summits_in_contact, 3);
    EXPECT_NEAR(heavy.real_area / light.real_area, 100.0, 30.0);
    // And the area really grows: 100 times the load, far more than 10 times the area.
    EXPECT_GT(heavy.summits_in_contact, 10 * light.summits_in_contact);
  }
}

TEST_F(GaussianSurfaces, TwoRoughSurfacesAddTheirRoughness) {
  // A against B: the composite is rougher than either, so less area at the same load.
  const SummitSet one = findSummits(surfaces_[0], nullptr, kSize);
  const SummitSet two = findSummits(surfaces_[0], &surfaces_[1], kSize);
  const double w = 1e-3 * kModulus * kSlope * one.apparent_area;
  EXPECT_LT(solveContact(two, {kModulus, 0.0}, w).real_area,
            0.85 * solveContact(one, {kModulus, 0.0}, w).real_area);
  EXPECT_GT(two.sigma, 1.2 * one.sigma);
}

TEST_F(GaussianSurfaces, PlasticityIndexSeparatesElasticFromPlastic) {
  const SummitSet set = findSummits(surfaces_[0], nullptr, kSize);
  const double root = std::sqrt(set.sigma / set.beta);
  // Hardness chosen for psi = 0.3 (elastic) and psi = 3 (plastic).
  for (double psi : {0.3, 3.0}) {
    const double hardness = kModulus * root / psi;
    const double w = 1e-3 * hardness * set.apparent_area;  // a light nominal pressure
    const ContactArea r = solveContact(set, {kModulus, hardness}, w);
    EXPECT_NEAR(r.plasticity_index, psi, 1e-9 * psi);
    const double plastic_share = static_cast<double>(r.summits_plastic) / r.summits_in_contact;
    // Elastic: few summits yield and the mean pressure stays well below H; plastic: most
    // yield and the mean pressure is close to H.
    if (psi < 0.6) {
      EXPECT_LT(plastic_share, 0.1) << psi;
      EXPECT_LT(r.mean_pressure, 0.2 * hardness);
    } else {
      EXPECT_GT(plastic_share, 0.5) << psi;
      EXPECT_GT(r.mean_pressure, 0.4 * hardness);
    }
  }
}

TEST(ContactArea, FlatPairIsInFullContact) {
  HeightMap flat(64, 64);
  const SummitSet set = findSummits(flat, &flat, 0.01);
  const double hardness = 1e9;
  const ContactArea r = solveContact(set, {2e11, hardness}, 1.5 * hardness * set.apparent_area);
  EXPECT_DOUBLE_EQ(r.fraction, 1.0);
  EXPECT_DOUBLE_EQ(r.real_area, 1e-4);
  EXPECT_NEAR(r.mean_pressure, 1.5 * hardness, 1e-6 * hardness);
}

TEST(ContactArea, RoughPairAboveHardnessTimesApparentAreaIsInFullContact) {
  const HeightMap h = gaussianSurface(64, 0.01, 0.2, 9);
  const SummitSet set = findSummits(h, nullptr, 0.01);
  const double hardness = 2e8;
  EXPECT_LT(solveContact(set, {1e10, hardness}, 0.2 * hardness * set.apparent_area).fraction, 1.0);
  EXPECT_DOUBLE_EQ(
      solveContact(set, {1e10, hardness}, 1.01 * hardness * set.apparent_area).fraction, 1.0);
}

TEST(ContactArea, BadInputIsRefused) {
  const HeightMap h = gaussianSurface(32, 0.01, 0.2, 4, 4.0, 16.0, 20);
  const SummitSet set = findSummits(h, nullptr, 0.01);
  EXPECT_THROW(solveContact(set, {1e9, 0.0}, -1.0), Error);
  EXPECT_THROW(solveContact(set, {0.0, 0.0}, 1.0), Error);
  EXPECT_THROW(solveContact(set, {1e9, -5.0}, 1.0), Error);
  EXPECT_THROW(solveContact(set, {1e9, 0.0}, std::nan("")), Error);
  EXPECT_THROW(findSummits(HeightMap(), nullptr, 0.01), Error);
  EXPECT_THROW(findSummits(h, nullptr, 0.0), Error);
  EXPECT_EQ(solveContact(set, {1e9, 0.0}, 0.0).real_area, 0.0);
}

// Its time is the benchmark's (asperity_contact_area_bench, BM_PairOf256), not a test's.
TEST(ContactArea, A256PairSolves) {
  const HeightMap a = gaussianSurface(256, kSize, kSlope, 11, 6.0, 48.0, 40);
  const HeightMap b = gaussianSurface(256, kSize, kSlope, 12, 6.0, 48.0, 40);
  const SummitSet set = findSummits(b, &a, kSize);
  const ContactArea r = solveContact(set, {kModulus, 1e9}, 10.0);
  EXPECT_GT(r.real_area, 0.0);
  EXPECT_LT(r.real_area, kSize * kSize);
}

}  // namespace
}  // namespace asperity
