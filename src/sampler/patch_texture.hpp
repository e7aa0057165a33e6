// Inline texture lookups of the CPU sampler's fragment loop: bilinear, repeat, the same texel
// layout as NormalMap::sample (texel centres at (i + 1/2) / W, rows bottom-up). The normal is
// NOT renormalised: the ploughing vector depends on its direction only (fragment_model.hpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "asperity/geometry/surface.hpp"
#include "asperity/texture/normal_map.hpp"

namespace asperity::patch {

// The two texels bracketing coordinate t (repeat) and the weight of the second.
struct TexelBracket {
  int lo = 0, hi = 0;
  float weight = 0.0f;
};

inline TexelBracket bracketRepeat(float t, int size) {
  // Texel centres at (i + 0.5) / size; wrap into [0, size).
  float x = t * static_cast<float>(size) - 0.5f;
  x -= std::floor(x / static_cast<float>(size)) * static_cast<float>(size);
  const float base = std::floor(x);
  int lo = static_cast<int>(base);
  if (lo >= size) lo -= size;  // x rounded up to size
  const int hi = lo + 1 == size ? 0 : lo + 1;
  return {lo, hi, x - base};
}

// Bilinear normal-map sample at (u, v) in repeats (unnormalised blend).
inline Vec3f sampleNormal(const NormalMap& map, float u, float v) {
  const TexelBracket bu = bracketRepeat(u, map.width());
  const TexelBracket bv = bracketRepeat(v, map.height());
  const Vec3f bottom = (1.0f - bu.weight) * map.at(bu.lo, bv.lo) + bu.weight * map.at(bu.hi, bv.lo);
  const Vec3f top = (1.0f - bu.weight) * map.at(bu.lo, bv.hi) + bu.weight * map.at(bu.hi, bv.hi);
  return (1.0f - bv.weight) * bottom + bv.weight * top;
}

// Bilinear gain-mask sample at (u, v) (repeat), >= 0; an empty mask reads 1.
inline float sampleMask(const GainMask& mask, float u, float v) {
  if (mask.width <= 0 || mask.height <= 0 ||
      mask.values.size() < static_cast<size_t>(mask.width) * static_cast<size_t>(mask.height)) {
    return 1.0f;
  }
  const TexelBracket bu = bracketRepeat(u, mask.width);
  const TexelBracket bv = bracketRepeat(v, mask.height);
  auto at = [&](int i, int j) { return mask.values[static_cast<size_t>(j) * mask.width + i]; };
  const float bottom = (1.0f - bu.weight) * at(bu.lo, bv.lo) + bu.weight * at(bu.hi, bv.lo);
  const float top = (1.0f - bu.weight) * at(bu.lo, bv.hi) + bu.weight * at(bu.hi, bv.hi);
  return std::max(0.0f, (1.0f - bv.weight) * bottom + bv.weight * top);
}

}  // namespace asperity::patch
