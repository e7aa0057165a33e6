// PNG output of rendered frames (stb_image_write, compiled once in the core library).
#include <stb_image_write.h>

#include "asperity/error.hpp"
#include "asperity/render/renderer.hpp"

namespace asperity::render {

void savePng(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw Error(path + ": image to save is empty or inconsistent");
  if (stbi_write_png(path.c_str(), image.width, image.height, 3, image.rgb.data(),
                     image.width * 3) == 0)
    throw Error(path + ": cannot write the PNG (missing directory or no permission?)");
}

}  // namespace asperity::render
