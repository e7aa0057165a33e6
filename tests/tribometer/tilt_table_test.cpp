// The tilt table (SPEC 12): a block on a plate of constant friction slides at tan(theta_s) =
// mu0; a tall block topples before it slides ("no slide"); a block that holds to the largest
// tilt has no static coefficient either; textured plates give mu_s beside mu_k.
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::near;
using test::tribometerPair;

// Settings of the tilt table alone, one track, with Coulomb friction mu0 in every direction.
TribometerSettings tiltOnly(double mu0, const std::string& sampler) {
  TribometerSettings settings;
  settings.drag = false;
  settings.tracks = 1;
  settings.friction.mu0 = mu0;
  settings.sampler = sampler;
  return settings;
}

TEST(TiltTable, SlidesAtTheAngleWhoseTangentIsMu) {
  // Coulomb: tan(theta_s) = mu, never below; the slow ramp overshoots by about 0.1 degree at
  // 0.2 deg/s (docs/tribometer.md), at most 0.15.
  for (double mu : {0.1, 0.3, 0.8}) {
    const TiltResult r =
        runTiltTest(tribometerPair("flat", "flat"), tiltOnly(mu, "constant"), 30.0);
    ASSERT_TRUE(r.mu_s.has_value()) << mu;
    EXPECT_FALSE(r.toppled);
    EXPECT_GE(*r.mu_s, mu * (1.0 - 1e-3)) << "it slid before the true angle";
    EXPECT_LE(*r.mu_s, std::tan(std::atan(mu) + 0.15 * kPi / 180.0)) << mu;
  }
}

TEST(TiltTable, ATallBlockToppleBeforeSlidingHasNoStaticCoefficient) {
  // A 10 cm wide, 30 cm tall block tips over at tan(theta) = 1/3, below mu = 0.8.
  TribometerSettings settings = tiltOnly(0.8, "constant");
  settings.block_height = 0.3;
  const TiltResult r = runTiltTest(tribometerPair("flat", "flat"), settings, 0.0);
  EXPECT_FALSE(r.mu_s.has_value());
  EXPECT_TRUE(r.toppled);
  EXPECT_LT(r.angle_deg, 30.0);
}

TEST(TiltTable, ABlockThatHoldsToTheLargestTiltHasNoStaticCoefficient) {
  TribometerSettings settings = tiltOnly(1.5, "constant");
  settings.tilt_max_deg = 45.0;
  const TiltResult r = runTiltTest(tribometerPair("flat", "flat"), settings, 90.0);
  EXPECT_FALSE(r.mu_s.has_value());
  EXPECT_FALSE(r.toppled);
  EXPECT_TRUE(near(r.angle_deg, 45.0, 1e-9));
}

TEST(TiltTable, StaticBesideKineticOnATexturedPair) {
  // The model bounds static and kinetic friction alike: on concrete the mean mu_s over the
  // directions is the mean mu_k within 5 % (each direction's mu_s depends on where the corners
  // rest: about 15 %).
  const TribometerSurfaces surfaces = tribometerPair("gen:plaster:4", "gen:concrete:1", 2.0, 2.0);
  TribometerSettings settings;
  settings.directions = 8;
  settings.friction.mu0 = 0.2;
  const TribometerResult r = runTribometer(surfaces, settings);
  double static_sum = 0.0, kinetic_sum = 0.0;
  for (const TribometerDirection& d : r.directions) {
    ASSERT_TRUE(d.mu_s.has_value() && d.mu_k.has_value()) << d.angle_deg;
    static_sum += *d.mu_s;
    kinetic_sum += *d.mu_k;
  }
  EXPECT_TRUE(near(static_sum, kinetic_sum, 0.05));
}

}  // namespace
}  // namespace asperity
