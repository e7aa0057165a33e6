// The generator catalog and dispatch (SPEC 6). Each family of generators lives in its own file
// and contributes GeneratorEntry values; this file only collects them and checks the request.
#include "asperity/texture/generators.hpp"

#include "asperity/error.hpp"
#include "texture/generator_support.hpp"

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

NormalMap generateNormalMap(const GeneratorSpec& spec) {
  // Find the generator by name.
  for (const texgen::GeneratorEntry& entry : registry()) {
    if (entry.info.name == spec.name) {
      // Checking the parameters first means a bad value fails before any work.
      const texgen::GeneratorContext context(entry.info, spec);
      return entry.make(context);
    }
  }
  std::string known;
  for (const texgen::GeneratorEntry& entry : registry()) {
    known += (known.empty() ? "" : ", ") + entry.info.name;
  }
  throw Error("texture generator '" + spec.name + "': unknown generator (known: " + known + ")");
}

}  // namespace asperity
