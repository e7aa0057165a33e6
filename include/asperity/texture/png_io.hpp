// PNG normal maps: 8 or 16 bits per channel, RGB or RGBA, m = normalize(2 rgb - 1) (SPEC 6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "asperity/diagnostics.hpp"
#include "asperity/texture/normal_map.hpp"

namespace asperity {

// OpenGL: green = +bitangent (+v). DirectX: green = -bitangent.
enum class GreenConvention { OpenGL, DirectX };

// Largest width or height accepted on load or generation (texels per side).
inline constexpr int kMaxTextureSize = 8192;

struct PngWriteOptions {
  int bits = 8;  // 8 or 16
  bool alpha = false;
  GreenConvention green = GreenConvention::OpenGL;
};

// What decoding a normal map found (SPEC 10): texels whose decoded vector 2 rgb - 1 has a length
// outside [0.5, 1.5] or z <= 0 are not normals (grey or white backgrounds, empty atlas space);
// they are stored flat (0, 0, 1), so they add no friction, and counted here.
struct NormalMapStats {
  size_t texels = 0;
  size_t invalid = 0;
  int bits = 8;  // bits per channel of the file
  double invalidFraction() const {
    return texels == 0 ? 0.0 : static_cast<double>(invalid) / static_cast<double>(texels);
  }
};

// Warns `NAME: P % of texels are not unit normals; treated as flat` when the map has any
// invalid texel (callers do so once per loaded map).
void warnInvalidTexels(const std::string& name, const NormalMapStats& stats,
                       Diagnostics& diagnostics);

// Throws asperity::Error naming the file and the problem (missing, corrupt, grayscale, palette,
// zero-sized, over kMaxTextureSize, ...). Invalid texels become flat and are counted in `stats`
// when given; the caller reports them (warnInvalidTexels): decoding prints nothing.
NormalMap loadNormalMapPng(const std::string& path, GreenConvention green = GreenConvention::OpenGL,
                           NormalMapStats* stats = nullptr);

// A normal map from an encoded image in memory (PNG, JPEG, BMP or TGA, as embedded in a .glb or
// a data URI). `scale` multiplies x and y before normalising (glTF normalTexture.scale, MTL
// -bm). `name` appears in errors; invalid texels are counted in `stats` as for loadNormalMapPng.
NormalMap decodeNormalMap(const std::vector<uint8_t>& bytes, const std::string& name,
                          GreenConvention green = GreenConvention::OpenGL, double scale = 1.0,
                          NormalMapStats* stats = nullptr);
// A whole file (an image, an asset's texture) in one read; std::nullopt when it is missing, a
// directory or unreadable. Callers name the file and the part in their own messages.
std::optional<std::vector<uint8_t>> readFileBytes(const std::string& path);

void saveNormalMapPng(const NormalMap& map, const std::string& path,
                      const PngWriteOptions& options = {});

}  // namespace asperity
