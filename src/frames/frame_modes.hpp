// The frame modes (SPEC 5), one file each, private to frames/. A mode gives each contact a
// desired tangent (projected on the contact plane by computeContactFrames) and may refine all
// frames afterwards. Adding a mode (docs/step.md): its file, a FrameMode value with its name
// (asperity/world/world.hpp), and its row in kFrameModeRules (contact_frames.cpp).
#pragma once

#include <span>

#include "asperity/frames/contact_frames.hpp"

namespace asperity {

struct FrameModeRule {
  // The desired tangent t of one contact (need not be unit or in the contact plane).
  Vec3 (*desired)(const FrameInputs& in, const Contact& c);
  // A pass over all the frames after the per-contact one, or nullptr.
  void (*refine)(const FrameInputs& in, std::span<Contact> contacts);
  // Whether `desired` may call user code (then it runs on the calling thread only).
  bool calls_user_code;
};

// world_frame.cpp: the world axis.
Vec3 worldFrameTangent(const FrameInputs& in, const Contact& c);
// body_frame.cpp: A's body-local axis, else B's, else the callback, else the world axis.
Vec3 bodyFrameTangent(const FrameInputs& in, const Contact& c);
// texture_frame.cpp: +u of B's texture at the contact, else the world axis.
Vec3 textureFrameTangent(const FrameInputs& in, const Contact& c);
// auto_frame.cpp: after world frames, t along A's sliding over B predicted without friction.
void alignFramesWithSliding(const FrameInputs& in, std::span<Contact> contacts);

}  // namespace asperity
