// Private support for the procedural generators (SPEC 6): a portable seeded random source,
// strict parameter reading, and the registry entry type each generator file contributes.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "asperity/texture/generators.hpp"

namespace asperity::texgen {

// Seeded random numbers that are identical on every standard library: mt19937_64 is fully
// specified, and the conversions below are written out (std:: distributions are not).
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  // Uniform in (0, 1]: 53 random bits.
  double uniform();
  // Standard normal by the Box-Muller transform.
  double gaussian();

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// Parameters of one generator call, already checked against the generator's declaration.
class GeneratorContext {
 public:
  GeneratorContext(const GeneratorInfo& info, const GeneratorSpec& spec);

  int size() const { return size_; }
  uint64_t seed() const { return seed_; }
  // The value of a declared "number" parameter (given or default), range-checked.
  double number(const std::string& name) const;
  // A declared "number" parameter that must also be a whole number.
  int integer(const std::string& name) const;
  // An axis parameter: "u" (0 degrees), "v" (90) or an angle in degrees from +u toward +v.
  double axisRadians(const std::string& name) const;
  // The value of a declared "path" parameter; throws if it is required and empty.
  std::string path(const std::string& name) const;
  // Throws asperity::Error "texture generator '<name>': <what>".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  const GeneratorParam& declared(const std::string& name) const;
  std::string raw(const GeneratorParam& param) const;

  const GeneratorInfo& info_;
  const GeneratorSpec& spec_;
  int size_ = 0;
  uint64_t seed_ = 0;
};

struct Field;  // height_field.hpp

// One catalog entry: the documentation, the function that builds the map and, for generators
// built on a height field, the function that gives those heights (texel units: a height of 1
// is one texel's width). Empty `heights`: the generator has no height field.
struct GeneratorEntry {
  GeneratorInfo info;
  std::function<NormalMap(const GeneratorContext&)> make;
  std::function<Field(const GeneratorContext&)> heights;
};

// An entry whose map is the central-difference normals (wrapping) of its heights.
GeneratorEntry heightEntry(GeneratorInfo info, std::function<Field(const GeneratorContext&)> heights);

// Parameter declaration helpers for the catalog tables.
GeneratorParam numberParam(std::string name, double default_value, double min, double max,
                           std::string doc);
GeneratorParam axisParam(std::string default_value, std::string doc);
GeneratorParam pathParam(std::string name, std::string doc);

// The generator families, one file each; generators.cpp concatenates them into the catalog.
std::vector<GeneratorEntry> noiseGenerators();     // noise_generators.cpp
std::vector<GeneratorEntry> profileGenerators();   // profile_generators.cpp
std::vector<GeneratorEntry> reliefGenerators();    // relief_generators.cpp
std::vector<GeneratorEntry> materialGenerators();  // material_generators.cpp

}  // namespace asperity::texgen
