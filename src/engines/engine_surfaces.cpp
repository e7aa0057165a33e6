// The surfaces file of an engine adapter (asperity/engines/engine_surfaces.hpp): friction
// settings and one scene-style surface per engine object name.
#include "asperity/engines/engine_surfaces.hpp"

#include <algorithm>

#include "asperity/error.hpp"
#include "asperity/friction/directions.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/world/world.hpp"
#include "scene/scene_common.hpp"

namespace asperity {

namespace {

using scene::JsonReader;
using scene::Range;

// "settings": the ContactFrictionSettings a file may set (mu0 comes from the engine).
ContactFrictionSettings parseSettings(JsonReader r) {
  ContactFrictionSettings s;
  FrictionSettings& f = s.friction;
  if (r.has("mu0"))
    r.failAt("mu0",
             "the engine's own friction coefficient of a pair is mu0 (set it in the engine's "
             "model or near callback)");
  f.mu0 = 0.0;
  scene::parseFrictionSettings(r, f);
  s.provider = r.string("friction_provider", s.provider);
  s.models.model = r.enumeration("friction_model", s.models.model,
                                 EnumNames<FrictionModel>(kFrictionModelNames));
  scene::parseFrameSettings(r, s.frame);
  s.threads = r.integer("threads", s.threads, 0, kMaxThreads);
  r.finish();
  return s;
}

// One "surfaces" entry, its normal map resolved; resolving errors name the entry.
EngineSurface parseEntry(JsonReader& surfaces, const std::string& name, const std::string& base_dir,
                         Diagnostics& diagnostics) {
  JsonReader object = surfaces.object(name);
  std::optional<Mechanical> mechanical;
  nlohmann::json rest;
  EngineSurface entry{
      name, scene::parseSurface(scene::withoutMechanical(object, mechanical, rest), base_dir)};
  entry.surface.mechanical = mechanical;
  try {
    resolveSurface(entry.surface, diagnostics);
  } catch (const Error& e) {
    surfaces.failAt(name, e.what());
  }
  return entry;
}

}  // namespace

const Surface* EngineSurfaces::find(std::string_view name) const {
  const auto it =
      std::lower_bound(surfaces.begin(), surfaces.end(), name,
                       [](const EngineSurface& e, std::string_view n) { return e.name < n; });
  return it != surfaces.end() && it->name == name ? &it->surface : nullptr;
}

void EngineSurfaces::failAt(const std::string& name, const std::string& what) const {
  const nlohmann::json empty = nlohmann::json::object();
  JsonReader(empty, file.empty() ? "(surfaces)" : file, "/surfaces").failAt(name, what);
}

EngineSurfaces parseEngineSurfaces(const nlohmann::json& json,
                                   const std::string& file_for_messages) {
  EngineSurfaces out;
  out.file = file_for_messages;
  JsonReader root(json, file_for_messages);
  root.requireObject();
  out.settings = parseSettings(root.object("settings"));
  // The entries, in name order (JSON objects are sorted by key).
  JsonReader surfaces = root.object("surfaces");
  const std::string base_dir = scene::parentFolder(file_for_messages);
  for (const auto& item : surfaces.value().items())
    out.surfaces.push_back(parseEntry(surfaces, item.key(), base_dir, out.diagnostics));
  surfaces.finish();
  root.finish();
  return out;
}

EngineSurfaces loadEngineSurfaces(const std::string& path) {
  return parseEngineSurfaces(scene::parseJsonFile(path), path);
}

}  // namespace asperity
