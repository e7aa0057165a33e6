// The height fields behind the procedural generators (SPEC 13): most generators build their
// normal maps from heights, which can be written as height maps at physical scale.
#pragma once

#include <string>

#include "asperity/texture/generators.hpp"
#include "asperity/texture/height_map.hpp"

namespace asperity {

// True when the generator builds its normals from a height field (all but gaussian, whose
// slopes are drawn independently per texel). Throws asperity::Error for an unknown name.
bool generatorHasHeights(const std::string& name);

// The height field a generator builds its normals from, in metres for a texture covering
// `texture_size` metres (a texel's width is texture_size / size): loaded back with that
// texture_size (normalsFromHeightMap), it gives the generator's normal map within quantisation
// (sawtooth, thread and cones sample their slopes at texel centres instead, and a sawtooth's
// heights give its ramp the share of the period that closes the profile: docs/textures.md).
// Throws as generateNormalMap, and for a generator without a height field.
HeightMap generateHeightMap(const GeneratorSpec& spec, double texture_size);

}  // namespace asperity
