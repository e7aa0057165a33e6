// libFuzzer target: scene text -> JSON (depth limit, duplicate keys) -> SceneDesc -> World,
// then two steps. Every rejection must be an asperity::Error; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"
#include "scene/json_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Relative file names resolve against scenes/examples/, as the example seeds expect.
  const std::string file = std::string(ASPERITY_SOURCE_DIR) + "/scenes/examples/fuzz.json";
  try {
    const asperity::SceneDesc scene =
        asperity::parseScene(asperity::scene::parseJsonText(text, file), file);
    // Large worlds are valid but slow; the loader is what is fuzzed, so keep steps cheap.
    if (scene.bodies.size() > 64) return 0;
    const std::unique_ptr<asperity::World> world = asperity::instantiate(scene);
    for (int i = 0; i < 2; ++i) world->step();
  } catch (const asperity::Error&) {
    // A clear one-line error is the expected outcome for bad input.
  }
  return 0;
}
