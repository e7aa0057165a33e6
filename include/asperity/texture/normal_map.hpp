// A tangent-space normal map held as unit vectors.
//
// Texel (i, j) covers u in [i/W, (i+1)/W) and v in [j/H, (j+1)/H): rows are stored bottom-up,
// as OpenGL samples them, so row 0 is the LAST row of a PNG file. A texel's vector is in the
// surface's tangent frame: x along +u (tangent), y along +v (bitangent), z out of the surface.
#pragma once

#include <vector>

#include "asperity/math/types.hpp"

namespace asperity {

enum class WrapMode { Repeat, Clamp };

// Wraps a texel index of a tiling map into [0, size) (a mask where size is a power of two).
inline int wrapTexel(int index, int size) {
  if ((size & (size - 1)) == 0) return index & (size - 1);
  const int m = index % size;
  return m < 0 ? m + size : m;
}

class NormalMap {
 public:
  NormalMap() = default;
  // A flat map: every texel (0, 0, 1).
  NormalMap(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return texels_.empty(); }

  Vec3f& at(int i, int j) { return texels_[static_cast<size_t>(j) * width_ + i]; }
  const Vec3f& at(int i, int j) const { return texels_[static_cast<size_t>(j) * width_ + i]; }
  const std::vector<Vec3f>& texels() const { return texels_; }

  // Bilinear sample at texture coordinates (u, v); texel centres sit at ((i+.5)/W, (j+.5)/H).
  // The result is renormalised.
  Vec3f sample(float u, float v, WrapMode wrap = WrapMode::Repeat) const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Vec3f> texels_;
};

}  // namespace asperity
