// The friction cone of a flat patch covering whole textures (Fig. 8, `asperity cone`).
#include "asperity/friction/patch_cone.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "asperity/error.hpp"

namespace asperity {

namespace {

constexpr size_t kBlock = 4096;

// Per-direction mean of max(0, g.d) over every texel of one map (Eq. 8 over the whole map).
// Texel normals go to the contact frame as (x, y, z) for B and (x, -y, -z) for A (see header).
std::vector<double> surfaceMeans(const NormalMap& map, Side side, std::span<const Vec2> dirs,
                                 float mu_max, SimdCopy simd) {
  std::vector<double> sums(dirs.size(), 0.0);
  const std::vector<Vec3f>& texels = map.texels();
  const float flip = side == Side::B ? 1.0f : -1.0f;
  std::vector<float> gx(kBlock), gy(kBlock);
  // Blocks of g in SoA, each swept by the kernel while still in cache.
  for (size_t base = 0; base < texels.size(); base += kBlock) {
    const size_t len = std::min(kBlock, texels.size() - base);
    for (size_t i = 0; i < len; ++i) {
      const Vec3f& t = texels[base + i];
      const Vec2f g = ploughingVector(Vec3f(t.x(), flip * t.y(), flip * t.z()), side, mu_max);
      gx[i] = g.x();
      gy[i] = g.y();
    }
    accumulateDirectionalSums(std::span<const float>(gx.data(), len),
                              std::span<const float>(gy.data(), len), dirs, sums, simd);
  }
  for (double& s : sums) s /= static_cast<double>(texels.size());
  return sums;
}

}  // namespace

DirectionalMu flatPatchCone(const NormalMap* a, const NormalMap& b, const PatchConeOptions& opt) {
  // Validate the options and inputs, naming the culprit.
  const std::vector<Vec2> dirs = sampleDirections(opt.directions);
  if (!std::isfinite(opt.mu_max) || !(opt.mu_max > 0.0f)) {
    throw Error("flatPatchCone: mu_max must be a positive finite number, got " +
                std::to_string(opt.mu_max));
  }
  if (b.empty()) throw Error("flatPatchCone: normal map of surface B is empty");
  if (a != nullptr && a->empty()) throw Error("flatPatchCone: normal map of surface A is empty");
  // Eq. 8 per surface (a flat A contributes nothing), then Eq. 7.
  const std::vector<double> mean_b = surfaceMeans(b, Side::B, dirs, opt.mu_max, opt.simd);
  std::vector<double> mean_a;
  if (a != nullptr) mean_a = surfaceMeans(*a, Side::A, dirs, opt.mu_max, opt.simd);
  return combinePatch(mean_a, mean_b, opt.gains);
}

}  // namespace asperity
