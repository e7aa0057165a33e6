// NormalMap: storage and bilinear sampling of a tangent-space normal map.
#include "asperity/texture/normal_map.hpp"

#include <algorithm>
#include <cmath>

namespace asperity {

namespace {

// Texel index along one axis for a (possibly out-of-range) integer index.
int wrapIndex(long long index, int size, WrapMode wrap) {
  if (wrap == WrapMode::Clamp) {
    return static_cast<int>(std::clamp<long long>(index, 0, size - 1));
  }
  const long long m = index % size;
  return static_cast<int>(m < 0 ? m + size : m);
}

// The two texels that bracket coordinate t (in [0, 1) per period) and the weight of the second.
struct Bracket {
  int lo = 0;
  int hi = 0;
  float weight = 0.0f;
};

Bracket bracket(float t, int size, WrapMode wrap) {
  // Texel centres sit at (i + 0.5) / size; a non-finite coordinate samples texel 0.
  double x = std::isfinite(t) ? static_cast<double>(t) * size - 0.5 : 0.0;
  if (wrap == WrapMode::Repeat) {
    x -= std::floor(x / size) * size;  // keep the index small for huge coordinates
  } else {
    x = std::clamp(x, -1.0, static_cast<double>(size));
  }
  const double base = std::floor(x);
  const auto i0 = static_cast<long long>(base);
  return {wrapIndex(i0, size, wrap), wrapIndex(i0 + 1, size, wrap), static_cast<float>(x - base)};
}

}  // namespace

NormalMap::NormalMap(int width, int height)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      texels_(static_cast<size_t>(width_) * static_cast<size_t>(height_), Vec3f(0, 0, 1)) {}

Vec3f NormalMap::sample(float u, float v, WrapMode wrap) const {
  // An empty map reads as flat.
  if (texels_.empty()) {
    return Vec3f(0, 0, 1);
  }
  const Bracket bu = bracket(u, width_, wrap);
  const Bracket bv = bracket(v, height_, wrap);
  // Bilinear blend of the four neighbouring texels.
  const Vec3f bottom = (1.0f - bu.weight) * at(bu.lo, bv.lo) + bu.weight * at(bu.hi, bv.lo);
  const Vec3f top = (1.0f - bu.weight) * at(bu.lo, bv.hi) + bu.weight * at(bu.hi, bv.hi);
  const Vec3f blended = (1.0f - bv.weight) * bottom + bv.weight * top;
  // Renormalise; opposite normals that cancel read as flat.
  const float length = blended.norm();
  return length > 1e-6f ? Vec3f(blended / length) : Vec3f(0, 0, 1);
}

}  // namespace asperity
