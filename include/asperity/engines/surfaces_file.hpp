// A JSON file that maps another engine's object names to Asperity surfaces, for the engine
// adapters (docs/engines.md). Each entry is a surface object as a scene's shapes write it
// (docs/scene-format.md: "normal_map" file or generator, "gain", "texture_size", ...):
//
//   {"surfaces": {
//     "ground": {"normal_map": {"generator": "sawtooth", "params": {"period": 16}, "size": 128},
//                "gain": 4, "texture_size": 0.08},
//     "crate": {"normal_map": "textures/oak_normal.png", "gain": 2}}}
//
// Relative paths resolve against the file's folder.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "asperity/diagnostics.hpp"
#include "asperity/error.hpp"
#include "asperity/geometry/surface.hpp"

namespace asperity {

struct SurfacesFile {
  std::string path;                         // the file it was read from, for messages
  std::map<std::string, Surface> surfaces;  // by object name; normal maps resolved
  Diagnostics diagnostics;                  // warnings found while the maps loaded
};

// Reads, checks and resolves a surfaces file (normal maps read or generated). Throws
// asperity::Error `path: /pointer: what`; a texture that is missing names its path.
SurfacesFile loadSurfacesFile(const std::string& path);

// The error for an entry whose name the engine has no object of: it names the name and the
// file, and lists the names the engine has (`known`, may be empty).
Error unknownObjectError(const SurfacesFile& file, const std::string& name,
                         const std::vector<std::string>& known);

}  // namespace asperity
