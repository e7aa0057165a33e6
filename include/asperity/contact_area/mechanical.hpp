// What the real-area model needs to know of a material (SPEC 13): Young's modulus E, Poisson's
// ratio nu, indentation hardness H and the shear strength tau of its junctions, with presets
// for the paper's materials and their sources in docs/materials.md.
#pragma once

#include <string>
#include <vector>

#include "asperity/contact_area/contact_area.hpp"

namespace asperity {

struct Mechanical {
  std::string name;
  double modulus = 0.0;   // E (Pa)
  double poisson = 0.0;   // nu (1)
  double hardness = 0.0;  // H (Pa); 0 = no plastic limit (rubber)
  double shear = 0.0;     // tau (Pa): shear strength of the junctions
};

// steel, cast_iron, concrete, oak, pvc, acrylic, rubber.
const std::vector<Mechanical>& mechanicalPresets();

// The preset of that name; throws asperity::Error naming the known ones.
const Mechanical& findMechanical(const std::string& name);

// E* = 1 / ((1 - nu_a^2) / E_a + (1 - nu_b^2) / E_b).
double effectiveModulus(const Mechanical& a, const Mechanical& b);

// The pair as the contact model sees it: E*, and the softer surface's hardness (the one that
// yields; 0 when neither has a plastic limit).
ContactMaterial contactPair(const Mechanical& a, const Mechanical& b);

// The weaker junction shear strength of the pair (the junctions shear in the softer material).
double pairShear(const Mechanical& a, const Mechanical& b);

// Bowden and Tabor's adhesion term, tau A_r / W (0 at zero load).
double adhesionFriction(double shear, const ContactArea& contact);

}  // namespace asperity
