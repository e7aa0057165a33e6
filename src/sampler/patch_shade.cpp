// Fragment shading of the CPU sampler (patch_shade.hpp).
#include "sampler/patch_shade.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "asperity/friction/fragment_model.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "math/simd.hpp"
#include "sampler/patch_texture.hpp"

namespace asperity::patch {

namespace {

// Tangent-space normal and mask at uv (flat and 1 when absent).
Fragment sampleMaterial(const Material& material, float u, float v, TexelReading reading) {
  Fragment f;
  if (material.map != nullptr && !material.map->empty())
    f.m = sampleNormal(*material.map, u, v, reading);
  if (material.mask != nullptr) f.gain = sampleMask(*material.mask, u, v, reading);
  return f;
}

Fragment shadePlanar(const Planar& p, TexelReading reading, double x, double y) {
  // uv and frame are affine over the primitive.
  const auto xf = static_cast<float>(x), yf = static_cast<float>(y);
  Fragment f = sampleMaterial(p.material, p.uf[0] + p.uf[1] * xf + p.uf[2] * yf,
                              p.vf[0] + p.vf[1] * xf + p.vf[2] * yf, reading);
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

Fragment shadeCurved(const Curved& c, Side side, TexelReading reading, double x, double y) {
  // The hit point in the shape frame, then the analytic mapping there.
  double z = 0.0;
  castCurved(c, side, x, y, z);
  const Vec3 local = c.origin_local + c.to_local * Vec3(x, y, z);
  const SurfaceFrame sf = surfaceFrameAt(*c.shape, -1, local);
  Fragment f = sampleMaterial(c.material, static_cast<float>(sf.uv.x()),
                              static_cast<float>(sf.uv.y()), reading);
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
  if (id >= 0) return shadePlanar(raster.planars[static_cast<size_t>(id)], volume.reading, x, y);
  return shadeCurved(raster.curveds[static_cast<size_t>(-1 - id)], raster.side, volume.reading, x,
                     y);
}

namespace {

// Whether the batched path applies: a flat-framed planar primitive with a normal map and no
// mask (boxes, planes, flat mesh triangles with the usual textures).
bool batchable(const SurfaceRaster& raster, int32_t id) {
  if (id < 0) return false;
  const Planar& p = raster.planars[static_cast<size_t>(id)];
  if (p.smooth || p.material.map == nullptr || p.material.mask != nullptr) return false;
  return p.material.map->width() > 0 && p.material.map->height() > 0;
}

// Whether every fragment of the primitive has the same meso normal: a planar primitive with
// one frame and neither a normal map nor a mask (a plain ground plane or box face).
bool flat(const SurfaceRaster& raster, int32_t id) {
  if (id < 0) return false;
  const Planar& p = raster.planars[static_cast<size_t>(id)];
  return !p.smooth && (p.material.map == nullptr || p.material.map->empty()) &&
         p.material.mask == nullptr;
}

int log2i(int v) {
  int l = 0;
  while ((1 << l) < v) ++l;
  return l;
}

// Fragments shaded together: small enough for the stack, large enough to amortise the setup.
constexpr size_t kChunk = 64;

// Per-fragment texel offsets (floats into the map) and bilinear weights of one chunk.
struct ChunkTexels {
  alignas(16) float wu[kChunk], wv[kChunk];
  alignas(16) int o00[kChunk], o01[kChunk], o10[kChunk], o11[kChunk];
};

// The meso normals of one chunk in the contact frame, as separate components.
struct ChunkNormals {
  alignas(16) float x[kChunk], y[kChunk], z[kChunk];
};

// What a run of one batchable primitive needs, set up once per run.
struct RunSetup {
  const float* tex = nullptr;
  int w = 0, h = 0, lw = 0;
  bool pow2 = false;  // both sizes powers of two: wrap by masks, rows by shifts
  int floats = 0;     // 3 w h
  float fw = 0.0f, fh = 0.0f, inv_w = 0.0f, inv_h = 0.0f;
  float base = 0.0f, step = 0.0f;  // pixel centre coordinate = base + step * index
};

RunSetup setupRun(const Volume& volume, const Planar& p) {
  const NormalMap& map = *p.material.map;
  RunSetup s;
  s.tex = map.at(0, 0).data();
  s.w = map.width(), s.h = map.height(), s.lw = log2i(s.w);
  s.pow2 = (s.w & (s.w - 1)) == 0 && (s.h & (s.h - 1)) == 0;
  s.floats = 3 * s.w * s.h;
  s.fw = static_cast<float>(s.w), s.fh = static_cast<float>(s.h);
  s.inv_w = 1.0f / s.fw, s.inv_h = 1.0f / s.fh;
  s.base = static_cast<float>(-0.5 * volume.width + 0.5 * volume.pixel);
  s.step = static_cast<float>(volume.pixel);
  return s;
}

// uv at each pixel centre (affine over the primitive), the bracketing texels (repeat) and the
// weights: straight-line code the compiler vectorises (masks and shifts for power-of-two
// maps). Returns the largest offset.
template <bool kPow2>
[[gnu::always_inline]] inline int chunkTexels(const RunSetup& s, const Planar& p,
                                              const uint32_t* pixels, size_t n, ChunkTexels& t) {
  int top = 0;
  for (size_t c = 0; c < n; ++c) {
    // Through int: an unsigned conversion branches on baseline x86-64.
    const auto i = static_cast<int>(pixels[c] & 0xffffu), j = static_cast<int>(pixels[c] >> 16);
    const float x = s.base + s.step * static_cast<float>(i);
    const float y = s.base + s.step * static_cast<float>(j);
    const float xu = (p.uf[0] + p.uf[1] * x + p.uf[2] * y) * s.fw - 0.5f;
    const float xv = (p.vf[0] + p.vf[1] * x + p.vf[2] * y) * s.fh - 0.5f;
    const int bu = floorInt(xu), bv = floorInt(xv);
    t.wu[c] = xu - static_cast<float>(bu);
    t.wv[c] = xv - static_cast<float>(bv);
    int iu, iv, iu1, iv1, row, row1;
    if constexpr (kPow2) {
      iu = bu & (s.w - 1), iv = bv & (s.h - 1);
      iu1 = (iu + 1) & (s.w - 1), iv1 = (iv + 1) & (s.h - 1);
      row = iv << s.lw, row1 = iv1 << s.lw;
    } else {
      iu = wrapTexelBy(bu, s.w, s.inv_w), iv = wrapTexelBy(bv, s.h, s.inv_h);
      iu1 = iu + 1 == s.w ? 0 : iu + 1, iv1 = iv + 1 == s.h ? 0 : iv + 1;
      row = iv * s.w, row1 = iv1 * s.w;
    }
    t.o00[c] = 3 * (row + iu);
    t.o01[c] = 3 * (row + iu1);
    t.o10[c] = 3 * (row1 + iu);
    t.o11[c] = 3 * (row1 + iu1);
    top = std::max(top, std::max(std::max(t.o00[c], t.o01[c]), std::max(t.o10[c], t.o11[c])));
  }
  return top;
}

// The texel each pixel centre falls in (repeat), as an offset in floats into the map: the
// nearest reading's one fetch per fragment, straight-line code as chunkTexels. Returns the
// largest offset.
template <bool kPow2>
[[gnu::always_inline]] inline int chunkNearestTexels(const RunSetup& s, const Planar& p,
                                                     const uint32_t* pixels, size_t n,
                                                     int* offset) {
  int top = 0;
  for (size_t c = 0; c < n; ++c) {
    const auto i = static_cast<int>(pixels[c] & 0xffffu), j = static_cast<int>(pixels[c] >> 16);
    const float x = s.base + s.step * static_cast<float>(i);
    const float y = s.base + s.step * static_cast<float>(j);
    const int bu = floorInt((p.uf[0] + p.uf[1] * x + p.uf[2] * y) * s.fw + kNearestTexelNudge);
    const int bv = floorInt((p.vf[0] + p.vf[1] * x + p.vf[2] * y) * s.fh + kNearestTexelNudge);
    int row, iu;
    if constexpr (kPow2) {
      iu = bu & (s.w - 1), row = (bv & (s.h - 1)) << s.lw;
    } else {
      iu = wrapTexelBy(bu, s.w, s.inv_w), row = wrapTexelBy(bv, s.h, s.inv_h) * s.w;
    }
    offset[c] = 3 * (row + iu);
    top = std::max(top, offset[c]);
  }
  return top;
}

// Each fragment's texel through the primitive's constant frame.
[[gnu::always_inline]] inline void chunkNearestNormals(const float* tex, const Eigen::Matrix3f& f,
                                                       const int* offset, size_t n,
                                                       ChunkNormals& m) {
  for (size_t c = 0; c < n; ++c) {
    const float* b = tex + offset[c];
    m.x[c] = f(0, 0) * b[0] + f(0, 1) * b[1] + f(0, 2) * b[2];
    m.y[c] = f(1, 0) * b[0] + f(1, 1) * b[1] + f(1, 2) * b[2];
    m.z[c] = f(2, 0) * b[0] + f(2, 1) * b[1] + f(2, 2) * b[2];
  }
}

// chunkNearestNormals with each texel's three channels in one 4-float register (the same float
// operations per channel), so that no lane gathers from memory: a gather of eight scattered
// texels costs more than eight loads on the processors measured. Reads one float past each
// texel, so the caller keeps it off the map's last texel.
[[gnu::always_inline]] inline void chunkNearestNormals4(const float* tex, const Eigen::Matrix3f& f,
                                                        const int* offset, size_t n,
                                                        ChunkNormals& m) {
  using Texel = Eigen::Array4f;
  const Texel c0(f(0, 0), f(1, 0), f(2, 0), 0.0f);
  const Texel c1(f(0, 1), f(1, 1), f(2, 1), 0.0f);
  const Texel c2(f(0, 2), f(1, 2), f(2, 2), 0.0f);
  for (size_t c = 0; c < n; ++c) {
    const Texel b(Eigen::Map<const Texel>(tex + offset[c]));
    const Texel frame = c0 * b[0] + c1 * b[1] + c2 * b[2];
    m.x[c] = frame[0];
    m.y[c] = frame[1];
    m.z[c] = frame[2];
  }
}

// Bilinear blend (unnormalised, as sampleNormal) through the primitive's constant frame.
[[gnu::always_inline]] inline void chunkNormals(const float* tex, const Eigen::Matrix3f& f,
                                                const ChunkTexels& t, size_t n, ChunkNormals& m) {
  for (size_t c = 0; c < n; ++c) {
    float b[3];
    for (int k = 0; k < 3; ++k) {
      const float bottom = tex[t.o00[c] + k] + t.wu[c] * (tex[t.o01[c] + k] - tex[t.o00[c] + k]);
      const float top = tex[t.o10[c] + k] + t.wu[c] * (tex[t.o11[c] + k] - tex[t.o10[c] + k]);
      b[k] = bottom + t.wv[c] * (top - bottom);
    }
    m.x[c] = f(0, 0) * b[0] + f(0, 1) * b[1] + f(0, 2) * b[2];
    m.y[c] = f(1, 0) * b[0] + f(1, 1) * b[1] + f(1, 2) * b[2];
    m.z[c] = f(2, 0) * b[0] + f(2, 1) * b[1] + f(2, 2) * b[2];
  }
}

// chunkNormals with each texel's three channels in one 4-float register: the same float
// operations per channel. Reads one float past each texel, so the caller keeps it off the
// map's last texel.
[[gnu::always_inline]] inline void chunkNormals4(const float* tex, const Eigen::Matrix3f& f,
                                                 const ChunkTexels& t, size_t n, ChunkNormals& m) {
  using Texel = Eigen::Array4f;
  auto load = [tex](int offset) { return Texel(Eigen::Map<const Texel>(tex + offset)); };
  const Texel c0(f(0, 0), f(1, 0), f(2, 0), 0.0f);
  const Texel c1(f(0, 1), f(1, 1), f(2, 1), 0.0f);
  const Texel c2(f(0, 2), f(1, 2), f(2, 2), 0.0f);
  for (size_t c = 0; c < n; ++c) {
    const Texel t00 = load(t.o00[c]), t01 = load(t.o01[c]);
    const Texel t10 = load(t.o10[c]), t11 = load(t.o11[c]);
    const Texel bottom = t00 + t.wu[c] * (t01 - t00);
    const Texel top = t10 + t.wu[c] * (t11 - t10);
    const Texel b = bottom + t.wv[c] * (top - bottom);
    const Texel frame = c0 * b[0] + c1 * b[1] + c2 * b[2];
    m.x[c] = frame[0];
    m.y[c] = frame[1];
    m.z[c] = frame[2];
  }
}

constexpr float kTwoOverPi = static_cast<float>(2.0 / kPi);

// Whether ploughingVector takes its unclamped branch ((2/pi) |m_tb| <= mu_max c, c > 0),
// compared in squares so that no sqrt (a libm call for errno) blocks vectorisation; the two
// branches agree where the comparison is within rounding of equality.
inline bool unclamped(float x, float y, float height, float mu_max) {
  const float slope = kTwoOverPi * kTwoOverPi * (x * x + y * y);
  const float limit = (mu_max * height) * (mu_max * height);
  return (height > 0.0f) & (slope <= limit);
}

// The unclamped branch of ploughingVector (g = (2/pi) m_tb / c, the same float operations) for
// every fragment, branch-free so it vectorises; returns how many need the clamped branch
// (chunkClamped overwrites those).
[[gnu::always_inline]] inline int chunkPloughing(const ChunkNormals& m, size_t n, float sign,
                                                 float mu_max, float* gx, float* gy) {
  int clamped = 0;
  for (size_t c = 0; c < n; ++c) {
    const float height = sign * m.z[c];
    const float ratio = sign * kTwoOverPi / height;
    gx[c] = ratio * m.x[c];
    gy[c] = ratio * m.y[c];
    clamped += unclamped(m.x[c], m.y[c], height, mu_max) ? 0 : 1;
  }
  return clamped;
}

// The fragments chunkPloughing left out (steep or facing away) through the friction module,
// which decides the branch itself.
void chunkClamped(const ChunkNormals& m, size_t n, Side side, float mu_max, float* gx, float* gy) {
  const float sign = side == Side::B ? 1.0f : -1.0f;
  for (size_t c = 0; c < n; ++c) {
    if (unclamped(m.x[c], m.y[c], sign * m.z[c], mu_max)) continue;
    const Vec2f g = ploughingVector(Vec3f(m.x[c], m.y[c], m.z[c]), side, mu_max);
    gx[c] = g.x();
    gy[c] = g.y();
  }
}

// Ploughing vectors of fragments [k0, k1) of one batchable primitive (unit gain), by chunks:
// texel indices, normals, then g; no per-fragment call and no normalisation.
[[gnu::always_inline]] inline void shadeRunBody(const Volume& volume, const Planar& p, Side side,
                                                float mu_max, std::span<const uint32_t> pixels,
                                                size_t k0, size_t k1, float* gx, float* gy) {
  const RunSetup setup = setupRun(volume, p);
  const float sign = side == Side::B ? 1.0f : -1.0f;
  ChunkTexels texels;
  ChunkNormals normals;
  const bool nearest = volume.reading == TexelReading::Nearest;
  for (size_t c0 = k0; c0 < k1; c0 += kChunk) {
    const size_t n = std::min(kChunk, k1 - c0);
    const uint32_t* chunk = pixels.data() + c0;
    if (nearest) {
      const int top = setup.pow2 ? chunkNearestTexels<true>(setup, p, chunk, n, texels.o00)
                                 : chunkNearestTexels<false>(setup, p, chunk, n, texels.o00);
      if (top + 4 <= setup.floats) {
        chunkNearestNormals4(setup.tex, p.frame, texels.o00, n, normals);
      } else {
        chunkNearestNormals(setup.tex, p.frame, texels.o00, n, normals);
      }
    } else {
      // Four floats from each texel unless the last texel of the map is among them.
      const int top = setup.pow2 ? chunkTexels<true>(setup, p, chunk, n, texels)
                                 : chunkTexels<false>(setup, p, chunk, n, texels);
      if (top + 4 <= setup.floats) {
        chunkNormals4(setup.tex, p.frame, texels, n, normals);
      } else {
        chunkNormals(setup.tex, p.frame, texels, n, normals);
      }
    }
    if (chunkPloughing(normals, n, sign, mu_max, gx + c0, gy + c0) > 0) {
      chunkClamped(normals, n, side, mu_max, gx + c0, gy + c0);
    }
  }
}

#if ASPERITY_AVX2_COPIES
// The AVX2 copy (math/simd.hpp): the chunk functions are always inlined, so they are compiled
// with AVX2 too (eight fragments per register).
ASPERITY_TARGET_AVX2 void shadeRunAvx2(const Volume& volume, const Planar& p, Side side,
                                       float mu_max, std::span<const uint32_t> pixels, size_t k0,
                                       size_t k1, float* gx, float* gy) {
  shadeRunBody(volume, p, side, mu_max, pixels, k0, k1, gx, gy);
}
#endif

void shadeRun(const Volume& volume, const Planar& p, Side side, float mu_max,
              std::span<const uint32_t> pixels, size_t k0, size_t k1, float* gx, float* gy) {
#if ASPERITY_AVX2_COPIES
  if (simd::avx2(volume.simd)) return shadeRunAvx2(volume, p, side, mu_max, pixels, k0, k1, gx, gy);
#endif
  shadeRunBody(volume, p, side, mu_max, pixels, k0, k1, gx, gy);
}

}  // namespace

void shadePloughing(const Volume& volume, const SurfaceRaster& raster,
                    std::span<const uint32_t> pixels, float mu_max, float* gx, float* gy) {
  const int r = volume.resolution;
  auto primitiveAt = [&](size_t k) {
    const uint32_t packed = pixels[k];
    return raster.primitive[(packed >> 16) * static_cast<uint32_t>(r) + (packed & 0xffffu)];
  };
  // One primitive in the patch (a box face, a plane): every covered pixel is one run.
  if (raster.planars.size() == 1 && raster.curveds.empty() && batchable(raster, 0)) {
    shadeRun(volume, raster.planars[0], raster.side, mu_max, pixels, 0, pixels.size(), gx, gy);
    return;
  }
  // Runs of one batchable primitive in bulk, runs of a flat one from their first fragment,
  // the rest one by one.
  for (size_t k = 0; k < pixels.size();) {
    const int32_t id = primitiveAt(k);
    size_t end = k + 1;
    const bool batch = batchable(raster, id), one_vector = !batch && flat(raster, id);
    if (batch || one_vector) {
      while (end < pixels.size() && primitiveAt(end) == id) ++end;
    }
    if (batch) {
      shadeRun(volume, raster.planars[static_cast<size_t>(id)], raster.side, mu_max, pixels, k, end,
               gx, gy);
      k = end;
      continue;
    }
    // Eqs. 3 to 6 through the friction module, scaled by the mask
    // (max(0, s g.d) = s max(0, g.d) for s >= 0).
    const int i = static_cast<int>(pixels[k] & 0xffffu), j = static_cast<int>(pixels[k] >> 16);
    const Fragment f = shadeFragment(volume, raster, j * r + i);
    const Vec2f g = ploughingVector(f.m, raster.side, mu_max);
    std::fill(gx + k, gx + end, f.gain * g.x());
    std::fill(gy + k, gy + end, f.gain * g.y());
    k = end;
  }
}

}  // namespace asperity::patch
