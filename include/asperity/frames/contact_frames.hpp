// Stage 3 of a step (SPEC 5, docs/step.md): each contact's tangent frame (t, b), b = n x t.
// Callable without a World: an engine that hands its own contacts in, or a test, sets their
// frames here. One file per frame mode in src/frames/; contact_frames.cpp holds the one table
// that dispatches on FrameMode.
#pragma once

#include <functional>
#include <span>
#include <utility>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

class ThreadPool;  // a world's worker threads (internal)

// How each contact's tangent t is chosen (SPEC 5).
enum class FrameMode {
  World,   // world_axis projected on the contact plane (fallback_axis when that vanishes)
  Body,    // body-local frame_axis of A, else of B, else the frame callback, else World
  Auto,    // along the relative sliding velocity after a few frictionless iterations
  Texture  // along the +u direction of B's texture (planes and boxes), else World
};
inline constexpr std::pair<const char*, FrameMode> kFrameModeNames[] = {
    {"world", FrameMode::World},
    {"body", FrameMode::Body},
    {"auto", FrameMode::Auto},
    {"texture", FrameMode::Texture}};

// How contact frames are chosen: one struct for a World (WorldSettings::frame) and an engine
// adapter (ContactFrictionSettings::frame).
struct FrameSettings {
  FrameMode mode = FrameMode::World;
  Vec3 world_axis = Vec3::UnitX();
  Vec3 fallback_axis = Vec3::UnitY();
  // m/s: in mode Auto, contacts sliding slower than this keep the world frame; an engine
  // adapter also keeps a contact's last sliding sense below it.
  double sliding_speed = 1e-3;
};

// Every body's velocities as a frictionless solve predicts them (frame mode Auto), indexed
// by BodyId. They must stay valid while computeContactFrames runs.
struct PredictedVelocities {
  std::span<const Vec3> linear;
  std::span<const Vec3> angular;
};

// What the frame modes read.
struct FrameInputs {
  std::span<const Body> bodies;
  Vec3 world_axis = Vec3::UnitX();
  Vec3 fallback_axis = Vec3::UnitY();
  // Body mode: the desired tangent of a contact from user code (empty: none).
  std::function<Vec3(const Contact&)> callback;
  // Auto mode: the velocities a few frictionless iterations over these contacts predict (a
  // World binds the solver's predictFrictionless). Empty: Auto keeps the world frames.
  // Contacts slower than `sliding_speed` (m/s) keep the world frame.
  std::function<PredictedVelocities(std::span<const Contact>)> predict_velocities;
  double sliding_speed = 1e-3;
};

// Sets every contact's (t, b) by `mode`. Contacts are independent, so they are split over
// the pool's threads (null: the calling thread only), except that a frame callback is only
// ever called from the calling thread. The same bits on any thread count.
void computeContactFrames(FrameMode mode, const FrameInputs& in, std::span<Contact> contacts,
                          const ThreadPool* pool = nullptr);

// `axis` projected on the plane of `n`, normalised; `fallback` when that projection is
// shorter than 1e-6 |axis|; any unit vector perpendicular to n when both vanish.
Vec3 projectedTangent(const Vec3& n, const Vec3& axis, const Vec3& fallback);

// Sets c.t from a desired tangent (projected on the contact plane, with `fallback` as in
// projectedTangent) and c.b = n x t.
void setContactFrame(Contact& c, const Vec3& desired_t, const Vec3& fallback);

}  // namespace asperity
