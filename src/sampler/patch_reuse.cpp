// Patch coherence (see patch_reuse.hpp).
#include "sampler/patch_reuse.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/error.hpp"

namespace asperity::patch {

namespace {

// A pixel centre crossing a face's edge within the tolerated move changes a sample's means by
// up to the coefficients' spread over its pixel count. Samples of fewer than 32 pixels are
// therefore kept only while they move by that share of the tolerance in the contact plane (a
// one-pixel sample by 1 / 32 of it: a box of a fallen stack leaning on another by its edge kept
// a one-pixel sample of mu 0.90 for 50 steps at the full tolerance where a fresh one found
// none), and not while sliding along a plain plane (alikeEverywhere; on the crawling worm's
// sawtooth skin they strayed by up to 0.37 in mu, kept step after step).
constexpr int kFewestPixelsToSlide = 32;

struct Tolerance {
  double along = 0.0, depth = 0.0;  // m
};

bool sameSettings(const FrictionSettings& x, const FrictionSettings& y) {
  return x.directions == y.directions && x.mu0 == y.mu0 && x.mu_max == y.mu_max &&
         x.patch_width == y.patch_width && x.patch_resolution == y.patch_resolution &&
         x.reuse_pixels == y.reuse_pixels && x.texel_reading == y.texel_reading;
}

// The contact point and its points w/2 along t and b, in a body's frame.
template <typename ToBody>
std::array<Vec3, 3> framePoints(const ToBody& body, const Contact& c, double half_width) {
  return {body.point(c.point), body.point(c.point + half_width * c.t),
          body.point(c.point + half_width * c.b)};
}

// How far a body moved since the sample, relative to the contact frame: the largest
// displacement of the frame's points in the contact plane and along the normal, and the range
// [rise_least, rise_most] of its surface's move along n over the whole footprint. (A rigid
// motion's normal displacement is affine over the plane: at the footprint's corners it is
// d0 +- (|d1 - d0| + |d2 - d0|).) NaN stays NaN.
struct Motion {
  double along = 0.0, depth = 0.0, tilt = 0.0, rise_least = 0.0, rise_most = 0.0;
};

template <typename ToBody>
Motion motionOf(const ToBody& to_body, const Contact& c, const std::array<Vec3, 3>& then,
                double half_width) {
  const std::array<Vec3, 3> now = framePoints(to_body, c, half_width);
  const Vec3 n = to_body.rotation * c.normal;
  std::array<double, 3> d{};
  Motion m;
  double along_squared = 0.0;  // one root for the largest (the root keeps the order)
  for (size_t i = 0; i < 3; ++i) {
    const Vec3 delta = now[i] - then[i];
    d[i] = delta.dot(n);
    along_squared = std::max((delta - d[i] * n).squaredNorm(), along_squared);
    m.depth = std::max(std::abs(d[i]), m.depth);
  }
  m.along = std::sqrt(along_squared);
  // The frame point moved by d along n on the body: the body's surface by -d in the frame.
  m.tilt = std::max(std::abs(d[1] - d[0]), std::abs(d[2] - d[0]));
  const double spread = std::abs(d[1] - d[0]) + std::abs(d[2] - d[0]);
  m.rise_least = -d[0] - spread;
  m.rise_most = -d[0] + spread;
  return m;
}

// Whether every clip decision of a surface with these margins still holds after it rose by
// [m.rise_least, m.rise_most] and the clip's half depth grew by `grow`: a kept fragment stays
// inside each plane and a clipped one beyond it.
bool clipHolds(const Motion& m, double grow, const DepthMargins& d) {
  // Beside z = h the fragment's h - z changes by grow - rise; beside z = -h its z + h by
  // rise + grow.
  return grow - m.rise_most > -d.in_top && grow - m.rise_least < d.out_top &&
         m.rise_least + grow > -d.in_bottom && m.rise_most + grow < d.out_bottom;
}

// Whether the sample still holds: both bodies moved by less than `along` in the contact plane,
// and along the normal by less than the fixed tolerance (the depth clip is far thinner than a
// pixel is wide) or so that no fragment crossed the clip, itself grown by half the change of
// |phi|. A rise along n changes nothing else (the patch is seen along n); a tilt also turns
// the meso normals, so it stays within the fixed tolerance either way.
bool holds(const Motion& a, const Motion& b, double phi_then, double phi_now,
           const std::array<DepthMargins, 2>& depth, const Tolerance& tol) {
  if (!(a.along < tol.along && b.along < tol.along)) return false;
  if (std::abs(phi_now - phi_then) < tol.depth && a.depth < tol.depth && b.depth < tol.depth)
    return true;
  if (!(a.tilt < tol.depth && b.tilt < tol.depth)) return false;
  const double grow = 0.5 * (std::abs(phi_now) - std::abs(phi_then));
  return clipHolds(a, grow, depth[0]) && clipHolds(b, grow, depth[1]);
}

// Whether every point of the contact's surface on this body looks the same to the patch: an
// untextured plane covers the whole footprint with coefficients of 0 wherever the frame lies
// on it, so moving along it changes nothing a sample saw (a box sliding on a plain floor keeps
// its sample while it keeps its place under the frame). Its rise and tilt still count.
bool alikeEverywhere(const Body& body, int shape) {
  if (shape < 0 && body.shapes.size() != 1) return false;
  const Shape& s = body.shapes[static_cast<size_t>(std::max(shape, 0))];
  return s.type == ShapeType::Plane && s.surface.normal_map == nullptr;
}

// Margins less a sliver far above the rounding of the margins and of the motion.
DepthMargins lessRounding(DepthMargins d, double width) {
  const double sliver = 1e-9 * width;
  for (double* m : {&d.in_top, &d.out_top, &d.in_bottom, &d.out_bottom})
    *m = std::max(0.0, *m - sliver);
  return d;
}

}  // namespace

PatchReuse::Key PatchReuse::keyOf(const Contact& c) {
  return {c.body_a, c.body_b, c.shape_a, c.shape_b, c.key};
}

size_t PatchReuse::find(const std::vector<Key>& keys, const Key& key, size_t& cursor) {
  // Contacts arrive sorted by their identity nearly always: the cursor's entry is the one
  // looked for, or a binary search finds it.
  if (cursor >= keys.size() || keys[cursor] != key) {
    cursor = static_cast<size_t>(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin());
    if (cursor == keys.size() || keys[cursor] != key) return kNone;
  }
  return cursor++;
}

const PatchReuse::ToBody& PatchReuse::toBody(std::span<const Body> bodies, BodyId id) {
  if (to_body_.size() < bodies.size()) {
    to_body_.resize(bodies.size());
    to_body_stamp_.resize(bodies.size(), ~uint64_t{0});  // made in no call yet
  }
  ToBody& t = to_body_[id];
  if (to_body_stamp_[id] != call_) {
    const Body& body = bodies[id];
    t = {body.pose.rotation.conjugate().toRotationMatrix(), body.pose.position};
    to_body_stamp_[id] = call_;
  }
  return t;
}

PatchReuse::Sample PatchReuse::record(std::span<const Body> bodies, const Contact& c,
                                      const std::array<DepthMargins, 2>& depth) {
  const double half = 0.5 * settings_.patch_width;
  Sample s;
  s.on_a = framePoints(toBody(bodies, c.body_a), c, half);
  s.on_b = framePoints(toBody(bodies, c.body_b), c, half);
  s.phi = c.phi;
  s.depth = {lessRounding(depth[0], settings_.patch_width),
             lessRounding(depth[1], settings_.patch_width)};
  s.mu = c.mu;
  s.covered_pixels = c.covered_pixels;
  s.fallback = c.fallback;
  return s;
}

void PatchReuse::reuse(std::span<const Body> bodies, std::span<Contact> contacts,
                       const FrictionSettings& settings, std::vector<uint8_t>& reused) {
  reused.assign(contacts.size(), 0);
  margins_.assign(contacts.size(), {});
  ++call_;  // the bodies may have moved since the last call
  if (!sameSettings(settings, settings_)) {
    keys_.clear();
    slot_of_.clear();
    slots_.clear();
    free_slots_.clear();
  }
  settings_ = settings;
  tolerance_ = settings.reuse_pixels * settings.patch_width / settings.patch_resolution;
  if (!(tolerance_ > 0.0)) return;
  // Along the normal: the same share of the depth clip's margin (0.01 w, SPEC 3).
  const Tolerance tol{tolerance_, settings.reuse_pixels * 0.01 * settings.patch_width};
  const double half = 0.5 * settings.patch_width;
  size_t cursor = 0;
  for (size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const size_t found = find(keys_, keyOf(c), cursor);
    if (found == kNone) continue;
    const Sample& s = slots_[slot_of_[found]];
    Tolerance own = tol;
    if (s.covered_pixels < kFewestPixelsToSlide)
      own.along *= static_cast<double>(s.covered_pixels) / kFewestPixelsToSlide;
    Motion a = motionOf(toBody(bodies, c.body_a), c, s.on_a, half);
    Motion b = motionOf(toBody(bodies, c.body_b), c, s.on_b, half);
    if (!holds(a, b, s.phi, c.phi, s.depth, own)) {
      if (s.covered_pixels < kFewestPixelsToSlide) continue;
      if (alikeEverywhere(bodies[c.body_a], c.shape_a)) a.along = 0.0;
      if (alikeEverywhere(bodies[c.body_b], c.shape_b)) b.along = 0.0;
      if (!holds(a, b, s.phi, c.phi, s.depth, tol)) continue;
    }
    // The directions in use only (the rest stay as the contact has them: 0).
    c.mu.count = s.mu.count;
    std::copy_n(s.mu.mu.begin(), s.mu.count, c.mu.mu.begin());
    c.covered_pixels = s.covered_pixels;
    c.fallback = s.fallback;
    reused[i] = 1;
  }
}

void PatchReuse::remember(std::span<const Body> bodies, std::span<const Contact> contacts,
                          std::span<const uint8_t> reused) {
  keys_.swap(next_keys_);
  slot_of_.swap(next_slot_of_);
  keys_.clear();
  slot_of_.clear();
  if (!(tolerance_ > 0.0)) {
    slots_.clear();
    free_slots_.clear();
    return;
  }
  // By key, then contact order: of two contacts with one identity the first is kept. The
  // contacts are nearly always in key order already (the collision stage sorts them by bodies
  // and key): then they are taken as they come.
  order_.clear();
  for (size_t i = 0; i < contacts.size(); ++i)
    order_.emplace_back(keyOf(contacts[i]), static_cast<uint32_t>(i));
  if (!std::is_sorted(order_.begin(), order_.end())) std::sort(order_.begin(), order_.end());
  // The last step's keys and slots are in next_ now. A kept sample stays in its slot; a contact
  // sampled afresh takes its identity's old slot, else a free one; the slots of identities gone
  // are freed after.
  slot_used_.assign(slots_.size(), 0);
  size_t cursor = 0;
  for (const auto& [key, i] : order_) {
    if (!keys_.empty() && keys_.back() == key) continue;
    const size_t old = find(next_keys_, key, cursor);
    uint32_t slot = 0;
    if (old != kNone) {
      slot = next_slot_of_[old];
    } else if (!free_slots_.empty()) {
      slot = free_slots_.back();
      free_slots_.pop_back();
    } else {
      slot = static_cast<uint32_t>(slots_.size());
      slots_.emplace_back();
      slot_used_.push_back(0);
    }
    if (!reused[i]) slots_[slot] = record(bodies, contacts[i], margins_[i]);
    slot_used_[slot] = 1;
    keys_.push_back(key);
    slot_of_.push_back(slot);
  }
  for (const uint32_t slot : next_slot_of_)
    if (!slot_used_[slot]) free_slots_.push_back(slot);
}

void PatchReuse::save(StateWriter& out) const {
  out.putBytes(&settings_, sizeof(settings_));
  out.put(tolerance_);
  out.put<uint64_t>(keys_.size());
  for (size_t i = 0; i < keys_.size(); ++i) {
    const auto& [a, b, shape_a, shape_b, key] = keys_[i];
    out.put(a), out.put(b), out.put(shape_a), out.put(shape_b), out.put(key);
    // A sample is numbers only (points, depths, coefficients, counts): its bytes as they are.
    out.putBytes(&slots_[slot_of_[i]], sizeof(Sample));
  }
}

void PatchReuse::load(StateReader& in) {
  in.getBytes(&settings_, sizeof(settings_));
  tolerance_ = in.get<double>();
  const size_t count = in.count(sizeof(Sample));
  keys_.resize(count);
  slots_.resize(count);
  slot_of_.resize(count);
  free_slots_.clear();
  for (size_t i = 0; i < count; ++i) {
    slot_of_[i] = static_cast<uint32_t>(i);
    auto& [a, b, shape_a, shape_b, key] = keys_[i];
    a = in.get<BodyId>(), b = in.get<BodyId>();
    shape_a = in.get<int>(), shape_b = in.get<int>();
    key = in.get<uint64_t>();
    in.getBytes(static_cast<void*>(&slots_[i]), sizeof(Sample));
    // A kept sample's coefficients are copied into contacts as they are: their count must be
    // one a contact can hold.
    if (slots_[i].mu.count < 0 || slots_[i].mu.count > kMaxDirections)
      throw Error("the state's kept patch sample " + std::to_string(i) + " has " +
                  std::to_string(slots_[i].mu.count) + " directions");
  }
}

}  // namespace asperity::patch
