// What every patch sampler shares (patch_sampler.hpp): the models it serves and patch reuse.
#include "asperity/sampler/patch_sampler.hpp"

#include <algorithm>

#include "sampler/models/friction_models.hpp"
#include "sampler/patch_common.hpp"
#include "sampler/patch_reuse.hpp"

namespace asperity {

PatchSampler::PatchSampler() : reuse_(std::make_unique<patch::PatchReuse>()) {}
PatchSampler::~PatchSampler() = default;

void PatchSampler::setFrictionModels(const FrictionModelSettings& models) {
  models_ = models;
}

bool PatchSampler::readsNormalLoads() const {
  for (const auto& [name, model] : kFrictionModelNames)
    if (models_.uses(model) && models::variantOf(model).reads_loads) return true;
  return false;
}

const models::FrictionModelVariant& PatchSampler::modelOf(std::span<const Body> bodies,
                                                          const Contact& contact) const {
  if (models_.pairs.empty()) return models::variantOf(models_.model);
  const Surface* a = patch::firstSurface(patch::shapesOf(bodies, contact, Side::A));
  const Surface* b = patch::firstSurface(patch::shapesOf(bodies, contact, Side::B));
  if (a == nullptr || b == nullptr) return models::variantOf(models_.model);
  return models::variantOf(models_.modelFor(*a, *b));
}

std::span<Contact* const> PatchSampler::keepSamples(std::span<const Body> bodies,
                                                    std::span<Contact> contacts,
                                                    const FrictionSettings& settings) {
  reuse_->reuse(bodies, contacts, settings, kept_);
  to_sample_.clear();
  for (size_t i = 0; i < contacts.size(); ++i)
    if (!kept_[i]) to_sample_.push_back(&contacts[i]);
  stats_.sampled = static_cast<int>(to_sample_.size());
  stats_.reused = static_cast<int>(contacts.size() - to_sample_.size());
  return to_sample_;
}

void PatchSampler::rememberSamples(std::span<const Body> bodies,
                                   std::span<const Contact> contacts) {
  reuse_->remember(bodies, contacts, kept_);
}

void PatchSampler::forgetHistory() {
  reuse_ = std::make_unique<patch::PatchReuse>();
}

void PatchSampler::saveHistory(StateWriter& out) const {
  reuse_->save(out);
}

void PatchSampler::loadHistory(StateReader& in) {
  reuse_->load(in);
}

}  // namespace asperity
