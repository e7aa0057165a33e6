// The real-contact-area model (docs/contact-area.md): both surfaces' heights at the pixels of P,
// with the depth between their rasterised faces, make the composite roughness of the patch; the
// load is the contact's previous normal impulse over the step; its Greenwood and Williamson
// summits give the real area A_r (contact_area/contact_area.hpp); mu_d = tau A_r / W plus
// Eq. 7's ploughing averaged over the pixels in contact only.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/contact_area/mechanical.hpp"
#include "asperity/error.hpp"
#include "sampler/models/friction_models.hpp"

namespace asperity::models {

namespace {

struct AreaScratch : ModelScratch {
  HeightMap composite;  // over P's bounding box, its pixel (0, 0) at patch pixel (i0, j0)
  int i0 = 0, j0 = 0;
  SummitSet summits;
  std::vector<unsigned char> mask;
  std::vector<float> gx, gy;  // ploughing vectors of the pixels in contact, A's then B's

  void reserveLike(const ModelScratch& other) override {
    const auto& o = static_cast<const AreaScratch&>(other);
    composite.values.reserve(o.composite.values.capacity());
    summits.summits.reserve(o.summits.summits.capacity());
    summits.surface.values.reserve(o.summits.surface.values.capacity());
    mask.reserve(o.mask.capacity());
    gx.reserve(o.gx.capacity());
    gy.reserve(o.gy.capacity());
  }
};

std::unique_ptr<ModelScratch> makeScratch() {
  return std::make_unique<AreaScratch>();
}

// Each side's mechanical values; throws naming the body and shape without any.
std::array<const Mechanical*, 2> mechanicalOf(const ModelInputs& in, const Contact& contact) {
  std::array<const Mechanical*, 2> pair{};
  const BodyId bodies[2] = {contact.body_a, contact.body_b};
  for (size_t s = 0; s < 2; ++s) {
    const Surface* surface = in.surfaces[s];
    if (surface == nullptr || !surface->mechanical)
      throw Error("friction model contact_area: body " + std::to_string(bodies[s]) + " shape " +
                  std::to_string(in.shapes[s]) +
                  " has no mechanical values (E, nu, H, tau): give its surface a \"mechanical\" "
                  "preset or values");
    pair[s] = &*surface->mechanical;
  }
  return pair;
}

// The composite roughness over P's bounding box: at each pixel of P, how far the two surfaces
// reach past each other. Other pixels lie below P's lowest by P's span, so that they never
// touch. Returns false when P is flat (the model's full contact). Only the box is scanned for
// summits: a contact often covers a part of its patch.
bool compositeOverPatch(const PatchFragments& f, AreaScratch& s) {
  int i0 = f.resolution, j0 = f.resolution, i1 = -1, j1 = -1;
  for (const uint32_t p : f.pixels) {
    const int i = pixelI(p), j = pixelJ(p);
    i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  }
  HeightMap& out = s.composite;
  s.i0 = i0, s.j0 = j0;
  out.width = i1 - i0 + 1, out.height = j1 - j0 + 1;
  out.values.assign(static_cast<size_t>(out.width * out.height),
                    std::numeric_limits<float>::quiet_NaN());
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (size_t k = 0; k < f.pixels.size(); ++k) {
    const float c = f.height[0][k] + f.height[1][k] + f.depth[0][k] + f.depth[1][k];
    out.at(pixelI(f.pixels[k]) - i0, pixelJ(f.pixels[k]) - j0) = c;
    lo = std::min(lo, c), hi = std::max(hi, c);
  }
  if (!(hi > lo)) return false;
  const float below = lo - (hi - lo);
  for (float& v : out.values)
    if (std::isnan(v)) v = below;
  return true;
}

// The ploughing vectors of the pixels of P in contact (in P's order), A's then B's: only those
// enter the means. Returns their count.
size_t gatherInContact(const PatchFragments& f, AreaScratch& s) {
  s.gx.clear();
  s.gy.clear();
  for (size_t side = 0; side < 2; ++side) {
    for (size_t k = 0; k < f.pixels.size(); ++k) {
      const int i = pixelI(f.pixels[k]) - s.i0, j = pixelJ(f.pixels[k]) - s.j0;
      if (!s.mask[static_cast<size_t>(j * s.composite.width + i)]) continue;
      s.gx.push_back(f.gx[side][k]);
      s.gy.push_back(f.gy[side][k]);
    }
  }
  return s.gx.size() / 2;
}

void reduce(const PatchFragments& f, const ModelInputs& in, Contact& contact,
            ModelScratch* scratch) {
  AreaScratch& s = *static_cast<AreaScratch*>(scratch);
  const std::array<const Mechanical*, 2> pair = mechanicalOf(in, contact);
  const size_t count = f.pixels.size();
  const double apparent = static_cast<double>(count) * f.pixel * f.pixel;
  const ContactMaterial material = contactPair(*pair[0], *pair[1]);
  // The load: last step's normal impulse over the step; a new contact (none yet) is taken at
  // a light load, 1e-4 of what would flatten the patch, where A_r is still proportional to W.
  const double stiff = material.hardness > 0.0 ? material.hardness : material.modulus;
  const double light = 1e-4 * stiff * apparent;
  const double load = std::max(contact.lambda_n / in.dt, light);
  double real_area = apparent;
  // Without relief every pixel of P is in contact.
  s.i0 = s.j0 = 0;
  s.composite.width = f.resolution;
  s.mask.assign(static_cast<size_t>(f.resolution * f.resolution), 1);
  if (count > 0 && compositeOverPatch(f, s)) {
    findSummitsInto(s.composite, s.composite.width * f.pixel, s.summits);
    s.summits.apparent_area = apparent;
    const ContactArea area = solveContact(s.summits, material, load);
    real_area = area.real_area;
    contactMaskInto(s.summits, area, s.mask);
  }
  const size_t touching = count > 0 ? gatherInContact(f, s) : 0;
  // Adhesion, capped as the ploughing term is (a flat pair is in full contact at any load).
  PatchGains gains = in.gains;
  gains.mu0 = std::min(pairShear(*pair[0], *pair[1]) * real_area / load, in.mu_max);
  std::array<std::array<double, kMaxDirections>, 2> sums{};
  const size_t n = in.directions.size();
  for (size_t k = 0; k < 2 && touching > 0; ++k) {
    accumulateDirectionalSums(std::span<const float>(s.gx.data() + k * touching, touching),
                              std::span<const float>(s.gy.data() + k * touching, touching),
                              in.directions, std::span<double>(sums[k].data(), n), in.simd);
  }
  finishContact(contact, std::span<const double>(sums[0].data(), n),
                std::span<const double>(sums[1].data(), n), static_cast<int>(touching), gains);
}

}  // namespace

const FrictionModelVariant kContactAreaModel{.kind = FrictionModel::ContactArea,
                                             .reads_heights = true,
                                             .reads_loads = true,
                                             .make_scratch = &makeScratch,
                                             .reduce = &reduce};

}  // namespace asperity::models
