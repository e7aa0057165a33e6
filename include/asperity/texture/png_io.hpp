// PNG normal maps: 8 or 16 bits per channel, RGB or RGBA, m = normalize(2 rgb - 1) (SPEC 6).
#pragma once

#include <string>

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

// Throws asperity::Error naming the file and the problem (missing, corrupt, grayscale, palette,
// zero-sized, over kMaxTextureSize, ...).
NormalMap loadNormalMapPng(const std::string& path,
                           GreenConvention green = GreenConvention::OpenGL);
void saveNormalMapPng(const NormalMap& map, const std::string& path,
                      const PngWriteOptions& options = {});

}  // namespace asperity
