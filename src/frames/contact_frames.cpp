// The contact-frame stage (asperity/frames/contact_frames.hpp) and the one table of modes.
#include "asperity/frames/contact_frames.hpp"

#include <array>
#include <cmath>

#include "frames/frame_modes.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

// Indexed by FrameMode: World, Body, Auto, Texture.
constexpr std::array<FrameModeRule, std::size(kFrameModeNames)> kFrameModeRules = {{
    {worldFrameTangent, nullptr, false},
    {bodyFrameTangent, nullptr, true},
    {worldFrameTangent, alignFramesWithSliding, false},
    {textureFrameTangent, nullptr, false},
}};

}  // namespace

void computeContactFrames(FrameMode mode, const FrameInputs& in, std::span<Contact> contacts,
                          const ThreadPool* pool) {
  const FrameModeRule& rule = kFrameModeRules.at(static_cast<size_t>(mode));
  // Each contact's frame alone, so threads may share the contacts; a user's frame callback
  // is only ever called from this thread.
  const bool user_code = rule.calls_user_code && in.callback;
  const size_t grain = user_code ? contacts.size() : 64;
  forEachOn(pool, contacts.size(), grain, [&](size_t i) {
    Contact& c = contacts[i];
    setContactFrame(c, rule.desired(in, c), in.fallback_axis);
  });
  if (rule.refine) rule.refine(in, contacts);
}

Vec3 projectedTangent(const Vec3& n, const Vec3& axis, const Vec3& fallback) {
  // Remove the normal component; a vanishing projection falls back to the next axis.
  const Vec3 t = axis - axis.dot(n) * n;
  if (t.norm() > 1e-6 * axis.norm() && t.norm() > 0.0) return t.normalized();
  const Vec3 f = fallback - fallback.dot(n) * n;
  if (f.norm() > 1e-6 * fallback.norm() && f.norm() > 0.0) return f.normalized();
  // Last resort: any perpendicular.
  return anyPerpendicular(n).cross(n);
}

void setContactFrame(Contact& c, const Vec3& desired_t, const Vec3& fallback) {
  c.t = projectedTangent(c.normal, desired_t, fallback);
  c.b = c.normal.cross(c.t);  // SPEC 1: right-handed (t, b, n)
}

}  // namespace asperity
