// libFuzzer target: a world's saved state (World::saveState's bytes, as a state file holds them
// after its header) loaded into scenes/stacking.json with the constant provider, then two
// steps. The file's checksum only catches accidents: a forger recomputes it, so the fuzzer
// starts past it. Every rejection must be an asperity::Error (a StepError included); a crash,
// a sanitizer report or a step that hangs is a finding.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"

namespace {

// The scene is parsed once; each input gets a world of its own (a failed load leaves a world
// that must be built anew).
const asperity::SceneDesc& stacking() {
  static const asperity::SceneDesc scene = [] {
    asperity::SceneDesc s =
        asperity::loadScene(std::string(ASPERITY_SOURCE_DIR) + "/scenes/stacking.json");
    s.friction_provider = "constant";
    return s;
  }();
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::unique_ptr<asperity::World> world = asperity::instantiate(stacking());
  try {
    world->loadState(std::string_view(reinterpret_cast<const char*>(data), size));
    for (int i = 0; i < 2; ++i) world->step();
  } catch (const asperity::Error&) {
    // A clear one-line error is the expected outcome for a forged state.
  }
  return 0;
}
