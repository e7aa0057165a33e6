// Stage 3 of a step (SPEC 5, docs/step.md): each contact's tangent frame (t, b), b = n x t.
// One file per frame mode in this folder; contact_frames.cpp holds the one table that
// dispatches on FrameMode.
#pragma once

#include <functional>
#include <span>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/math/types.hpp"
#include "asperity/world/world.hpp"

namespace asperity {

class ContactSolver;
class ThreadPool;

// What the frame modes read.
struct FrameInputs {
  std::span<const Body> bodies;
  Vec3 world_axis = Vec3::UnitX();
  Vec3 fallback_axis = Vec3::UnitY();
  // Body mode: the world's frame callback with the world bound (empty: none).
  std::function<Vec3(const Contact&)> callback;
  // Auto mode: runs a few frictionless PGS iterations over the contacts and returns the
  // solver holding the predicted velocities; contacts slower than `sliding_speed` (m/s) keep
  // the world frame.
  std::function<const ContactSolver&(std::span<const Contact>)> frictionless_solve;
  double sliding_speed = 1e-3;
};

// Sets every contact's (t, b) by `mode`. Contacts are independent, so they are split over
// the pool's threads, except that a user's frame callback is only ever called from this one.
void computeContactFrames(FrameMode mode, const FrameInputs& in, std::span<Contact> contacts,
                          const ThreadPool& pool);

// `axis` projected on the plane of `n`, normalised; `fallback` when that projection is
// shorter than 1e-6 |axis|; any unit vector perpendicular to n when both vanish.
Vec3 projectedTangent(const Vec3& n, const Vec3& axis, const Vec3& fallback);

// Sets c.t from a desired tangent (projected on the contact plane, with `fallback` as in
// projectedTangent) and c.b = n x t.
void setContactFrame(Contact& c, const Vec3& desired_t, const Vec3& fallback);

}  // namespace asperity
