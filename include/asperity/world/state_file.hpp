// Checkpoint files: a world's state (World::saveState) with a header that names its format and
// the scene it belongs to (docs/checkpoints.md).
//
// Layout: "ASPSTATE", the format (uint32), a byte-order and number-format mark, the scene's id
// (sceneStateId in asperity/scene/scene.hpp: the scene's canonical JSON hashed, thread count
// left out), the body count, the state's length and its FNV-1a checksum, then the state.
// Reading refuses, each with one line naming the file and what is wrong: another kind of file,
// another format version, a file written on a machine of another byte order, another scene,
// another body count, a length that does not match (a truncated file) and a checksum that does
// not (a corrupt one).
#pragma once

#include <cstdint>
#include <string>

#include "asperity/world/world.hpp"

namespace asperity {

// The file format this build writes and reads; raised whenever a stage's state changes.
inline constexpr uint32_t kStateFormat = 1;

// The state of `world` into `path`, atomically (a temporary file beside it, renamed into place;
// asperity/math/atomic_file.hpp). Throws asperity::Error "PATH: ..." when it cannot be written.
void saveStateFile(const World& world, const std::string& path, uint64_t scene_id);
// Restores `world`, built from the scene whose id is `scene_id`, from `path`. Throws
// asperity::Error "PATH: what is wrong"; after an error the world must be built anew.
void loadStateFile(World& world, const std::string& path, uint64_t scene_id);

}  // namespace asperity
