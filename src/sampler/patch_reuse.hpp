// Patch coherence (FrictionSettings::reuse_pixels): a contact whose two surfaces have moved,
// relative to each other and to the contact frame, by less than a set distance since the step
// that sampled its patch keeps that sample instead of rasterising the same pixels again. A
// resting stack then samples each contact once.
//
// What the patch sees of a surface is fixed by where the contact frame (point, t, b) and the
// depth clip lie on that surface's body, so each sample remembers the point, the point + w/2 t
// and the point + w/2 b in both bodies' frames, and phi. Along the normal a sample also holds
// while no fragment can have crossed the depth clip, when the sampler gives the margins of its
// clip decisions (DepthMargins), so that a face lying well inside the clip may rise and sink
// by more than the fixed tolerance. Contacts are matched across steps by their warm-start
// identity (bodies, shapes, key). The decisions are made before any sampling and depend on the
// contacts alone, so they are the same for every thread count.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/math/state_stream.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity::patch {

class PatchReuse {
 public:
  // For each contact, into `reused` (the caller's, so that its room is kept): 1 when its last
  // sample still holds (and is copied into it), else 0. Every contact gets 0 when
  // settings.reuse_pixels is 0 or the settings changed.
  void reuse(std::span<const Body> bodies, std::span<Contact> contacts,
             const FrictionSettings& settings, std::vector<uint8_t>& reused);
  // Where a sampler puts contact i's depth clip margins (A's, B's) when it samples it, between
  // reuse() and remember(); those it leaves know nothing.
  std::array<DepthMargins, 2>& margins(size_t i) { return margins_[i]; }
  // After sampling the others: remembers the freshly sampled contacts as they are now, keeps
  // the reused ones' original record and forgets the contacts that are gone.
  void remember(std::span<const Body> bodies, std::span<const Contact> contacts,
                std::span<const uint8_t> reused);
  // The kept samples and the settings they were taken with, saved and restored bit for bit
  // (World::saveState).
  void save(StateWriter& out) const;
  void load(StateReader& in);

 private:
  using Key = std::tuple<BodyId, BodyId, int, int, uint64_t>;
  struct Sample {
    std::array<Vec3, 3> on_a, on_b;  // the frame's three points in A's and B's body frames
    double phi = 0.0;
    std::array<DepthMargins, 2> depth;  // A's, B's
    DirectionalMu mu;
    int covered_pixels = 0;
    bool fallback = false;
  };
  // World to a body's frame, as a matrix: a contact's points are moved by one rotation made
  // once per body and call, cheaper than quaternion products per point.
  struct ToBody {
    Mat3 rotation;
    Vec3 origin;
    Vec3 point(const Vec3& world) const { return rotation * (world - origin); }
  };
  static Key keyOf(const Contact& c);
  // Body `id`'s ToBody in this call (made on first use; bodies do not move within a call).
  const ToBody& toBody(std::span<const Body> bodies, BodyId id);
  Sample record(std::span<const Body> bodies, const Contact& c,
                const std::array<DepthMargins, 2>& depth);
  // The index of `key` in sorted `keys` (kNone when absent), starting the search where
  // `cursor` stands and leaving it after the entry found.
  static constexpr size_t kNone = ~size_t{0};
  static size_t find(const std::vector<Key>& keys, const Key& key, size_t& cursor);

  // keys_[i] is the identity of the sample in slots_[slot_of_[i]], sorted; the keys are apart
  // from the (large) samples so that a lookup touches few cache lines, and a kept sample stays
  // in its slot from step to step (only its key and slot index move). The next_ buffers are
  // swapped in each step and the sort moves only (key, contact index) pairs, so that a warm
  // sampler does not allocate.
  std::vector<Key> keys_, next_keys_;
  std::vector<uint32_t> slot_of_, next_slot_of_;
  std::vector<Sample> slots_;
  std::vector<uint32_t> free_slots_;
  std::vector<uint8_t> slot_used_;
  std::vector<std::pair<Key, uint32_t>> order_;
  std::vector<std::array<DepthMargins, 2>> margins_;  // this call's, per contact
  std::vector<ToBody> to_body_;                       // per body, valid where stamped
  std::vector<uint64_t> to_body_stamp_;
  uint64_t call_ = 0;
  FrictionSettings settings_;  // those the samples were taken with
  double tolerance_ = 0.0;     // m: reuse_pixels patch pixels
};

}  // namespace asperity::patch
