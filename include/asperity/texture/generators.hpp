// Procedural normal maps (SPEC 6), deterministic for a seed. docs/textures.md documents each.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "asperity/texture/normal_map.hpp"

namespace asperity {

// One parameter of a generator. Numbers are range-checked; a "path" parameter names a file.
struct GeneratorParam {
  std::string name;
  std::string kind;  // "number" or "path"
  std::string default_value;
  double min = 0.0;  // numbers only, inclusive
  double max = 0.0;
  std::string doc;
};

struct GeneratorInfo {
  std::string name;
  std::string doc;
  std::vector<GeneratorParam> params;
};

// What to generate: the same structure scene files and the CLI use.
struct GeneratorSpec {
  std::string name;
  std::map<std::string, std::string> params;  // unset ones take their defaults
  int size = 256;                             // square, texels per side
  uint64_t seed = 1;
};

const std::vector<GeneratorInfo>& generatorCatalog();

// Throws asperity::Error for an unknown generator or parameter, or a bad value (NaN, out of
// range, not a number), naming it.
NormalMap generateNormalMap(const GeneratorSpec& spec);

}  // namespace asperity
