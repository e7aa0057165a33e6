// The stage between collision and solve: it fills every contact's per-direction friction
// coefficients (Contact::mu, covered_pixels, fallback). One call per step for all contacts.
// Implementations: constant (mu0 only), cone (whole-texture cones), and the patch samplers
// (CPU reference, OpenGL) of SPEC 3.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"

namespace asperity {

// The friction provider of a world built in code and of a scene that names none: whole-texture
// cones (sampler/cone_provider.hpp), anisotropic from the textures at almost no cost.
inline constexpr const char* kDefaultFrictionProvider = "cone";

// How a patch pixel reads the normal map and gain mask at its uv (docs/samplers.md).
enum class TexelReading {
  // The texel the pixel's centre falls in: each texel is one facet, as the paper builds its
  // materials (one facet per 1 x 1 mm texel) and as the authors' code samples its maps.
  Nearest,
  // The four texels around the uv blended before Eq. 5. Eq. 5 is nonlinear in a facet's tilt,
  // so a blend flattens facets and reads rough maps smoother than their own texels (concrete
  // about 40 % low); kept to show that difference.
  Bilinear,
};
inline constexpr std::pair<const char*, TexelReading> kTexelReadingNames[] = {
    {"nearest", TexelReading::Nearest}, {"bilinear", TexelReading::Bilinear}};

// What every provider needs to know (SPEC 3, Eq. 7).
struct FrictionSettings {
  int directions = 4;         // N
  double mu0 = 0.2;           // nominal coefficient (unit: 1)
  float mu_max = 4.0f;        // clamp of the ploughing term
  double patch_width = 0.02;  // w (m)
  int patch_resolution = 16;  // R (pixels per side)
  // Patch coherence (cpu and gl samplers): a contact whose surfaces moved by less than this
  // many patch pixels (w / R each) since its patch was sampled keeps that sample; a kept
  // sample's mu differs from a fresh one by what a sub-pixel move changes (pixel centres that
  // crossed a texel edge read the next facet): mostly below 0.005, a few hundredths at most on
  // rough maps (docs/samplers.md). 0: sample every call.
  // Samples are matched across calls by the contact's identity (bodies, shapes, key): after
  // changing a body's shapes or surfaces, call forgetHistory() (World::forgetContactHistory).
  double reuse_pixels = 0.1;
  // How each patch pixel reads the textures (cpu and gl samplers).
  TexelReading texel_reading = TexelReading::Nearest;
};

class ThreadPool;  // the world's worker threads (internal)
class StateReader;  // asperity/math/state_stream.hpp
class StateWriter;

class FrictionProvider {
 public:
  virtual ~FrictionProvider() = default;
  // The world's worker threads for the next calls (null: the calling thread only). A provider
  // may spread its contacts over them; its results must not depend on how many there are.
  virtual void setThreadPool(const ThreadPool* pool) { (void)pool; }
  virtual std::string name() const = 0;
  // Fills mu (count = settings.directions), covered_pixels and fallback of every contact.
  // Contacts already carry their frame (t, b). Body A of a contact is bodies[c.body_a].
  virtual void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                                   const FrictionSettings& settings) = 0;
  // The same work in two calls, for a provider whose work runs on another device (a GPU):
  // startCoefficients queues it, finishCoefficients waits for it and fills the contacts given
  // to start, which stay alive and unchanged in between. The world sets up the solver's rows,
  // which need no coefficients, in between. By default start does everything.
  virtual void startCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                                 const FrictionSettings& settings) {
    computeCoefficients(bodies, contacts, settings);
  }
  virtual void finishCoefficients() {}
  // True when the coefficients depend on each contact's load: the world then gives every
  // contact last step's normal impulse (Contact::lambda_n) before computeCoefficients. Finding
  // them is a search per contact, so a provider that ignores the load says no.
  virtual bool readsNormalLoads() const { return false; }
  // True when startCoefficients returns before the work is done, so that overlapping pays.
  virtual bool runsAsynchronously() const { return false; }
  // Time spent in the last call, split as the paper's Table 1 does (ms).
  virtual double lastPatchTimeMs() const { return 0.0; }
  virtual double lastAveragingTimeMs() const { return 0.0; }
  // Contacts of the last call that kept an earlier sample (FrictionSettings::reuse_pixels).
  virtual int lastReusedCount() const { return 0; }
  // Forgets what earlier calls left behind (kept samples), as in a new provider.
  virtual void forgetHistory() {}
  // What earlier calls left for the next one (kept samples), saved and restored bit for bit
  // (World::saveState); a provider that keeps nothing writes nothing.
  virtual void saveHistory(StateWriter& out) const { (void)out; }
  virtual void loadHistory(StateReader& in) { (void)in; }
};

}  // namespace asperity
