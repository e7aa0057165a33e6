// Patch coherence (see patch_reuse.hpp).
#include "sampler/patch_reuse.hpp"

#include <algorithm>
#include <cmath>

namespace asperity::patch {

namespace {

struct Tolerance {
  double along = 0.0, depth = 0.0;  // m
};

bool sameSettings(const FrictionSettings& x, const FrictionSettings& y) {
  return x.directions == y.directions && x.mu0 == y.mu0 && x.mu_max == y.mu_max &&
         x.patch_width == y.patch_width && x.patch_resolution == y.patch_resolution &&
         x.reuse_pixels == y.reuse_pixels;
}

// The contact point and its points w/2 along t and b, in a body's frame.
std::array<Vec3, 3> framePoints(const Body& body, const Contact& c, double half_width) {
  return {body.pose.applyInverse(c.point), body.pose.applyInverse(c.point + half_width * c.t),
          body.pose.applyInverse(c.point + half_width * c.b)};
}

// Whether a body's frame points moved by less than the tolerances: `along` in the contact
// plane, `depth` along the normal (the depth clip is far thinner than a pixel is wide).
bool within(const Body& body, const Contact& c, const std::array<Vec3, 3>& then, double half_width,
            const Tolerance& tol) {
  const std::array<Vec3, 3> now = framePoints(body, c, half_width);
  const Vec3 n = body.pose.rotation.conjugate() * c.normal;
  for (size_t i = 0; i < 3; ++i) {
    const Vec3 d = now[i] - then[i];
    const double depth = d.dot(n);
    if (!(std::abs(depth) < tol.depth) || !((d - depth * n).norm() < tol.along)) return false;
  }
  return true;
}

}  // namespace

PatchReuse::Key PatchReuse::keyOf(const Contact& c) {
  return {c.body_a, c.body_b, c.shape_a, c.shape_b, c.key};
}

const PatchReuse::Sample* PatchReuse::find(const Key& key) const {
  const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
  return it != keys_.end() && *it == key ? &samples_[static_cast<size_t>(it - keys_.begin())]
                                         : nullptr;
}

PatchReuse::Sample PatchReuse::record(std::span<const Body> bodies, const Contact& c) const {
  const double half = 0.5 * settings_.patch_width;
  Sample s;
  s.on_a = framePoints(bodies[c.body_a], c, half);
  s.on_b = framePoints(bodies[c.body_b], c, half);
  s.phi = c.phi;
  s.mu = c.mu;
  s.covered_pixels = c.covered_pixels;
  s.fallback = c.fallback;
  return s;
}

void PatchReuse::reuse(std::span<const Body> bodies, std::span<Contact> contacts,
                       const FrictionSettings& settings, std::vector<uint8_t>& reused) {
  reused.assign(contacts.size(), 0);
  if (!sameSettings(settings, settings_)) {
    keys_.clear();
    samples_.clear();
  }
  settings_ = settings;
  tolerance_ = settings.reuse_pixels * settings.patch_width / settings.patch_resolution;
  if (!(tolerance_ > 0.0)) return;
  // Along the normal: the same share of the depth clip's margin (0.01 w, SPEC 3).
  const Tolerance tol{tolerance_, settings.reuse_pixels * 0.01 * settings.patch_width};
  const double half = 0.5 * settings.patch_width;
  for (size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Sample* found = find(keyOf(c));
    if (found == nullptr) continue;
    const Sample& s = *found;
    if (!(std::abs(c.phi - s.phi) < tol.depth) || !within(bodies[c.body_a], c, s.on_a, half, tol) ||
        !within(bodies[c.body_b], c, s.on_b, half, tol))
      continue;
    c.mu = s.mu;
    c.covered_pixels = s.covered_pixels;
    c.fallback = s.fallback;
    reused[i] = 1;
  }
}

void PatchReuse::remember(std::span<const Body> bodies, std::span<const Contact> contacts,
                          std::span<const uint8_t> reused) {
  keys_.swap(next_keys_);
  samples_.swap(next_samples_);
  keys_.clear();
  samples_.clear();
  if (!(tolerance_ > 0.0)) return;
  // By key, then contact order: of two contacts with one identity the first is kept.
  order_.clear();
  for (size_t i = 0; i < contacts.size(); ++i)
    order_.emplace_back(keyOf(contacts[i]), static_cast<uint32_t>(i));
  std::sort(order_.begin(), order_.end());
  for (const auto& [key, i] : order_) {
    if (!keys_.empty() && keys_.back() == key) continue;
    // The last step's records are in next_ now; a reused contact keeps its original one.
    const auto old = std::lower_bound(next_keys_.begin(), next_keys_.end(), key);
    const bool keep = reused[i] && old != next_keys_.end() && *old == key;
    keys_.push_back(key);
    samples_.push_back(keep ? next_samples_[static_cast<size_t>(old - next_keys_.begin())]
                            : record(bodies, contacts[i]));
  }
}

}  // namespace asperity::patch
