// Material presets, the pair's E* and hardness, and Bowden and Tabor's adhesion term: with the
// real area proportional to load, mu = tau A_r / W is independent of load (Amontons) as a
// result of the model, and a fully plastic contact gives tau / H.
#include "asperity/contact_area/mechanical.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "contact_area/gaussian_surface.hpp"

namespace asperity {
namespace {

TEST(Mechanical, PresetsCoverThePapersMaterials) {
  for (const char* name : {"steel", "cast_iron", "concrete", "oak", "pvc", "acrylic", "rubber"}) {
    const Mechanical& m = findMechanical(name);
    EXPECT_GT(m.modulus, 0.0) << name;
    EXPECT_GT(m.shear, 0.0) << name;
    EXPECT_GE(m.hardness, 0.0) << name;
    EXPECT_GT(m.poisson, 0.0) << name;
    EXPECT_LT(m.poisson, 0.5) << name;
  }
  // Stiffness and hardness order as the handbooks have them.
  EXPECT_GT(findMechanical("steel").modulus, findMechanical("concrete").modulus);
  EXPECT_GT(findMechanical("concrete").modulus, findMechanical("oak").modulus);
  EXPECT_GT(findMechanical("oak").modulus, findMechanical("pvc").modulus);
  EXPECT_GT(findMechanical("pvc").modulus, 100.0 * findMechanical("rubber").modulus);
  try {
    findMechanical("marble");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("marble"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cast_iron"), std::string::npos);
  }
}

TEST(Mechanical, EffectiveModulusAndHardnessOfAPair) {
  const Mechanical& steel = findMechanical("steel");
  // Equal materials: E / (2 (1 - nu^2)).
  EXPECT_NEAR(effectiveModulus(steel, steel), 200e9 / (2 * (1 - 0.29 * 0.29)), 1e3);
  // A soft partner dominates: rubber on steel is rubber's E / (1 - nu^2) within 0.1 %.
  const Mechanical& rubber = findMechanical("rubber");
  EXPECT_NEAR(effectiveModulus(rubber, steel), 5e6 / (1 - 0.49 * 0.49), 5e6 * 1e-3);
  EXPECT_DOUBLE_EQ(effectiveModulus(rubber, steel), effectiveModulus(steel, rubber));
  // The softer one yields.
  EXPECT_DOUBLE_EQ(contactPair(steel, findMechanical("pvc")).hardness, 150e6);
  EXPECT_DOUBLE_EQ(contactPair(rubber, steel).hardness, 1.3e9);
  EXPECT_DOUBLE_EQ(pairShear(steel, findMechanical("oak")), findMechanical("oak").shear);
}

TEST(Mechanical, AdhesionFrictionObeysAmontonsOverTwoDecades) {
  // Steel on an acrylic plate, a rough elastic contact: mu = tau A_r / W barely moves while
  // the load grows a hundredfold.
  const HeightMap h = test::gaussianSurface(256, 1e-3, 0.02, 5, 4.0, 32.0);
  const SummitSet set = findSummits(h, nullptr, 1e-3);
  const Mechanical& a = findMechanical("acrylic");
  const Mechanical& b = findMechanical("steel");
  const ContactMaterial pair = contactPair(a, b);
  const double w0 = 1e-4 * pair.modulus * 0.02 * set.apparent_area;
  const double light = adhesionFriction(pairShear(a, b), solveContact(set, pair, w0));
  const double heavy = adhesionFriction(pairShear(a, b), solveContact(set, pair, 100 * w0));
  EXPECT_GT(light, 0.0);
  EXPECT_NEAR(heavy / light, 1.0, 0.25);
}

TEST(Mechanical, AFullyPlasticContactGivesShearOverHardness) {
  // Steel on steel with slopes of 0.5: psi far above 1, every junction at H, mu = tau / H.
  const HeightMap h = test::gaussianSurface(128, 1e-3, 0.5, 6, 4.0, 32.0);
  const SummitSet set = findSummits(h, nullptr, 1e-3);
  const Mechanical& steel = findMechanical("steel");
  const ContactMaterial pair = contactPair(steel, steel);
  for (double w : {1.0, 10.0, 100.0}) {
    const ContactArea r = solveContact(set, pair, w);
    EXPECT_GT(r.plasticity_index, 10.0);
    const double mu = adhesionFriction(steel.shear, r);
    EXPECT_GE(mu, steel.shear / steel.hardness * (1 - 1e-12)) << w;  // A_r >= W / H
    EXPECT_LT(mu, 1.1 * steel.shear / steel.hardness) << w;
  }
}

}  // namespace
}  // namespace asperity
