// Private: 32-bit float OpenEXR height maps, built when Debian's libopenexr-dev is found
// (cmake/AsperityDependencies.cmake); without it the functions throw, naming the package.
#pragma once

#include <string>

#include "asperity/texture/height_map.hpp"

namespace asperity::exr {

// True when this build reads and writes OpenEXR files.
bool available();

// The channel named "height", "Z", "Y" or "R" (the first found; or the file's only channel),
// times `scale` (EXR heights are metres when scale is 1). Rows as in HeightMap (the file's top
// row is row H - 1). Throws asperity::Error naming the file.
HeightMap load(const std::string& path, double scale);

// Writes `map` as one 32-bit float channel "Y" (metres). Throws asperity::Error naming the file.
void save(const HeightMap& map, const std::string& path);

}  // namespace asperity::exr
