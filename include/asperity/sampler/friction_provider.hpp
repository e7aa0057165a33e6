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
#include "asperity/friction/friction_model.hpp"
#include "asperity/sampler/friction_settings.hpp"

namespace asperity {

// The friction provider of a world built in code and of a scene that names none: whole-texture
// cones (sampler/cone_provider.hpp), anisotropic from the textures at almost no cost.
inline constexpr const char* kDefaultFrictionProvider = "cone";

class ThreadPool;   // the world's worker threads (internal)
class StateReader;  // asperity/math/state_stream.hpp
class StateWriter;

// A provider's figures for its last call, split as the paper's Table 1 does.
struct ProviderStats {
  double patch_ms = 0.0;      // finding the patches' fragments (CPU time summed over threads)
  double averaging_ms = 0.0;  // reducing them to coefficients
  int sampled = 0;            // contacts sampled afresh
  int reused = 0;  // contacts that kept an earlier sample (FrictionSettings::reuse_pixels)
  int passes = 0;  // device passes (the OpenGL sampler's atlas fills)
};

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
  // Which friction model each contact uses (friction/friction_model.hpp). Patch samplers serve
  // every model; a provider without patches serves the paper's only and throws asperity::Error
  // naming itself for settings that ask for another.
  virtual void setFrictionModels(const FrictionModelSettings& models);
  // True when the coefficients depend on each contact's load: the world then gives every
  // contact last step's normal impulse (Contact::lambda_n) before computeCoefficients. Finding
  // them is a search per contact, so a provider that ignores the load says no.
  virtual bool readsNormalLoads() const { return false; }
  // True when startCoefficients returns before the work is done, so that overlapping pays.
  virtual bool runsAsynchronously() const { return false; }
  // The figures of the last call.
  virtual ProviderStats lastStats() const { return {}; }
  // Forgets what earlier calls left behind (kept samples), as in a new provider.
  virtual void forgetHistory() {}
  // What earlier calls left for the next one (kept samples), saved and restored bit for bit
  // (World::saveState); a provider that keeps nothing writes nothing.
  virtual void saveHistory(StateWriter& out) const { (void)out; }
  virtual void loadHistory(StateReader& in) { (void)in; }
};

}  // namespace asperity
