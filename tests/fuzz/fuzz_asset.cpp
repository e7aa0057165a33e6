// libFuzzer target: asset bytes through the importer from memory (assimp: every format it reads
// for us, glTF text and glb, FBX, COLLADA, 3DS; OBJ goes through tinyobjloader from files,
// fuzz_obj's), embedded textures decoded. The first byte picks the format; every rejection must
// be an asperity::Error naming the asset, anything else (a crash, a report, another exception)
// is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/geometry/asset_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kFormats[] = {"glb", "gltf", "fbx", "dae", "3ds"};
  const std::string format = kFormats[data[0] % 5];
  const std::vector<uint8_t> bytes(data + 1, data + size);
  try {
    const asperity::ImportedAsset asset =
        asperity::importAssetFromMemory(bytes, "fuzz." + format, format);
    // What the importer hands on must hold together: triangles index real vertices.
    for (const auto& t : asset.mesh->triangles) {
      for (const int v : t) {
        if (v < 0 || static_cast<size_t>(v) >= asset.mesh->vertices.size()) __builtin_trap();
      }
    }
  } catch (const asperity::Error&) {
    // Malformed assets end in a message naming the file.
  }
  return 0;
}
