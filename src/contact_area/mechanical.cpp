// Material presets for the real-area model and the pair's effective properties.
#include "asperity/contact_area/mechanical.hpp"

#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// Junctions shear at k = Y / sqrt 3 (von Mises) and H is about 3 Y (Tabor), so tau ~ H / (3
// sqrt 3): the shear strength where no measured one is tabulated (docs/materials.md).
double taborShear(double hardness) {
  return hardness / (3.0 * std::sqrt(3.0));
}

Mechanical preset(std::string name, double e, double nu, double h, double tau) {
  return {std::move(name), e, nu, h, tau};
}

}  // namespace

const std::vector<Mechanical>& mechanicalPresets() {
  // Representative values; docs/materials.md gives the ranges and sources.
  static const std::vector<Mechanical> presets = {
      preset("steel", 200e9, 0.29, 1.3e9, taborShear(1.3e9)),
      preset("cast_iron", 110e9, 0.26, 2.0e9, taborShear(2.0e9)),
      preset("concrete", 30e9, 0.20, 0.6e9, taborShear(0.6e9)),
      preset("oak", 12e9, 0.35, 40e6, taborShear(40e6)),
      preset("pvc", 3.0e9, 0.38, 150e6, taborShear(150e6)),
      preset("acrylic", 3.2e9, 0.37, 200e6, taborShear(200e6)),
      preset("rubber", 5e6, 0.49, 0.0, 0.5e6),
  };
  return presets;
}

const Mechanical& findMechanical(const std::string& name) {
  std::string known;
  for (const Mechanical& m : mechanicalPresets()) {
    if (m.name == name) return m;
    known += (known.empty() ? "" : ", ") + m.name;
  }
  throw Error("material '" + name + "': unknown (known: " + known + ")");
}

double effectiveModulus(const Mechanical& a, const Mechanical& b) {
  return 1.0 / ((1.0 - a.poisson * a.poisson) / a.modulus +
                (1.0 - b.poisson * b.poisson) / b.modulus);
}

ContactMaterial contactPair(const Mechanical& a, const Mechanical& b) {
  // The softer of two materials with a plastic limit yields; one without (rubber) never does,
  // so the other's limit applies alone.
  double hardness = 0.0;
  if (a.hardness > 0.0 && b.hardness > 0.0)
    hardness = std::min(a.hardness, b.hardness);
  else
    hardness = std::max(a.hardness, b.hardness);
  return {effectiveModulus(a, b), hardness};
}

double pairShear(const Mechanical& a, const Mechanical& b) {
  return std::min(a.shear, b.shear);
}

double adhesionFriction(double shear, const ContactArea& contact) {
  return contact.load > 0.0 ? shear * contact.real_area / contact.load : 0.0;
}

}  // namespace asperity
