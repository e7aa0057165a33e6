// An sRGB colour image for display only (an asset's base colour texture): friction never reads
// it. Rows are stored bottom-up like NormalMap, so texture coordinate v = 0 is row 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace asperity {

struct ColorImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // 4 bytes per texel, sRGB, rows bottom-up

  bool empty() const { return rgba.empty(); }
};

// Decodes a PNG, JPEG, BMP or TGA image in memory (as embedded in a .glb or read beside an
// asset) to 8-bit RGBA, its size checked against kMaxTextureSize first. Throws asperity::Error
// naming `name` and the problem.
ColorImage decodeColorImage(const std::vector<uint8_t>& bytes, const std::string& name);

}  // namespace asperity
