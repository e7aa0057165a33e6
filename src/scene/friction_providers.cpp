// The name -> factory table of friction providers, one per front end or world owner.
#include "asperity/scene/friction_providers.hpp"

#include "asperity/error.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/sampler/constant_provider.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"

namespace asperity {

FrictionProviders FrictionProviders::builtIn() {
  // The core library's own providers; the default scene sampler is one of them.
  FrictionProviders providers;
  providers.add("constant", [] { return std::make_unique<ConstantProvider>(); });
  providers.add("cone", [] { return std::make_unique<ConeProvider>(); });
  providers.add("cpu", [] { return std::make_unique<CpuPatchSampler>(); });
  return providers;
}

void FrictionProviders::add(const std::string& name, FrictionProviderFactory factory) {
  if (name.empty() || !factory) throw Error("FrictionProviders::add: empty name or factory");
  factories_[name] = std::move(factory);
}

bool FrictionProviders::has(const std::string& name) const {
  return factories_.count(name) > 0;
}

std::unique_ptr<FrictionProvider> FrictionProviders::make(const std::string& name) const {
  const auto it = factories_.find(name);
  if (it == factories_.end()) {
    // The message lists what this table offers, so a typo is easy to fix.
    std::string list;
    for (const std::string& n : names()) list += (list.empty() ? "" : ", ") + n;
    throw Error("unknown friction sampler \"" + name + "\" (available: " + list + ")");
  }
  return it->second();
}

std::vector<std::string> FrictionProviders::names() const {
  std::vector<std::string> names;
  for (const auto& [name, factory] : factories_) names.push_back(name);
  return names;
}

}  // namespace asperity
