// The friction models as variants (friction/friction_model.hpp names them): a sampler hands a
// model the fragments of one contact's patch P, the model reduces them to the contact's mu_d.
// The samplers own how fragments are found (rasterised on the CPU, rendered on the GPU); the
// models own what they mean.
//
// Adding a model (docs/layers.md): its source in this folder defining its FrictionModelVariant,
// its enum value and name in friction_model.hpp, and its entry in kFrictionModelVariants below,
// at the enum value's position.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>

#include "asperity/collision/contact.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/friction/friction_model.hpp"

namespace asperity::models {

// A pixel of the patch as (i, j) packed i | j << 16 (the samplers' Volume::pack).
inline int pixelI(uint32_t packed) {
  return static_cast<int>(packed & 0xffffu);
}
inline int pixelJ(uint32_t packed) {
  return static_cast<int>(packed >> 16);
}

// The fragments of P, the pixels both surfaces cover, per surface (0 = A, 1 = B).
struct PatchFragments {
  int resolution = 0;                // R: the patch is R x R pixels
  double pixel = 0.0;                // side of a pixel (m)
  std::span<const uint32_t> pixels;  // P's pixels, packed
  // Per pixel of P: the ploughing vector g of the surface's facet there (Eq. 5 is
  // max(0, g . d)), times its gain mask.
  std::array<const float*, 2> gx{}, gy{};
  // Where the model reads heights (FrictionModelVariant::reads_heights), null otherwise: at
  // each pixel of P, the height of the surface's texture there (m, out of the surface toward
  // the other one) and the depth of its rasterised face, signed so that the sum of the four is
  // how far the two surfaces overlap there (the depth of A is -z, of B +z, along n).
  std::array<const float*, 2> height{}, depth{};
};

// What a model needs besides the fragments.
struct ModelInputs {
  std::span<const Vec2> directions;  // d_k, k < N
  PatchGains gains;                  // mu0, k_A, k_B
  double mu_max = 4.0;               // cap of every term
  double dt = 0.01;                  // FrictionModelSettings::dt
  // Each side's surface (its first shape's) and that shape's index, for messages.
  std::array<const Surface*, 2> surfaces{};
  std::array<int, 2> shapes{};
  SimdCopy simd = SimdCopy::Auto;
};

// One thread's scratch of a model (no allocation once warm).
struct ModelScratch {
  virtual ~ModelScratch() = default;
  // Every buffer at least as large as other's (a scratch of the same model).
  virtual void reserveLike(const ModelScratch& other) { (void)other; }
};

struct FrictionModelVariant {
  FrictionModel kind;
  bool reads_heights = false;  // the sampler fills PatchFragments::height and depth
  bool reads_loads = false;    // the world gives Contact::lambda_n
  std::unique_ptr<ModelScratch> (*make_scratch)() = nullptr;  // null: needs none
  // Fills contact.mu, covered_pixels and fallback from the fragments of P.
  void (*reduce)(const PatchFragments& fragments, const ModelInputs& in, Contact& contact,
                 ModelScratch* scratch) = nullptr;
  // For a model that needs no more of P than its per-direction sums of max(0, g . d) and |P|
  // (Eq. 8): the rest of reduce, so that a sampler may sum on its device. Null otherwise.
  void (*finish_sums)(std::span<const double> sums_a, std::span<const double> sums_b, int count,
                      const ModelInputs& in, Contact& contact) = nullptr;
};

extern const FrictionModelVariant kPaperModel;        // paper_model.cpp
extern const FrictionModelVariant kContactAreaModel;  // contact_area_model.cpp

// In FrictionModel's order.
inline const FrictionModelVariant* const kFrictionModelVariants[] = {&kPaperModel,
                                                                     &kContactAreaModel};
static_assert(std::size(kFrictionModelVariants) == std::size(kFrictionModelNames),
              "every friction model has a variant and a name");

inline const FrictionModelVariant& variantOf(FrictionModel m) {
  return *kFrictionModelVariants[static_cast<size_t>(m)];
}

// Eq. 8 then Eq. 7, which every model ends with: the means of the per-surface sums over
// `count` pixels into contact.mu with `gains`; count 0 gives the fallback mu = mu0
// (contact.fallback).
void finishContact(Contact& contact, std::span<const double> sums_a, std::span<const double> sums_b,
                   int count, const PatchGains& gains);

}  // namespace asperity::models
