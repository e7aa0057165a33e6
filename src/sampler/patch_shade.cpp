// Fragment shading of the CPU sampler (patch_shade.hpp).
#include "sampler/patch_shade.hpp"

#include <array>
#include <vector>

#include "asperity/friction/fragment_model.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "sampler/patch_texture.hpp"

namespace asperity::patch {

namespace {

// Tangent-space normal and mask at uv (flat and 1 when absent).
Fragment sampleMaterial(const Material& material, float u, float v) {
  Fragment f;
  if (material.map != nullptr && !material.map->empty()) f.m = sampleNormal(*material.map, u, v);
  if (material.mask != nullptr) f.gain = sampleMask(*material.mask, u, v);
  return f;
}

Fragment shadePlanar(const Planar& p, double x, double y) {
  // uv and frame are affine over the primitive.
  const auto xf = static_cast<float>(x), yf = static_cast<float>(y);
  Fragment f = sampleMaterial(p.material, p.uf[0] + p.uf[1] * xf + p.uf[2] * yf,
                              p.vf[0] + p.vf[1] * xf + p.vf[2] * yf);
  if (!p.smooth) {
    f.m = p.frame * f.m;
    return f;
  }
  Eigen::Matrix3f frame;
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      frame(row, col) = static_cast<float>(p.tbn[static_cast<size_t>(3 * col + row)].at(x, y));
    }
  }
  f.m = frame * f.m;
  return f;
}

Fragment shadeCurved(const Curved& c, Side side, double x, double y) {
  // The hit point in the shape frame, then the analytic mapping there.
  double z = 0.0;
  castCurved(c, side, x, y, z);
  const Vec3 local = c.origin_local + c.to_local * Vec3(x, y, z);
  const SurfaceFrame sf = surfaceFrameAt(*c.shape, -1, local);
  Fragment f =
      sampleMaterial(c.material, static_cast<float>(sf.uv.x()), static_cast<float>(sf.uv.y()));
  const Mat3 to_contact = c.to_local.transpose();
  const Vec3 m =
      to_contact * (sf.t * static_cast<double>(f.m.x()) + sf.b * static_cast<double>(f.m.y()) +
                    sf.n * static_cast<double>(f.m.z()));
  f.m = m.cast<float>();
  return f;
}

// The hot path: a flat-framed planar primitive with a normal map and no mask, in plain floats.
[[gnu::always_inline]] inline Vec3f shadeFlat(const Planar& p, float x, float y) {
  const NormalMap& map = *p.material.map;
  const float u = p.uf[0] + p.uf[1] * x + p.uf[2] * y;
  const float v = p.vf[0] + p.vf[1] * x + p.vf[2] * y;
  const TexelBracket bu = bracketRepeat(u, map.width());
  const TexelBracket bv = bracketRepeat(v, map.height());
  const float* row0 = map.at(0, bv.lo).data();
  const float* row1 = map.at(0, bv.hi).data();
  const int a = 3 * bu.lo, b = 3 * bu.hi;
  const float wu = bu.weight, wv = bv.weight;
  float m[3];
  for (int c = 0; c < 3; ++c) {
    const float bottom = row0[a + c] + wu * (row0[b + c] - row0[a + c]);
    const float top = row1[a + c] + wu * (row1[b + c] - row1[a + c]);
    m[c] = bottom + wv * (top - bottom);
  }
  const Eigen::Matrix3f& f = p.frame;
  return Vec3f(f(0, 0) * m[0] + f(0, 1) * m[1] + f(0, 2) * m[2],
               f(1, 0) * m[0] + f(1, 1) * m[1] + f(1, 2) * m[2],
               f(2, 0) * m[0] + f(2, 1) * m[1] + f(2, 2) * m[2]);
}

}  // namespace

Fragment shadeFragment(const Volume& volume, const SurfaceRaster& raster, int pixel) {
  const int r = volume.resolution;
  const double x = volume.centreX(pixel % r), y = volume.centreX(pixel / r);
  const int32_t id = raster.primitive[static_cast<size_t>(pixel)];
  if (id >= 0) return shadePlanar(raster.planars[static_cast<size_t>(id)], x, y);
  return shadeCurved(raster.curveds[static_cast<size_t>(-1 - id)], raster.side, x, y);
}

void shadePloughing(const Volume& volume, const SurfaceRaster& raster,
                    std::span<const uint32_t> pixels, float mu_max, ShadeScratch& scratch,
                    float* gx, float* gy) {
  // Pixel centres once per call.
  std::array<float, 256> centre;  // NOLINT: filled below up to R
  for (int i = 0; i < volume.resolution; ++i) {
    centre[static_cast<size_t>(i)] = static_cast<float>(volume.centreX(i));
  }
  const int r = volume.resolution;
  // Pass 1: meso normals (independent texture loads overlap).
  // The common case (flat-framed planar primitive with a map and no mask) is inlined.
  std::vector<Vec3f>& normals = scratch.normals;
  std::vector<float>& gains = scratch.gains;
  if (normals.size() < pixels.size()) {
    normals.resize(pixels.size());
    gains.resize(pixels.size());
  }
  for (size_t k = 0; k < pixels.size(); ++k) {
    const int i = static_cast<int>(pixels[k] & 0xffffu), j = static_cast<int>(pixels[k] >> 16);
    const int32_t id = raster.primitive[static_cast<size_t>(j * r + i)];
    const float x = centre[static_cast<size_t>(i)], y = centre[static_cast<size_t>(j)];
    if (id >= 0) {
      const Planar& p = raster.planars[static_cast<size_t>(id)];
      if (!p.smooth && p.material.map != nullptr && p.material.mask == nullptr &&
          !p.material.map->empty()) {
        normals[k] = shadeFlat(p, x, y);
        gains[k] = 1.0f;
        continue;
      }
    }
    const Fragment f = shadeFragment(volume, raster, j * r + i);
    normals[k] = f.m;
    gains[k] = f.gain;
  }
  // Pass 2: Eqs. 3 to 6 through the friction module, scaled by the mask
  // (max(0, s g.d) = s max(0, g.d) for s >= 0).
  for (size_t k = 0; k < pixels.size(); ++k) {
    const Vec2f g = ploughingVector(normals[k], raster.side, mu_max);
    gx[k] = gains[k] * g.x();
    gy[k] = gains[k] * g.y();
  }
}

}  // namespace asperity::patch
