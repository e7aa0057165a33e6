// PNG output of rendered frames (stb_image_write, compiled once in the core library).
#include <stb_image_write.h>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/render/renderer.hpp"

namespace asperity::render {

void savePng(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw Error(path + ": image to save is empty or inconsistent");
  // Encoded in memory, then written whole under a temporary name and renamed: a killed
  // render leaves no cut PNG under the final name.
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<size_t>(size));
  };
  if (stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, image.rgb.data(),
                             image.width * 3) == 0)
    throw Error(path + ": cannot encode the PNG");
  writeFileAtomically(path, bytes);
}

}  // namespace asperity::render
