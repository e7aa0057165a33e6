// The model's terms for calibration: the cone's are `asperity cone`'s half a turn round (and
// follow a texture's rotation); the sampler's reproduce the tribometer's mu_model through Eq. 7.
#include <gtest/gtest.h>

#include <vector>

#include "asperity/friction/patch_cone.hpp"
#include "asperity/tribometer/calibrate.hpp"
#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::near;
using test::tribometerPair;

const std::vector<double> kAngles = {0.0, 90.0, 180.0, 270.0};

TEST(ModelTerms, TheConeHalfATurnRound) {
  // The paper's sawtooth resists sliding toward -u (180 degrees) with its mu(+u) = 0.8745.
  const TribometerSurfaces s = tribometerPair("flat", "gen:sawtooth:1");
  const ModelTerms t = modelTerms(s, TribometerSettings{}, kAngles, ModelKind::Cone);
  PatchConeOptions opt;
  opt.gains = {0.0, 0.0, 1.0};
  const DirectionalMu cone = flatPatchCone(nullptr, *s.plate.normal_map, opt);
  EXPECT_TRUE(near(t.plate[2], cone.mu[0], 1e-6));
  EXPECT_TRUE(near(t.plate[0], cone.mu[8], 1e-6));
  EXPECT_TRUE(near(t.plate[2], 0.8745, 0.001));
  EXPECT_EQ(t.block, std::vector<double>(4, 0.0));
}

TEST(ModelTerms, TheConeFollowsTheTexturesRotation) {
  // Turning the plate's sawtooth by 90 degrees moves its terms a quarter turn; the block's
  // mirrored face turns the other way.
  TribometerSurfaces s = tribometerPair("gen:sawtooth:1", "gen:sawtooth:1");
  const ModelTerms straight = modelTerms(s, TribometerSettings{}, kAngles, ModelKind::Cone);
  s.plate.texture_rotation = s.block.texture_rotation = kPi / 2.0;
  const ModelTerms turned = modelTerms(s, TribometerSettings{}, kAngles, ModelKind::Cone);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_TRUE(near(turned.plate[(k + 1) % 4], straight.plate[k], 1e-6)) << k;
    EXPECT_TRUE(near(turned.block[(k + 3) % 4], straight.block[k], 1e-6)) << k;
  }
}

TEST(ModelTerms, TheSamplersGiveTheTribometersMuModel) {
  // Eq. 7 over the unit-gain terms against a drag with gains 2 and 3 and mu0 0.1: the mean over
  // the same paths' contacts is linear in the gains, so within 0.5 % (the paths differ a little
  // with the friction).
  const TribometerSurfaces unit = tribometerPair("gen:gaussian:2:sx=0.2", "gen:oak:1");
  TribometerSettings settings = test::dragOnly(4, 0.1);
  const ModelTerms t = modelTerms(unit, settings, kAngles, ModelKind::Sampler);
  TribometerSurfaces gained = unit;
  gained.block.gain = 2.0, gained.plate.gain = 3.0;
  const TribometerResult r = runTribometer(gained, settings);
  for (size_t k = 0; k < 4; ++k)
    EXPECT_TRUE(near(0.1 + 2.0 * t.block[k] + 3.0 * t.plate[k], *r.directions[k].mu_model, 0.005))
        << k;
}

}  // namespace
}  // namespace asperity
