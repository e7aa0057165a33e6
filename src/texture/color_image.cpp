// Colour images for display (see color_image.hpp), decoded by the PNG codec's stb reader.
#include "asperity/texture/color_image.hpp"

#include <cmath>

#include "asperity/texture/png_io.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

ColorImage decodeColorImage(const std::vector<uint8_t>& bytes, const std::string& name) {
  const png::Image image = png::decodeAny(bytes, name, kMaxTextureSize, 4);
  ColorImage out;
  out.width = image.header.width;
  out.height = image.header.height;
  out.rgba.resize(image.samples.size());
  // File row r (top first) becomes row H - 1 - r; samples in [0, 1] back to bytes.
  const size_t row = static_cast<size_t>(out.width) * 4;
  for (int r = 0; r < out.height; ++r) {
    const size_t from = static_cast<size_t>(r) * row;
    const size_t to = static_cast<size_t>(out.height - 1 - r) * row;
    for (size_t k = 0; k < row; ++k)
      out.rgba[to + k] = static_cast<uint8_t>(std::lround(255.0f * image.samples[from + k]));
  }
  return out;
}

}  // namespace asperity
