// libFuzzer target: the normal-map generators' parameters. The input picks a generator, a
// size and a seed, and gives each parameter a value string; bad values must be
// asperity::Error naming the parameter, good ones must produce a finite unit normal map.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "asperity/error.hpp"
#include "asperity/texture/generators.hpp"

namespace {

// Consumes bytes up to (not including) the next ';' as one value string.
std::string nextValue(const uint8_t*& data, const uint8_t* end) {
  std::string out;
  while (data < end && *data != ';') out += static_cast<char>(*data++);
  if (data < end) ++data;
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const auto& catalog = asperity::generatorCatalog();
  const uint8_t* end = data + size;
  asperity::GeneratorSpec spec;
  // Byte 0: generator (one past the end tries an unknown name); byte 1: size; byte 2: seed.
  const size_t pick = data[0] % (catalog.size() + 1);
  if (pick < catalog.size())
    spec.name = catalog[pick].name;
  else
    spec.name.append("no_such_generator");
  spec.size = 1 + data[1] % 48;
  spec.seed = data[2];
  data += 3;
  if (pick < catalog.size())
    for (const auto& param : catalog[pick].params)
      if (data < end) spec.params[param.name] = nextValue(data, end);
  // Whatever is left names an unknown parameter.
  if (data < end) spec.params[nextValue(data, end)] = std::string(1, '1');
  try {
    const asperity::NormalMap map = asperity::generateNormalMap(spec);
    // A generated map holds finite unit normals (SPEC 6); anything else is a finding.
    for (const auto& n : map.texels())
      if (!n.allFinite() || std::abs(n.norm() - 1.0f) > 1e-3f) std::abort();
  } catch (const asperity::Error&) {
    // Unknown names and bad values are errors naming them.
  }
  return 0;
}
