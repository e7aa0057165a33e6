// Load balance over the summits: elastic (Hertz) summits up to the interference where their
// mean pressure reaches H, plastic beyond; the separation found by bisection.
#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/error.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

namespace {

// Sum of the summits' loads and contact areas with the partner's plane at height d.
struct Totals {
  double force = 0.0;
  double area = 0.0;
  int touching = 0;
  int plastic = 0;
};

// Hertz: F = (4/3) E* R^1/2 delta^3/2 on pi R delta, mean pressure (4 / 3 pi) E* (delta / R)^1/2.
// That pressure reaches H at delta = R (3 pi H / 4 E*)^2; beyond it the summit is fully plastic
// and carries H on pi R delta, which meets the elastic load there (no jump). A summit counts as
// yielded past Greenwood and Williamson's onset of plastic flow, delta = R (H / E*)^2, the
// interference their plasticity index compares with sigma.
Totals totalsAt(const SummitSet& set, const ContactMaterial& m, double d) {
  const double ratio = m.hardness > 0.0 ? m.hardness / m.modulus : HUGE_VAL;
  const double onset = ratio * ratio;
  const double full = std::pow(3.0 * kPi / 4.0, 2) * onset;
  Totals t;
  for (const Summit& s : set.summits) {
    const double delta = s.height - d;
    if (delta <= 0.0) break;  // highest first: the rest are below the plane too
    const double area = kPi * s.radius * delta;
    t.area += area;
    t.force += delta < full * s.radius
                   ? (4.0 / 3.0) * m.modulus * std::sqrt(s.radius) * delta * std::sqrt(delta)
                   : m.hardness * area;
    ++t.touching;
    t.plastic += delta > onset * s.radius ? 1 : 0;
  }
  return t;
}

void checkInputs(const ContactMaterial& m, double load) {
  if (!(load >= 0.0) || !std::isfinite(load))
    throw Error("contact area: load must be a finite number of newtons >= 0, got " +
                std::to_string(load));
  if (!(m.modulus > 0.0) || !std::isfinite(m.modulus))
    throw Error("contact area: modulus E* must be a positive number of pascals, got " +
                std::to_string(m.modulus));
  if (!(m.hardness >= 0.0) || !std::isfinite(m.hardness))
    throw Error("contact area: hardness must be a positive number of pascals, got " +
                std::to_string(m.hardness));
}

// The plane height at which the summits carry `load`, by bisection (the load falls as d rises).
double separationFor(const SummitSet& set, const ContactMaterial& m, double load) {
  double hi = set.summits.front().height;
  double span = std::max(hi - set.summits.back().height, set.texel);
  // Lower the plane until the summits carry at least the load.
  while (totalsAt(set, m, hi - span).force < load && span < 1e6) span *= 2.0;
  double lo = hi - span;
  for (int k = 0; k < 200 && hi - lo > 1e-13 * span; ++k) {
    const double mid = 0.5 * (lo + hi);
    (totalsAt(set, m, mid).force < load ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

ContactArea solveContact(const SummitSet& set, const ContactMaterial& material, double load) {
  checkInputs(material, load);
  ContactArea r;
  r.load = load;
  r.apparent_area = set.apparent_area;
  r.summits = static_cast<int>(set.summits.size());
  if (material.hardness > 0.0 && set.beta > 0.0)
    r.plasticity_index = material.modulus / material.hardness * std::sqrt(set.sigma / set.beta);
  if (load == 0.0) return r;
  if (set.flat || set.summits.empty()) {
    // Two smooth planes meet everywhere under any load.
    r.real_area = set.apparent_area;
  } else {
    r.separation = separationFor(set, material, load);
    const Totals t = totalsAt(set, material, r.separation);
    r.real_area = t.area;
    r.summits_in_contact = t.touching;
    r.summits_plastic = t.plastic;
  }
  // The summits cannot touch more than the patch; a mean pressure above H flattens it all.
  if (material.hardness > 0.0) r.real_area = std::max(r.real_area, load / material.hardness);
  r.real_area = std::min(r.real_area, set.apparent_area);
  r.fraction = r.real_area / set.apparent_area;
  r.mean_pressure = load / r.real_area;
  return r;
}

std::vector<unsigned char> contactMask(const SummitSet& set, const ContactArea& result) {
  std::vector<unsigned char> mask;
  contactMaskInto(set, result, mask);
  return mask;
}

void contactMaskInto(const SummitSet& set, const ContactArea& result,
                     std::vector<unsigned char>& mask) {
  const auto count = static_cast<size_t>(set.width) * static_cast<size_t>(set.height);
  mask.assign(count, result.fraction >= 1.0 ? 1 : 0);
  if (result.fraction >= 1.0 || result.load == 0.0) return;
  for (const Summit& s : set.summits) {
    const double delta = s.height - result.separation;
    if (delta <= 0.0) break;
    // Contact radius a = sqrt(R delta) in texels, drawn as a disc around the summit.
    const double a = std::sqrt(s.radius * delta) / set.texel;
    const int reach = static_cast<int>(std::ceil(a));
    for (int dj = -reach; dj <= reach; ++dj) {
      for (int di = -reach; di <= reach; ++di) {
        if (di * di + dj * dj > a * a && (di != 0 || dj != 0)) continue;
        const int i = ((s.i + di) % set.width + set.width) % set.width;
        const int j = ((s.j + dj) % set.height + set.height) % set.height;
        mask[static_cast<size_t>(j) * set.width + i] = 1;
      }
    }
  }
}

}  // namespace asperity
