// The CPU patch rasteriser (SPEC 3): one surface's geometry inside a contact's viewing volume,
// projected orthographically along n onto an R x R grid of pixel centres.
//
// Everything here is in the contact frame: x along t, y along b, z along n, origin at the
// contact point. Pixel (i, j) has its centre at x = -w/2 + (i + 1/2) w/R, y = -w/2 + (j + 1/2)
// w/R (row 0 at -b, like an OpenGL viewport); index j * R + i. A fragment is kept when
// |z| <= half_depth (the depth clip of the volume) and, among the fragments of one surface at a
// pixel, it is the one nearest the other body (largest z for B, smallest for A: what a depth
// test sees looking from the other body).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "asperity/friction/fragment_model.hpp"
#include "asperity/geometry/shape.hpp"
#include "asperity/math/simd_copy.hpp"
#include "asperity/math/types.hpp"
#include "asperity/sampler/friction_provider.hpp"

namespace asperity::patch {

// Where the nearest reading looks for a pixel's texel: its centre moved this far (in texels)
// along +u and +v. A centre exactly on a texel edge is common (round scene numbers on binary
// texel sizes: a box corner at 0.9 m on 0.05 m / 128 texels) and would be decided by rounding,
// which differs between the CPU's uv and the GPU's interpolated one: one pixel row of a
// sawtooth then reads the other facet. Moved, such centres lie well inside one texel on both,
// and the reading shifts by a hundredth of a texel (10 um on 1 mm texels).
inline constexpr float kNearestTexelNudge = 0.01f;

// The viewing volume of one contact (SPEC 3): centre, axes and size.
struct Volume {
  Vec3 origin = Vec3::Zero();    // contact point (world)
  Mat3 axes = Mat3::Identity();  // columns t, b, n (world)
  double width = 0.02;           // w (m)
  double half_depth = 1e-4;      // (|phi| + 0.01 w) / 2 (m)
  int resolution = 16;           // R
  double pixel = 0.02 / 16;      // w / R
  // Which compiled copy of the rasterising and shading loops runs (the sampler's option).
  SimdCopy simd = SimdCopy::Auto;
  // How each pixel reads the normal maps and masks (the settings' texel_reading).
  TexelReading reading = TexelReading::Nearest;

  double centreX(int i) const { return -0.5 * width + (i + 0.5) * pixel; }
  // Packs pixel (i, j) for the fragment lists (i, j < 2^16).
  static uint32_t pack(int i, int j) {
    return static_cast<uint32_t>(i) | static_cast<uint32_t>(j) << 16;
  }
};

// a + dx x + dy y: an attribute that is affine over a planar primitive.
struct Affine {
  double c = 0.0, dx = 0.0, dy = 0.0;
  double at(double x, double y) const { return c + dx * x + dy * y; }
};

// One edge of a counter-clockwise convex polygon: inside when e > 0, or e == 0 on a top or left
// edge (the top-left rule, so a pixel centre on a shared edge belongs to one triangle).
struct Edge {
  double a = 0.0, b = 0.0, c = 0.0;
  bool inclusive = false;
  bool inside(double x, double y) const {
    const double e = a * x + b * y + c;
    return e > 0.0 || (e == 0.0 && inclusive);
  }
};

// What the shading needs to evaluate a fragment's meso normal, per primitive.
struct Material {
  const NormalMap* map = nullptr;  // null = flat
  const GainMask* mask = nullptr;  // null = 1
};

// A planar primitive: a triangle, a box face, or a whole plane (no edges), with affine depth,
// uv and (for smooth-shaded mesh triangles) tangent frame in the contact frame.
struct Planar {
  int edge_count = 0;
  std::array<Edge, 4> edges{};
  Affine z;
  Affine u, v;
  std::array<float, 3> uf{}, vf{};  // u, v as float (c, dx, dy) for the fragment loop
  bool smooth = false;              // false: `frame` holds the constant frame
  std::array<Affine, 9> tbn{};      // T, B, N components (contact frame)
  Eigen::Matrix3f frame =
      Eigen::Matrix3f::Identity();       // columns T, B, N at tbn[].c (flat primitives)
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1;  // pixel bounds (inclusive)
  Material material;
};

// A curved primitive (sphere, capsule, cylinder): every pixel casts a ray along n.
struct Curved {
  const Shape* shape = nullptr;
  Mat3 to_local = Mat3::Identity();  // contact frame -> shape frame (rotation)
  Vec3 origin_local = Vec3::Zero();  // contact point in the shape frame
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
  Material material;
};

// How far (m) one surface's depth clip decisions are from changing, per plane of the clip
// (z = h, z = -h) and per side of it: `in_*` how far a kept fragment lies inside that plane,
// `out_*` how far a clipped one lies beyond it, at the least. Patch coherence keeps a sample
// while its surfaces and the clip moved by less (patch_reuse.hpp). The default, 0, knows
// nothing; `unlimited()` is where no decision has been made yet.
struct DepthMargins {
  double in_top = 0.0, out_top = 0.0, in_bottom = 0.0, out_bottom = 0.0;

