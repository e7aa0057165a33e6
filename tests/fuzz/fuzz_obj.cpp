// libFuzzer target: OBJ text through the mesh reader and the collision simplifier.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "asperity/error.hpp"
#include "asperity/geometry/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // The reader takes a path: the input goes to a file of this process's own.
  static const std::string path = "/tmp/asperity_fuzz_" + std::to_string(getpid()) + ".obj";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const auto mesh = asperity::loadObjMesh(path, 1.0);
    asperity::simplifyMesh(*mesh, 64);
  } catch (const asperity::Error&) {
    // Malformed meshes end in a message naming the file.
  }
  return 0;
}
