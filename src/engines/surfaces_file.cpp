// Surfaces files of the engine adapters (asperity/engines/surfaces_file.hpp): the scene
// reader's surface objects under the names of another engine's objects.
#include "asperity/engines/surfaces_file.hpp"

#include <utility>

#include "scene/scene_common.hpp"
#include "scene/scene_resources.hpp"

namespace asperity {

SurfacesFile loadSurfacesFile(const std::string& path) {
  SurfacesFile out;
  out.path = path;
  const nlohmann::json json = scene::parseJsonFile(path);
  scene::JsonReader root(json, path);
  root.requireObject();
  scene::JsonReader table = root.object("surfaces");
  const std::string base_dir = scene::parentFolder(path);
  scene::ResourceCache cache(base_dir);
  // One surface per object name, read as a scene shape's "surface" and resolved as a scene's
  // are (paths relative to the file's folder, equal maps shared).
  for (const auto& entry : table.value().items()) {
    if (entry.key().empty()) table.fail("an object name must not be empty");
    Surface surface = scene::parseSurfaceObject(table.object(entry.key()), base_dir);
    surface.normal_map = cache.normalMap(surface, out.diagnostics);
    surface.mask = cache.mask(surface.source.mask_file);
    out.surfaces.emplace(entry.key(), std::move(surface));
  }
  table.finish();
  root.finish();
  return out;
}

Error unknownObjectError(const SurfacesFile& file, const std::string& name,
                         const std::vector<std::string>& known) {
  // The engine's names, quoted.
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "\"" : ", \"") + k + "\"";
  // The entry's JSON pointer, escaped as the scene reader's errors escape it.
  const nlohmann::json none;
  const scene::JsonReader table(none, file.path, "/surfaces");
  return Error(file.path + ": " + table.childPointer(name) + ": unknown object \"" + name + "\" (" +
               (known.empty() ? std::string("the engine named no objects") : list) + ")");
}

}  // namespace asperity
