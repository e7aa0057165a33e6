// Friction providers by name, for scene files ("settings": {"sampler": "cone"}) and the CLI.
// Built in: "constant", "cone" and "cpu" (the CPU patch sampler). Others (the OpenGL sampler)
// register a factory once before scenes are instantiated, from a function the front end calls.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

using FrictionProviderFactory = std::function<std::unique_ptr<FrictionProvider>()>;

// Adds or replaces the factory for `name` (thread-safe).
void registerFrictionProvider(const std::string& name, FrictionProviderFactory factory);
// True when `name` has a factory.
bool hasFrictionProvider(const std::string& name);
// A new provider; throws asperity::Error `unknown friction sampler "x" (available: ...)`.
std::unique_ptr<FrictionProvider> makeFrictionProvider(const std::string& name);
// Every registered name, sorted.
std::vector<std::string> frictionProviderNames();

}  // namespace asperity
