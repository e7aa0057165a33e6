// The surfaces file of an engine adapter (MuJoCo, ODE): which of the engine's objects carry
// which Asperity surface, and the friction settings, in a small JSON file beside the engine's
// own model (docs/engines.md):
//
//   {"settings": {"patch_width": 0.02, "friction_provider": "cpu", "frame_mode": "world"},
//    "surfaces": {"floor": {"normal_map": {"generator": "sawtooth", "size": 128}, "gain": 4,
//                           "texture_size": 0.08},
//                 "box": {"normal_map": "textures/oak.png", "gain": 1}}}
//
// A surface takes the keys of a scene's "surface" (docs/scene-format.md). mu0 is not set here:
// the engine's own coefficient of the pair is mu0 (SPEC 3, Eq. 7), so Asperity adds
// k_A mubar_A + k_B mubar_B to what the engine would use.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "asperity/diagnostics.hpp"
#include "asperity/engines/contact_friction.hpp"
#include "asperity/geometry/surface.hpp"

namespace asperity {

struct EngineSurface {
  std::string name;  // the engine object's name (MuJoCo geom, ODE geom)
  Surface surface;   // normal map resolved
};

struct EngineSurfaces {
  // friction.mu0 is 0: the engine's coefficient stands for mu0.
  ContactFrictionSettings settings;
  std::vector<EngineSurface> surfaces;  // by name, sorted
  std::string file;                     // for messages ("" = built in code)
  Diagnostics diagnostics;              // warnings found while the maps loaded

  // The surface of that name, or null.
  const Surface* find(std::string_view name) const;
  // Throws asperity::Error `file: /surfaces/<name>: what` (the entry that names it).
  [[noreturn]] void failAt(const std::string& name, const std::string& what) const;
};

// Reads and validates a surfaces file, resolving every normal map (PNG or generator; relative
// paths from the file's folder). Throws asperity::Error `file: /pointer: what`, naming a
// missing texture's path.
EngineSurfaces loadEngineSurfaces(const std::string& path);
// The same from parsed JSON; relative paths resolve against the folder of file_for_messages.
EngineSurfaces parseEngineSurfaces(const nlohmann::json& json,
                                   const std::string& file_for_messages);

}  // namespace asperity
