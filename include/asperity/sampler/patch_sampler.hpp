// What the patch samplers (CPU reference and OpenGL) share: the base class that serves every
// friction model and drives patch reuse the same way for both, and the per-pixel images of one
// contact's patch (the paper's Fig. 7), for tests, the `asperity patch` command and debugging.
// Their settings are checked by validate(FrictionSettings).
//
// Pixel layout: R x R, index j * R + i, pixel (i, j) centred at (-w/2 + (i + 1/2) w/R) t +
// (-w/2 + (j + 1/2) w/R) b from the contact point (row 0 at -b, as an OpenGL viewport).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "asperity/math/types.hpp"
#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

// One contact's patch, per surface (index 0 = A, 1 = B).
struct PatchImages {
  int resolution = 0;
  int directions = 0;
  std::array<std::vector<uint8_t>, 2> covered;  // 1 where the surface has a fragment
  std::array<std::vector<Vec3f>, 2> normals;    // unit meso normal, contact frame (t, b, n)
  std::array<std::vector<float>, 2> mu;         // [pixel * directions + k]: Eq. 5 (mask applied,
                                                // without k), 0 where not covered
  std::vector<uint8_t> in_patch;                // the set P of Eq. 8: covered by both
};

namespace patch {
class PatchReuse;
}
namespace models {
struct FrictionModelVariant;
}

// A patch sampler finds the fragments of each contact's patch; the friction models reduce them
// (sampler/models/). This base holds what every sampler does the same way: which model each
// contact takes, patch reuse (FrictionSettings::reuse_pixels: a contact whose surfaces barely
// moved keeps its sample) and the call's figures.
class PatchSampler : public FrictionProvider {
 public:
  ~PatchSampler() override;
  void setFrictionModels(const FrictionModelSettings& models) override;
  // Whether a model in use reads each contact's load (the contact-area model does).
  bool readsNormalLoads() const override;
  ProviderStats lastStats() const override { return stats_; }
  void forgetHistory() override;
  void saveHistory(StateWriter& out) const override;
  void loadHistory(StateReader& in) override;

 protected:
  PatchSampler();
  // A call's first step: the contacts whose earlier sample still holds get it back; the others
  // are listed in contact order, for the sampler to sample. Sets stats_.sampled and reused.
  std::span<Contact* const> keepSamples(std::span<const Body> bodies, std::span<Contact> contacts,
                                        const FrictionSettings& settings);
  // A call's last step, once every listed contact is sampled: remembers them for the next call.
  void rememberSamples(std::span<const Body> bodies, std::span<const Contact> contacts);
  // The reuse records, for a sampler that reports its depth clip margins (patch_reuse.hpp).
  patch::PatchReuse& reuse() { return *reuse_; }
  // The model of a contact (FrictionModelSettings::modelFor on each side's first shape).
  const models::FrictionModelVariant& modelOf(std::span<const Body> bodies,
                                              const Contact& contact) const;
  const FrictionModelSettings& models() const { return models_; }

  ProviderStats stats_;

 private:
  FrictionModelSettings models_;
  std::unique_ptr<patch::PatchReuse> reuse_;
  std::vector<uint8_t> kept_;        // this call's reuse decisions
  std::vector<Contact*> to_sample_;  // this call's other contacts
};

}  // namespace asperity
