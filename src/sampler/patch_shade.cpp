// Fragment shading of the CPU sampler (patch_shade.hpp).
#include "sampler/patch_shade.hpp"

#include <algorithm>
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

}  // namespace

Fragment shadeFragment(const Volume& volume, const SurfaceRaster& raster, int pixel) {
  const int r = volume.resolution;
  const double x = volume.centreX(pixel % r), y = volume.centreX(pixel / r);
  const int32_t id = raster.primitive[static_cast<size_t>(pixel)];
  if (id >= 0) return shadePlanar(raster.planars[static_cast<size_t>(id)], x, y);
  return shadeCurved(raster.curveds[static_cast<size_t>(-1 - id)], raster.side, x, y);
}

namespace {

// Whether the batched path applies: a flat-framed planar primitive with a power-of-two normal
// map and no mask (boxes, planes, flat mesh triangles with the usual textures).
bool batchable(const SurfaceRaster& raster, int32_t id) {
  if (id < 0) return false;
  const Planar& p = raster.planars[static_cast<size_t>(id)];
  if (p.smooth || p.material.map == nullptr || p.material.mask != nullptr) return false;
  const int w = p.material.map->width(), h = p.material.map->height();
  return w > 0 && h > 0 && (w & (w - 1)) == 0 && (h & (h - 1)) == 0;
}

int log2i(int v) {
  int l = 0;
  while ((1 << l) < v) ++l;
  return l;
}

// Meso normals of fragments [k0, k1) of one batchable primitive: texel indices and weights for
// a chunk in straight-line (vectorisable) code, then the bilinear fetch and the frame.
void shadeRun(const Volume& volume, const Planar& p, std::span<const uint32_t> pixels, size_t k0,
              size_t k1, Vec3f* normals) {
  const NormalMap& map = *p.material.map;
  const int w = map.width(), h = map.height(), lw = log2i(w);
  const float fw = static_cast<float>(w), fh = static_cast<float>(h);
  const auto base = static_cast<float>(-0.5 * volume.width + 0.5 * volume.pixel);
  const auto step = static_cast<float>(volume.pixel);
  const float* tex = map.at(0, 0).data();
  constexpr size_t kChunk = 64;
  alignas(16) float wu[kChunk], wv[kChunk];
  alignas(16) int o00[kChunk], o01[kChunk], o10[kChunk], o11[kChunk];
  for (size_t c0 = k0; c0 < k1; c0 += kChunk) {
    const size_t n = std::min(kChunk, k1 - c0);
    // uv at the pixel centre, the bracketing texels (repeat) and the weights.
    for (size_t c = 0; c < n; ++c) {
      const uint32_t packed = pixels[c0 + c];
      const float x = base + step * static_cast<float>(packed & 0xffffu);
      const float y = base + step * static_cast<float>(packed >> 16);
      const float xu = (p.uf[0] + p.uf[1] * x + p.uf[2] * y) * fw - 0.5f;
      const float xv = (p.vf[0] + p.vf[1] * x + p.vf[2] * y) * fh - 0.5f;
      const float bu = floorFast(xu), bv = floorFast(xv);
      wu[c] = xu - bu;
      wv[c] = xv - bv;
      const int iu = static_cast<int>(bu) & (w - 1), iv = static_cast<int>(bv) & (h - 1);
      const int iu1 = (iu + 1) & (w - 1), iv1 = (iv + 1) & (h - 1);
      o00[c] = 3 * ((iv << lw) + iu);
      o01[c] = 3 * ((iv << lw) + iu1);
      o10[c] = 3 * ((iv1 << lw) + iu);
      o11[c] = 3 * ((iv1 << lw) + iu1);
    }
    // Bilinear blend (unnormalised) through the constant frame.
    const Eigen::Matrix3f& f = p.frame;
    for (size_t c = 0; c < n; ++c) {
      float m[3];
      for (int k = 0; k < 3; ++k) {
        const float bottom = tex[o00[c] + k] + wu[c] * (tex[o01[c] + k] - tex[o00[c] + k]);
        const float top = tex[o10[c] + k] + wu[c] * (tex[o11[c] + k] - tex[o10[c] + k]);
        m[k] = bottom + wv[c] * (top - bottom);
      }
      normals[c0 + c] = Vec3f(f(0, 0) * m[0] + f(0, 1) * m[1] + f(0, 2) * m[2],
                              f(1, 0) * m[0] + f(1, 1) * m[1] + f(1, 2) * m[2],
                              f(2, 0) * m[0] + f(2, 1) * m[1] + f(2, 2) * m[2]);
    }
  }
}

}  // namespace

void shadePloughing(const Volume& volume, const SurfaceRaster& raster,
                    std::span<const uint32_t> pixels, float mu_max, ShadeScratch& scratch,
                    float* gx, float* gy) {
  const int r = volume.resolution;
  auto primitiveAt = [&](size_t k) {
    const uint32_t packed = pixels[k];
    return raster.primitive[(packed >> 16) * static_cast<uint32_t>(r) + (packed & 0xffffu)];
  };
  std::vector<Vec3f>& normals = scratch.normals;
  std::vector<float>& gains = scratch.gains;
  if (normals.size() < pixels.size()) {
    normals.resize(pixels.size());
    gains.resize(pixels.size());
  }
  // Pass 1: meso normals; runs of one batchable primitive in bulk, the rest one by one.
  bool all_unit_gain = true;
  for (size_t k = 0; k < pixels.size();) {
    const int32_t id = primitiveAt(k);
    if (batchable(raster, id)) {
      size_t end = k + 1;
      while (end < pixels.size() && primitiveAt(end) == id) ++end;
      shadeRun(volume, raster.planars[static_cast<size_t>(id)], pixels, k, end, normals.data());
      std::fill(gains.begin() + static_cast<long>(k), gains.begin() + static_cast<long>(end), 1.0f);
      k = end;
      continue;
    }
    const int i = static_cast<int>(pixels[k] & 0xffffu), j = static_cast<int>(pixels[k] >> 16);
    const Fragment f = shadeFragment(volume, raster, j * r + i);
    normals[k] = f.m;
    gains[k] = f.gain;
    all_unit_gain = all_unit_gain && f.gain == 1.0f;
    ++k;
  }
  // Pass 2: Eqs. 3 to 6 through the friction module, scaled by the mask
  // (max(0, s g.d) = s max(0, g.d) for s >= 0).
  for (size_t k = 0; k < pixels.size(); ++k) {
    const Vec2f g = ploughingVector(normals[k], raster.side, mu_max);
    gx[k] = all_unit_gain ? g.x() : gains[k] * g.x();
    gy[k] = all_unit_gain ? g.y() : gains[k] * g.y();
  }
}

}  // namespace asperity::patch