  static DepthMargins unlimited() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, inf, inf};
  }
  // A decision on a fragment at depth z.
  void note(double z, double h) {
    if (z <= h)
      in_top = std::min(in_top, h - z);
    else
      out_top = std::min(out_top, z - h);
    if (z >= -h)
      in_bottom = std::min(in_bottom, z + h);
    else
      out_bottom = std::min(out_bottom, -h - z);
  }
  // A decision on a whole primitive, its fragments at depths in [zmin, zmax]: the extremes
  // bound every margin.
  void noteRange(double zmin, double zmax, double h) {
    note(zmin, h);
    note(zmax, h);
  }
  // Whether a whole primitive, its fragments at depths in [zmin, zmax], lies beyond the clip
  // widened by `slack`: then it is rejected, a decision noted here.
  bool rejectsRange(double zmin, double zmax, double h, double slack = 0.0) {
    if (!(zmin > h + slack || zmax < -h - slack)) return false;
    noteRange(zmin, zmax, h);
    return true;
  }
  // A fragment beyond the clip may move in by no more than `m` (either plane).
  void limitOutside(double m) {
    out_top = std::min(out_top, m);
    out_bottom = std::min(out_bottom, m);
  }
  // Decisions whose margins are not known.
  void forget() { *this = DepthMargins{}; }
};

// One surface's pixels: for each, the kept fragment's primitive and its depth key.
struct SurfaceRaster {
  Side side = Side::B;
  std::vector<float> key;  // z for B, -z for A; -inf where nothing is kept
  std::vector<int32_t>
      primitive;  // >= 0 planar index, < 0: curved index -1 - p; unused if key=-inf
  std::vector<Planar> planars;
  std::vector<Curved> curveds;
  // Only pixels in this window are rasterised: rows wj0..wj1, in row j pixels win_lo[j] to
  // win_hi[j] (all after reset). The sampler narrows B's to A's coverage when only P matters.
  int wj0 = 0, wj1 = -1;
  std::vector<int> win_lo, win_hi;
  // Per row, the pixels where a fragment passed the coverage tests lie in cov_lo[j]..cov_hi[j]
  // (empty when lo > hi).
  std::vector<int> cov_lo, cov_hi;

  DepthMargins depth;  // of the depth clip decisions made for this surface

  void reset(Side s, int resolution);
  bool covered(int pixel) const { return key[static_cast<size_t>(pixel)] > kEmpty; }
  // Widens row j's coverage span to [lo, hi] (lo <= hi).
  void cover(int j, int lo, int hi) {
    const auto row = static_cast<size_t>(j);
    cov_lo[row] = std::min(cov_lo[row], lo);
    cov_hi[row] = std::max(cov_hi[row], hi);
  }
  static constexpr float kEmpty = -3.0e38f;
};

// Builds a planar primitive from a counter-clockwise (seen from +n) convex polygon of up to 4
// vertices (contact frame) with per-vertex attributes u, v and frame (9 floats). Returns false
// when it is edge-on or outside the volume's footprint; notes the depth clip decisions it
// makes in `depth`.
struct PolygonVertex {
  Vec3 p = Vec3::Zero();
  double u = 0.0, v = 0.0;
  std::array<double, 9> tbn{};
};
// Fills Planar::uf, vf from u, v.
void setFloatUv(Planar& prim);

bool makePlanar(const Volume& volume, const PolygonVertex* vertices, int count, bool smooth,
                const Material& material, Planar& out, DepthMargins& depth);
inline constexpr int kMaxPolygonCorners = 4;

// makePlanar in two steps, for a caller that has the corners' positions before their
// attributes (a box's sides seen edge-on are mostly rejected): boundPlanar sets out's pixel
// bounds and makes the reject tests and their depth notes from the positions alone (false:
// the polygon covers no pixel centre); finishPlanar then sets its edges, depth, uv and frame
// from the same corners with their attributes.
bool boundPlanar(const Volume& volume, const Vec3* corners, int count, Planar& out,
                 DepthMargins& depth);
void finishPlanar(const PolygonVertex* vertices, int count, bool smooth, const Material& material,
                  Planar& out);

// The pixel index range [lo, hi] whose centres may lie in [a, b] along one axis (clamped to
// the grid; empty when lo > hi).
void pixelRange(const Volume& volume, double a, double b, int& lo, int& hi);

// Rasterises into `raster` (depth clip + nearest-to-the-other-body test).
void rasterisePlanar(const Volume& volume, const Planar& prim, int32_t id, SurfaceRaster& raster);
void rasteriseCurved(const Volume& volume, const Curved& prim, int32_t id, SurfaceRaster& raster);

// The ray along n through (x, y) of the contact frame against a curved primitive: the surface
// point that faces the other body (exit for B, entry for A), as z. False when it misses.
bool castCurved(const Curved& prim, Side side, double x, double y, double& z);

}  // namespace asperity::patch
