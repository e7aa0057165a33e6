// The drag test against physics (SPEC 12): the solver delivers the coefficients the sampler gave
// (mu_k = mu_model in every direction, and their load-weighted mean within 1 %), Amontons' laws
// (mu_k independent of load and apparent area), Bowden and Tabor's cone through the `cones`
// texture, a symmetric sawtooth the same in both senses, and a block that cannot slide reported as
// such.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::dragOnly;
using test::near;
using test::tribometerPair;

// In each of 16 directions: mu_k = mu_model within 8 %, and within 1 % of the contacts'
// coefficients weighted by their loads, what the friction adds up to if the solver holds every
// contact at its bound (0.002 absolute where they are near 0). mu_model is the plain mean over
// the contacts: each corner's patch reads its own texels' facets, and on the roughest maps here
// (Gaussian slopes of rms 1, mu near 0.6) the corners' coefficients spread by a tenth and the
// solver's loads follow them, so the plain mean lies up to 6 % from the load-weighted one.
void expectKineticEqualsModel(const TribometerSurfaces& surfaces, double mu0) {
  const TribometerSettings settings = dragOnly(16, mu0);
  for (int k = 0; k < 16; ++k) {
    const DragResult d = runDragTest(surfaces, settings, 22.5 * k);
    ASSERT_TRUE(d.mu_k.has_value()) << "no steady sliding at " << 22.5 * k << " deg";
    EXPECT_TRUE(near(*d.mu_k, d.mu_model, 0.08, 0.002)) << 22.5 * k << " deg";
    EXPECT_TRUE(near(*d.mu_k, d.mu_loaded, 0.01, 0.002)) << 22.5 * k << " deg";
  }
}

TEST(DragTest, KineticEqualsModelOnIsotropicGaussians) {
  expectKineticEqualsModel(tribometerPair("gen:gaussian:2", "gen:gaussian:1"), 0.1);
}

TEST(DragTest, KineticEqualsModelOnAnisotropicGaussians) {
  expectKineticEqualsModel(tribometerPair("gen:gaussian:2:sx=0.1", "gen:gaussian:1:sx=0.1"), 0.1);
}

TEST(DragTest, KineticEqualsModelOnASawtooth) {
  // The paper's sawtooth (ramps 20, steep faces 70 degrees) under a flat block.
  expectKineticEqualsModel(tribometerPair("flat", "gen:sawtooth:1"), 0.1);
}

TEST(DragTest, KineticEqualsModelOnOak) {
  expectKineticEqualsModel(tribometerPair("gen:oak:2", "gen:oak:1"), 0.2);
}

TEST(DragTest, AmontonsKineticFrictionIndependentOfLoadAndArea) {
  // Blocks 5 and 20 cm wide under 1, 10 and 100 N. The plate repeats every 7.5 cm, so the
  // corners of both blocks (7.5 cm apart) cross the same texels: only the mechanics differ.
  const TribometerSurfaces surfaces = tribometerPair("flat", "gen:concrete:1", 1.0, 2.0, 0.075);
  std::vector<double> reference;
  for (double size : {0.05, 0.2}) {
    for (double load : {1.0, 10.0, 100.0}) {
      TribometerSettings settings = dragOnly(4, 0.2);
      settings.block_size = size;
      settings.load = load;
      const TribometerResult r = runTribometer(surfaces, settings);
      for (size_t k = 0; k < r.directions.size(); ++k) {
        ASSERT_TRUE(r.directions[k].mu_k.has_value());
        if (reference.size() < r.directions.size()) reference.push_back(*r.directions[k].mu_k);
        EXPECT_TRUE(near(*r.directions[k].mu_k, reference[k], 0.02))
            << "block " << size << " m, " << load << " N, direction " << k;
      }
    }
  }
}

TEST(DragTest, ConesGiveBaseSquaredTimesBowdenTabor) {
  // Touching cones 4 mm apart: mu_d = base^2 (2/pi) tan(alpha) = (1/4) (2/pi) tan(alpha)
  // (docs/textures.md), alpha 5 to 45 degrees, within 5 % in 8 directions. The plate is turned
  // 10 degrees, so that no direction runs along the cones' rows: a corner sliding along a row
  // crosses the same few texels of each cone.
  for (double alpha : {5.0, 15.0, 25.0, 35.0, 45.0}) {
    TribometerSurfaces surfaces =
        tribometerPair("flat", "gen:cones:1:flank_angle=" + std::to_string(alpha), 1.0, 1.0, 0.064);
    surfaces.plate.texture_rotation = 10.0 * kPi / 180.0;
    const double expected = 0.25 * 2.0 / kPi * std::tan(alpha * kPi / 180.0);
    const TribometerResult r = runTribometer(surfaces, dragOnly(8, 0.0));
    for (const TribometerDirection& d : r.directions) {
      ASSERT_TRUE(d.mu_k.has_value());
      EXPECT_TRUE(near(*d.mu_k, expected, 0.05)) << "alpha " << alpha << ", " << d.angle_deg;
    }
  }
}

TEST(DragTest, SymmetricSawtoothIsTheSameInBothSenses) {
  // Flanks of theta both ways: mu0 + k (1/2) (2/pi) tan(theta) up and down the axis, mu0 along
  // the ridges (docs/tribometer.md compares it with the wedge, tan(phi +- theta)).
  for (double theta : {10.0, 30.0}) {
    const std::string angle = std::to_string(theta);
    const TribometerSurfaces surfaces = tribometerPair(
        "flat", "gen:sawtooth:1:period=32,ramp_angle=" + angle + ",steep_angle=" + angle, 1.0, 1.0,
        0.064);
    const TribometerResult r = runTribometer(surfaces, dragOnly(4, 0.1));
    const double model = 0.1 + 0.5 * 2.0 / kPi * std::tan(theta * kPi / 180.0);
    EXPECT_TRUE(near(*r.directions[0].mu_k, *r.directions[2].mu_k, 0.01)) << theta;
    EXPECT_TRUE(near(*r.directions[0].mu_k, model, 0.05)) << theta;
    EXPECT_TRUE(near(*r.directions[1].mu_k, 0.1, 0.02)) << theta;
    EXPECT_TRUE(near(*r.directions[3].mu_k, 0.1, 0.02)) << theta;
  }
}

TEST(DragTest, ABlockThatCannotSlideHasNoKineticCoefficient) {
  // A soft, slow drive never pulls hard enough to overcome mu0 = 0.5 within the run.
  TribometerSettings settings = dragOnly(4, 0.5);
  settings.spring_frequency = 1.0;
  settings.drag_speed = 0.01;
  settings.tracks = 1;
  const DragResult r = runDragTest(tribometerPair("flat", "flat"), settings, 0.0);
  EXPECT_FALSE(r.mu_k.has_value());
  EXPECT_LT(r.min_speed, 0.001);
  EXPECT_TRUE(near(r.mu_model, 0.5, 1e-6));
}

TEST(DragTest, ConstantFrictionGivesMu0) {
  // Coulomb friction of mu0 alone: the drive pulls with mu0 times the normal force.
  TribometerSettings settings = dragOnly(4, 0.35);
  settings.sampler = "constant";
  const TribometerResult r = runTribometer(tribometerPair("flat", "gen:gaussian:1"), settings);
  for (const TribometerDirection& d : r.directions) {
    ASSERT_TRUE(d.mu_k.has_value());
    EXPECT_TRUE(near(*d.mu_k, 0.35, 0.005)) << d.angle_deg;
    EXPECT_TRUE(near(*d.mu_model, 0.35, 1e-6)) << d.angle_deg;
  }
}

}  // namespace
}  // namespace asperity
