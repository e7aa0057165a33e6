// Normal maps to and from PNG files (SPEC 6): m = normalize(2 rgb - 1), rows bottom-up in memory.
#include "asperity/texture/png_io.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "asperity/error.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

namespace {

// SPEC 10: a texel is a normal when its decoded length lies in [0.5, 1.5] and it faces out.
constexpr float kMinNormalLength = 0.5f;
constexpr float kMaxNormalLength = 1.5f;

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

// Encoded value in [0, 1] -> unit normal; a texel that is no normal reads flat (SPEC 10).
Vec3f decodeTexel(const float* rgb, GreenConvention green, float scale, bool& valid) {
  Vec3f m(2.0f * rgb[0] - 1.0f, 2.0f * rgb[1] - 1.0f, 2.0f * rgb[2] - 1.0f);
  const float raw_length = m.norm();
  valid = raw_length >= kMinNormalLength && raw_length <= kMaxNormalLength && m.z() > 0.0f;
  if (!valid) return Vec3f(0, 0, 1);
  if (green == GreenConvention::DirectX) m.y() = -m.y();
  // glTF normalTexture.scale: x and y scaled before normalising.
  m.x() *= scale;
  m.y() *= scale;
  return m.normalized();
}

// Decoded RGB samples (rows top first) -> a map with rows bottom-up; counts invalid texels.
NormalMap fromImage(const png::Image& image, GreenConvention green, double scale,
                    NormalMapStats& stats) {
  const int w = image.header.width;
  const int h = image.header.height;
  NormalMap map(w, h);
  stats.texels = static_cast<size_t>(w) * static_cast<size_t>(h);
  stats.invalid = 0;
  stats.bits = image.header.bit_depth == 16 ? 16 : 8;
  const auto s = static_cast<float>(scale);
  // PNG row r (top first) becomes map row j = H - 1 - r.
  for (int r = 0; r < h; ++r) {
    for (int i = 0; i < w; ++i) {
      const size_t k = (static_cast<size_t>(r) * w + i) * 3;
      bool valid = true;
      map.at(i, h - 1 - r) = decodeTexel(&image.samples[k], green, s, valid);
      stats.invalid += valid ? 0 : 1;
    }
  }
  return map;
}

}  // namespace

void warnInvalidTexels(const std::string& name, const NormalMapStats& stats,
                       Diagnostics& diagnostics) {
  if (stats.invalid == 0) return;
  const double percent = 100.0 * stats.invalidFraction();
  const long rounded = std::lround(percent);
  const std::string shown = rounded == 0 ? "< 1" : std::to_string(rounded);
  diagnostics.warn(name + ": " + shown + " % of texels are not unit normals; treated as flat");
}

std::optional<std::vector<uint8_t>> readFileBytes(const std::string& path) {
  // A directory opens as a stream on Linux; its size is not a file's.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  const std::streamoff size = in.tellg();
  if (size < 0) return std::nullopt;
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) return std::nullopt;
  return bytes;
}

NormalMap loadNormalMapPng(const std::string& path, GreenConvention green, NormalMapStats* stats) {
  // Header checks (size, colour type) come before any decoding.
  const std::vector<uint8_t> bytes = png::readFile(path);
  requireRgb(png::inspect(bytes, path, kMaxTextureSize), path);
  const png::Image image = png::decode(bytes, path, kMaxTextureSize, 3);
  NormalMapStats local;
  return fromImage(image, green, 1.0, stats ? *stats : local);
}

NormalMap decodeNormalMap(const std::vector<uint8_t>& bytes, const std::string& name,
                          GreenConvention green, double scale, NormalMapStats* stats) {
  // PNGs must be RGB(A); other formats are converted by stb.
  if (png::isPng(bytes)) requireRgb(png::inspect(bytes, name, kMaxTextureSize), name);
  const png::Image image = png::decodeAny(bytes, name, kMaxTextureSize, 3);
  NormalMapStats local;
  return fromImage(image, green, scale, stats ? *stats : local);
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
