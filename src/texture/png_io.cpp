// Normal maps to and from PNG files (SPEC 6): m = normalize(2 rgb - 1), rows bottom-up in memory.
#include "asperity/texture/png_io.hpp"

#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

namespace {

// Decoded vectors shorter than this read as flat (0, 0, 1) (see docs/textures.md).
constexpr float kMinLength = 1e-6f;

// Rejects colour types that cannot hold a normal map, naming the file.
void requireRgb(const png::Header& header, const std::string& path) {
  if (header.colour_type == png::kPalette) {
    throw Error("PNG file '" + path +
                "': palette (indexed-colour) image; normal maps need RGB or RGBA");
  }
  if (header.colour_type == png::kGrey || header.colour_type == png::kGreyAlpha) {
    throw Error("PNG file '" + path + "': grayscale image; normal maps need RGB or RGBA");
  }
}

// Encoded value in [0, 1] -> signed component in [-1, 1].
Vec3f decodeTexel(const float* rgb, GreenConvention green) {
  Vec3f m(2.0f * rgb[0] - 1.0f, 2.0f * rgb[1] - 1.0f, 2.0f * rgb[2] - 1.0f);
  if (green == GreenConvention::DirectX) {
    m.y() = -m.y();
  }
  const float length = m.norm();
  return length < kMinLength ? Vec3f(0, 0, 1) : Vec3f(m / length);
}

}  // namespace

NormalMap loadNormalMapPng(const std::string& path, GreenConvention green) {
  // Header checks (size, colour type) come before any decoding.
  const std::vector<uint8_t> bytes = png::readFile(path);
  requireRgb(png::inspect(bytes, path, kMaxTextureSize), path);
  const png::Image image = png::decode(bytes, path, kMaxTextureSize, 3);
  // PNG row r (top first) becomes map row j = H - 1 - r.
  const int w = image.header.width;
  const int h = image.header.height;
  NormalMap map(w, h);
  for (int r = 0; r < h; ++r) {
    for (int i = 0; i < w; ++i) {
      const size_t k = (static_cast<size_t>(r) * w + i) * 3;
      map.at(i, h - 1 - r) = decodeTexel(&image.samples[k], green);
    }
  }
  return map;
}

void saveNormalMapPng(const NormalMap& map, const std::string& path,
                      const PngWriteOptions& options) {
  // Validate what the PNG format can hold.
  if (map.empty()) {
    throw Error("PNG file '" + path + "': cannot save an empty normal map");
  }
  if (options.bits != 8 && options.bits != 16) {
    throw Error("PNG file '" + path + "': bits must be 8 or 16, got " +
                std::to_string(options.bits));
  }
  const int channels = options.alpha ? 4 : 3;
  const double max_value = options.bits == 16 ? 65535.0 : 255.0;
  const int w = map.width();
  const int h = map.height();
  // Quantise c = round((m + 1) / 2 * max), top PNG row = map row H - 1; alpha is opaque.
  std::vector<uint16_t> samples(static_cast<size_t>(w) * h * channels);
  for (int r = 0; r < h; ++r) {
    for (int i = 0; i < w; ++i) {
      Vec3f m = map.at(i, h - 1 - r);
      if (options.green == GreenConvention::DirectX) {
        m.y() = -m.y();
      }
      const size_t k = (static_cast<size_t>(r) * w + i) * channels;
      for (int c = 0; c < 3; ++c) {
        const double unit = std::clamp((static_cast<double>(m[c]) + 1.0) * 0.5, 0.0, 1.0);
        samples[k + c] = static_cast<uint16_t>(std::lround(unit * max_value));
      }
      if (options.alpha) {
        samples[k + 3] = static_cast<uint16_t>(max_value);
      }
    }
  }
  png::write(path, w, h, channels, options.bits, samples);
}

}  // namespace asperity
