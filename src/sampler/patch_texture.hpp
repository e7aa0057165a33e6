// Inline texture lookups of the CPU sampler's fragment loop, with repeat and the texel layout
// of NormalMap::sample (texel i covers [i, i + 1) / W, its centre at (i + 1/2) / W, rows
// bottom-up): the nearest texel (each texel one facet, the default) or the bilinear blend of
// the four around (FrictionSettings::texel_reading). A blended normal is NOT renormalised: the
// ploughing vector depends on its direction only (fragment_model.hpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "asperity/geometry/surface.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/texture/normal_map.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity::patch {

// The two texels bracketing coordinate t (repeat) and the weight of the second.
struct TexelBracket {
  int lo = 0, hi = 0;
  float weight = 0.0f;
};

// floor() as an int without a libm call (baseline x86-64 has no rounding instruction), for
// |x| < 2^24; the correction is done on ints, so that loops using it stay branch-free. Beyond
// 2^30 the value is clamped, keeping the conversion defined: a coordinate that large (a
// degenerate primitive's extrapolated uv) has lost its fraction already, and nothing smaller
// changes.
inline int floorInt(float x) {
  constexpr float kLimit = 1073741824.0f;  // 2^30
  x = std::min(std::max(x, -kLimit), kLimit);
  const int t = static_cast<int>(x);
  return t - (static_cast<float>(t) > x ? 1 : 0);
}

inline float floorFast(float x) {
  return static_cast<float>(floorInt(x));
}

// wrapTexel without a division, given 1 / size, for |index| < 2^24: the float quotient is off
// by at most one, which the two corrections undo (branch-free, so loops vectorise).
inline int wrapTexelBy(int index, int size, float inv_size) {
  int m = index - size * floorInt(static_cast<float>(index) * inv_size);
  m += m < 0 ? size : 0;
  m -= m >= size ? size : 0;
  return m;
}

inline TexelBracket bracketRepeat(float t, int size) {
  // Texel centres at (i + 0.5) / size (t is kept small by the callers).
  const float x = t * static_cast<float>(size) - 0.5f;
  const float base = floorFast(x);
  const int lo = wrapTexel(static_cast<int>(base), size);
  return {lo, lo + 1 == size ? 0 : lo + 1, x - base};
}

// The texel that coordinate t (in repeats) falls in, wrapped (t is kept small by the callers),
// looked up kNearestTexelNudge past t.
inline int nearestTexel(float t, int size) {
  return wrapTexel(floorInt(t * static_cast<float>(size) + kNearestTexelNudge), size);
}

// Bilinear normal-map sample at (u, v) in repeats (unnormalised blend).
[[gnu::always_inline]] inline Vec3f sampleNormalBilinear(const NormalMap& map, float u, float v) {
  const TexelBracket bu = bracketRepeat(u, map.width());
  const TexelBracket bv = bracketRepeat(v, map.height());
  const Vec3f* row0 = &map.at(0, bv.lo);
  const Vec3f* row1 = &map.at(0, bv.hi);
  const Vec3f bottom = (1.0f - bu.weight) * row0[bu.lo] + bu.weight * row0[bu.hi];
  const Vec3f top = (1.0f - bu.weight) * row1[bu.lo] + bu.weight * row1[bu.hi];
  return (1.0f - bv.weight) * bottom + bv.weight * top;
}

// The normal of the facet at (u, v), as `reading` reads the map.
[[gnu::always_inline]] inline Vec3f sampleNormal(const NormalMap& map, float u, float v,
                                                 TexelReading reading) {
  if (reading == TexelReading::Bilinear) return sampleNormalBilinear(map, u, v);
  return map.at(nearestTexel(u, map.width()), nearestTexel(v, map.height()));
}

// Gain-mask sample at (u, v) (repeat), as `reading` reads it, >= 0; an empty mask reads 1.
inline float sampleMask(const GainMask& mask, float u, float v, TexelReading reading) {
  if (mask.width <= 0 || mask.height <= 0 ||
      mask.values.size() < static_cast<size_t>(mask.width) * static_cast<size_t>(mask.height)) {
    return 1.0f;
  }
  if (reading == TexelReading::Nearest) {
    const size_t at = static_cast<size_t>(nearestTexel(v, mask.height)) * mask.width +
                      static_cast<size_t>(nearestTexel(u, mask.width));
    return std::max(0.0f, mask.values[at]);
  }
  const TexelBracket bu = bracketRepeat(u, mask.width);
  const TexelBracket bv = bracketRepeat(v, mask.height);
  auto at = [&](int i, int j) { return mask.values[static_cast<size_t>(j) * mask.width + i]; };
  const float bottom = (1.0f - bu.weight) * at(bu.lo, bv.lo) + bu.weight * at(bu.hi, bv.lo);
  const float top = (1.0f - bu.weight) * at(bu.lo, bv.hi) + bu.weight * at(bu.hi, bv.hi);
  return std::max(0.0f, (1.0f - bv.weight) * bottom + bv.weight * top);
}

}  // namespace asperity::patch
