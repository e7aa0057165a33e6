// The generator catalog and dispatch (SPEC 6). Each family of generators lives in its own file
// and contributes GeneratorEntry values; this file only collects them and checks the request.
#include "asperity/texture/generators.hpp"

#include <cmath>

#include "asperity/error.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "texture/generator_support.hpp"
#include "texture/height_field.hpp"

namespace asperity {

namespace {

// Every generator, in catalog order; built once.
const std::vector<texgen::GeneratorEntry>& registry() {
  static const std::vector<texgen::GeneratorEntry> entries = [] {
    std::vector<texgen::GeneratorEntry> all;
    for (auto family : {texgen::noiseGenerators, texgen::profileGenerators,
                        texgen::reliefGenerators, texgen::materialGenerators}) {
      for (texgen::GeneratorEntry& entry : family()) {
        all.push_back(std::move(entry));
      }
    }
    return all;
  }();
  return entries;
}

}  // namespace

const std::vector<GeneratorInfo>& generatorCatalog() {
  static const std::vector<GeneratorInfo> catalog = [] {
    std::vector<GeneratorInfo> infos;
    for (const texgen::GeneratorEntry& entry : registry()) {
      infos.push_back(entry.info);
    }
    return infos;
  }();
  return catalog;
}

namespace {

const texgen::GeneratorEntry& findEntry(const std::string& name) {
  for (const texgen::GeneratorEntry& entry : registry()) {
    if (entry.info.name == name) return entry;
  }
  std::string known;
  for (const texgen::GeneratorEntry& entry : registry()) {
    known += (known.empty() ? "" : ", ") + entry.info.name;
  }
  throw Error("texture generator '" + name + "': unknown generator (known: " + known + ")");
}

}  // namespace

NormalMap generateNormalMap(const GeneratorSpec& spec) {
  const texgen::GeneratorEntry& entry = findEntry(spec.name);
  // Checking the parameters first means a bad value fails before any work.
  const texgen::GeneratorContext context(entry.info, spec);
  return entry.make(context);
}

bool generatorHasHeights(const std::string& name) {
  return static_cast<bool>(findEntry(name).heights);
}

HeightMap generateHeightMap(const GeneratorSpec& spec, double texture_size) {
  const texgen::GeneratorEntry& entry = findEntry(spec.name);
  const texgen::GeneratorContext context(entry.info, spec);
  if (!entry.heights)
    context.fail("has no height field (its slopes are not the gradient of any heights)");
  if (!(texture_size > 0.0) || !std::isfinite(texture_size))
    context.fail("texture size must be positive, got " + std::to_string(texture_size));
  const texgen::Field field = entry.heights(context);
  // Texel units to metres: one texel is texture_size / width metres wide.
  const double metres = texture_size / field.width;
  HeightMap map(field.width, field.height);
  for (size_t k = 0; k < field.values.size(); ++k)
    map.values[k] = static_cast<float>(field.values[k] * metres);
  return map;
}

}  // namespace asperity
