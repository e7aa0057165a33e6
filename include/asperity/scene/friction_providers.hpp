// Friction providers by name, for scene files ("settings": {"friction_provider": "cone"}) and
// the CLI (--sampler).
// A FrictionProviders table belongs to whoever instantiates worlds (a command, a viewer, a test):
// there is no process-wide registry. builtIn() holds the core library's "constant", "cone" and
// "cpu"; other targets add theirs (the OpenGL sampler: addGlPatchSampler, gl_sampler_provider.hpp).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

using FrictionProviderFactory = std::function<std::unique_ptr<FrictionProvider>()>;

class FrictionProviders {
 public:
  // The core library's providers: "constant", "cone" and "cpu" (the CPU patch sampler).
  static FrictionProviders builtIn();

  // Adds or replaces the factory for `name`; throws asperity::Error for an empty name or factory.
  void add(const std::string& name, FrictionProviderFactory factory);
  // True when `name` has a factory.
  bool has(const std::string& name) const;
  // A new provider; throws asperity::Error `unknown friction sampler "x" (available: ...)`.
  std::unique_ptr<FrictionProvider> make(const std::string& name) const;
  // Every name with a factory, sorted.
  std::vector<std::string> names() const;

 private:
  std::map<std::string, FrictionProviderFactory> factories_;
};

}  // namespace asperity
