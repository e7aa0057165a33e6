// The name -> factory table of friction providers. Built-in providers are listed here; other
// targets add theirs through registerFrictionProvider.
#include "asperity/scene/friction_registry.hpp"

#include <map>
#include <mutex>

#include "asperity/error.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/sampler/constant_provider.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"

namespace asperity {

namespace {

// Created on first use with the core library's own providers.
struct Registry {
  Registry() {
    factories["constant"] = [] { return std::make_unique<ConstantProvider>(); };
    factories["cone"] = [] { return std::make_unique<ConeProvider>(); };
    factories["cpu"] = [] { return std::make_unique<CpuPatchSampler>(); };
  }
  std::mutex mutex;
  std::map<std::string, FrictionProviderFactory> factories;
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

void registerFrictionProvider(const std::string& name, FrictionProviderFactory factory) {
  if (name.empty() || !factory) throw Error("registerFrictionProvider: empty name or factory");
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.factories[name] = std::move(factory);
}

bool hasFrictionProvider(const std::string& name) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  return r.factories.count(name) > 0;
}

std::unique_ptr<FrictionProvider> makeFrictionProvider(const std::string& name) {
  FrictionProviderFactory factory;
  {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    const auto it = r.factories.find(name);
    if (it != r.factories.end()) factory = it->second;
  }
  if (!factory) {
    std::string list;
    for (const std::string& n : frictionProviderNames()) list += (list.empty() ? "" : ", ") + n;
    throw Error("unknown friction sampler \"" + name + "\" (available: " + list + ")");
  }
  return factory();
}

std::vector<std::string> frictionProviderNames() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& [name, factory] : r.factories) names.push_back(name);
  return names;
}

}  // namespace asperity
