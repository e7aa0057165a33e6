// The CPU patch rasteriser's planar primitives, by edge functions (curved ones:
// patch_raster_curved.cpp).
#include "sampler/patch_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/simd.hpp"

namespace asperity::patch {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Affine fit of an attribute through three points (x, y) -> value.
Affine fitAffine(const Vec3& p0, double a0, double a1, double a2, const Eigen::Matrix2d& inv) {
  const double d1 = a1 - a0, d2 = a2 - a0;
  Affine f;
  f.dx = inv(0, 0) * d1 + inv(1, 0) * d2;
  f.dy = inv(0, 1) * d1 + inv(1, 1) * d2;
  f.c = a0 - f.dx * p0.x() - f.dy * p0.y();
  return f;
}

}  // namespace

void pixelRange(const Volume& volume, double a, double b, int& lo, int& hi) {
  // Conservative by one pixel; the coverage tests decide exactly.
  const double half = 0.5 * volume.width;
  const double fa = std::floor((a + half) / volume.pixel - 0.5);
  const double fb = std::ceil((b + half) / volume.pixel - 0.5);
  lo = static_cast<int>(std::clamp(fa, 0.0, static_cast<double>(volume.resolution)));
  hi = static_cast<int>(std::clamp(fb, -1.0, static_cast<double>(volume.resolution - 1)));
}

void setFloatUv(Planar& prim) {
  prim.uf = {static_cast<float>(prim.u.c), static_cast<float>(prim.u.dx),
             static_cast<float>(prim.u.dy)};
  prim.vf = {static_cast<float>(prim.v.c), static_cast<float>(prim.v.dx),
             static_cast<float>(prim.v.dy)};
}

void SurfaceRaster::reset(Side s, int resolution) {
  side = s;
  planars.clear();
  curveds.clear();
  depth = DepthMargins::unlimited();
  const int pixels = resolution * resolution;
  wj0 = 0;
  wj1 = resolution - 1;
  win_lo.assign(static_cast<size_t>(resolution), 0);
  win_hi.assign(static_cast<size_t>(resolution), resolution - 1);
  cov_lo.assign(static_cast<size_t>(resolution), resolution);
  cov_hi.assign(static_cast<size_t>(resolution), -1);
  key.assign(static_cast<size_t>(pixels), kEmpty);
  primitive.resize(static_cast<size_t>(pixels));
}

namespace {

// The polygon's part within the depth clip widened by `widen`, |z| <= h + widen (and far beyond
// rounding): its extent in x and y, as [lo, hi] per axis. False when no part is within.
bool extentWithinDepth(const Volume& volume, double widen, const Vec3* corners, int count,
                       std::array<double, 2>& lo, std::array<double, 2>& hi) {
  const double h = volume.half_depth + widen + 1e-9 * volume.width;
  // Sutherland-Hodgman against z <= h (a convex polygon of up to 4 corners gains at most one
  // corner), then against -z <= h with the kept corners going straight into the extent.
  std::array<Vec3, 8> kept;
  int n = 0;
  for (int k = 0; k < count; ++k) {
    const int next = k + 1 == count ? 0 : k + 1;
    const Vec3& p = corners[k];
    const Vec3& q = corners[next];
    const double dp = p.z() - h, dq = q.z() - h;
    if (dp <= 0.0) kept[static_cast<size_t>(n++)] = p;
    if ((dp <= 0.0) != (dq <= 0.0)) kept[static_cast<size_t>(n++)] = p + (q - p) * (dp / (dp - dq));
  }
  lo = {kInf, kInf}, hi = {-kInf, -kInf};
  auto grow = [&](const Vec3& p) {
    lo[0] = std::min(lo[0], p.x()), hi[0] = std::max(hi[0], p.x());
    lo[1] = std::min(lo[1], p.y()), hi[1] = std::max(hi[1], p.y());
  };
  bool any = false;
  for (int k = 0; k < n; ++k) {
    const int next = k + 1 == n ? 0 : k + 1;
    const Vec3& p = kept[static_cast<size_t>(k)];
    const Vec3& q = kept[static_cast<size_t>(next)];
    const double dp = -p.z() - h, dq = -q.z() - h;
    if (dp <= 0.0) grow(p), any = true;
    if ((dp <= 0.0) != (dq <= 0.0)) grow(p + (q - p) * (dp / (dp - dq))), any = true;
  }
  return any;
}

// Whether some pixel centre lies in [a, b] along one axis, give or take far more than rounding
// (pixelRange's range is wider by a pixel on each side).
bool centreWithin(const Volume& volume, double a, double b) {
  const double slack = 1e-6;
  const double half = 0.5 * volume.width;
  const double first = std::max(0.0, std::ceil((a + half) / volume.pixel - 0.5 - slack));
  const double last =
      std::min(volume.resolution - 1.0, std::floor((b + half) / volume.pixel - 0.5 + slack));
  return first <= last;
}

// Whether no pixel centre can lie in the extent [lo, hi].
bool noCentreWithin(const Volume& volume, const std::array<double, 2>& lo,
                    const std::array<double, 2>& hi) {
  return !centreWithin(volume, lo[0], hi[0]) || !centreWithin(volume, lo[1], hi[1]);
}

// Notes rejecting a face seen nearly edge-on because no pixel centre lies in its part within
// the clip: its fragments beyond the clip may move in by the clip's own margin, 0.005 w
// (SPEC 3), when the face is still rejected with the clip that much deeper, else unknown.
void noteEdgeOn(const Volume& volume, const Vec3* corners, int count, DepthMargins& depth) {
  const double widen = 0.005 * volume.width;
  std::array<double, 2> lo{}, hi{};
  if (!extentWithinDepth(volume, widen, corners, count, lo, hi) || noCentreWithin(volume, lo, hi))
    depth.limitOutside(widen);
  else
    depth.forget();
}

// The polygon's pixel bounds in `out`; false when it surely covers no pixel centre: entirely
// beyond the depth clip or the footprint, or seen so nearly edge-on that its band within the
// clip holds no centre (decisions noted in `depth`).
bool boundPixels(const Volume& volume, const Vec3* corners, int count, Planar& out,
                 DepthMargins& depth) {
  // Reject: entirely beyond the depth clip or the footprint.
  double zmin = kInf, zmax = -kInf, xmin = kInf, xmax = -kInf, ymin = kInf, ymax = -kInf;
  for (int k = 0; k < count; ++k) {
    const Vec3& p = corners[k];
    zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  }
  const double h = volume.half_depth;
  if (depth.rejectsRange(zmin, zmax, h)) return false;
  pixelRange(volume, xmin, xmax, out.i0, out.i1);
  pixelRange(volume, ymin, ymax, out.j0, out.j1);
  if (out.i0 > out.i1 || out.j0 > out.j1) return false;
  // A face seen nearly edge-on (a box's side beyond its bottom face) reaches the depth clip in
  // a thin band only: when no pixel centre can lie in that band's extent, nothing is covered.
  // Worth the clipping where the range is two pixels or less across (a band between centres).
  // Without clipping, that holds at any depth (clipping only narrows the extent).
  if (out.i1 - out.i0 <= 1 || out.j1 - out.j0 <= 1) {
    std::array<double, 2> lo{xmin, ymin}, hi{xmax, ymax};
    const bool clipped = zmin < -h || zmax > h;
    if ((clipped && !extentWithinDepth(volume, 0.0, corners, count, lo, hi)) ||
        noCentreWithin(volume, lo, hi)) {
      if (clipped) noteEdgeOn(volume, corners, count, depth);
      return false;
    }
  }
  return true;
}

// Edges with the top-left rule (counter-clockwise, y up: left edges go down).
void setEdges(const PolygonVertex* vtx, int count, Planar& out) {
  out.edge_count = count;
  for (int k = 0; k < count; ++k) {
    const Vec3& a = vtx[k].p;
    const Vec3& b = vtx[(k + 1) % count].p;
    Edge& e = out.edges[static_cast<size_t>(k)];
    e.a = -(b.y() - a.y());
    e.b = b.x() - a.x();
    e.c = -(e.a * a.x() + e.b * a.y());
    e.inclusive = b.y() < a.y() || (b.y() == a.y() && b.x() < a.x());
  }
}

// Affine depth, uv and frame through the first three vertices (the polygon is planar); `inv`
// inverts their (x, y) differences from the first.
void fitAttributes(const PolygonVertex* vtx, bool smooth, const Eigen::Matrix2d& inv, Planar& out) {
  const Vec3 &p0 = vtx[0].p, &p1 = vtx[1].p, &p2 = vtx[2].p;
  out.z = fitAffine(p0, p0.z(), p1.z(), p2.z(), inv);
  out.u = fitAffine(p0, vtx[0].u, vtx[1].u, vtx[2].u, inv);
  out.v = fitAffine(p0, vtx[0].v, vtx[1].v, vtx[2].v, inv);
  out.smooth = smooth;
  for (size_t c = 0; c < 9; ++c) {
    out.tbn[c] = smooth ? fitAffine(p0, vtx[0].tbn[c], vtx[1].tbn[c], vtx[2].tbn[c], inv)
                        : Affine{vtx[0].tbn[c], 0.0, 0.0};
  }
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      out.frame(row, col) = static_cast<float>(out.tbn[static_cast<size_t>(3 * col + row)].c);
    }
  }
  setFloatUv(out);
}

// The (x, y) differences of the second and third corners from the first, as columns.
Eigen::Matrix2d differencesOf(const Vec3* p) {
  Eigen::Matrix2d m;
  m << p[1].x() - p[0].x(), p[2].x() - p[0].x(), p[1].y() - p[0].y(), p[2].y() - p[0].y();
  return m;
}

}  // namespace

bool boundPlanar(const Volume& volume, const Vec3* corners, int count, Planar& out,
                 DepthMargins& depth) {
  if (!boundPixels(volume, corners, count, out, depth)) return false;
  // Edge-on (zero projected area) primitives cover no pixel centre.
  return differencesOf(corners).determinant() > 1e-30 * volume.width * volume.width;
}

void finishPlanar(const PolygonVertex* vtx, int count, bool smooth, const Material& material,
                  Planar& out) {
  setEdges(vtx, count, out);
  const Vec3 first[3] = {vtx[0].p, vtx[1].p, vtx[2].p};
  fitAttributes(vtx, smooth, differencesOf(first).inverse(), out);
  out.material = material;
}

bool makePlanar(const Volume& volume, const PolygonVertex* vtx, int count, bool smooth,
                const Material& material, Planar& out, DepthMargins& depth) {
  std::array<Vec3, kMaxPolygonCorners> corners;
  for (int k = 0; k < count; ++k) corners[static_cast<size_t>(k)] = vtx[k].p;
  if (!boundPlanar(volume, corners.data(), count, out, depth)) return false;
  finishPlanar(vtx, count, smooth, material, out);
  return true;
}

namespace {

// Whether pixel centre (x, y) is inside the primitive's edges (the exact test).
[[gnu::always_inline]] inline bool insideEdges(const Planar& prim, double x, double y) {
  for (int k = 0; k < prim.edge_count; ++k) {
    if (!prim.edges[static_cast<size_t>(k)].inside(x, y)) return false;
  }
  return true;
}

// Narrows [lo, hi] to the pixels of the row where a x + rest satisfies the half-line (> 0, or
// >= 0 when inclusive) or, for the depth clip, |a x + rest| <= h. Conservative: the exact test
// trims the ends afterwards.
[[gnu::always_inline]] inline void clipSpan(const Volume& volume, double a, double lo_value,
                                            double hi_value, int& lo, int& hi) {
  // Solutions of lo_value <= a x <= hi_value, as pixel indices.
  if (a == 0.0) {
    if (lo_value > 0.0 || hi_value < 0.0) hi = lo - 1;
    return;
  }
  const double x0 = volume.centreX(0);
  double from = lo_value / a, to = hi_value / a;
  if (a < 0.0) std::swap(from, to);
  const double limit = volume.resolution + 1.0;
  const double first = std::clamp(std::floor((from - x0) / volume.pixel), -1.0, limit);
  const double last = std::clamp(std::ceil((to - x0) / volume.pixel), -1.0, limit);
  lo = std::max(lo, static_cast<int>(first));
  hi = std::min(hi, static_cast<int>(last));
}

// Where an edge crosses row j, as a pixel index affine in j: t(j) = t0 + dt j. Inside is
// i > t for a lower bound, i < t for an upper one; rows of an edge parallel to x are either
// all in or all out (`row_in`, decided per row). Set up once per primitive: a row then costs
// a multiply-add instead of two divisions.
struct EdgeBound {
  double t0 = 0.0, dt = 0.0;
  bool lower = true, horizontal = false;
};

[[gnu::always_inline]] inline EdgeBound edgeBound(const Volume& volume, const Edge& e) {
  EdgeBound eb;
  eb.horizontal = e.a == 0.0;
  if (eb.horizontal) return eb;
  // a x + b y + c = 0 at x = -(b y + c) / a, with x = x0 + i p and y = x0 + j p.
  const double x0 = volume.centreX(0), p = volume.pixel;
  eb.t0 = (-(e.b * x0 + e.c) / e.a - x0) / p;
  eb.dt = -e.b / e.a;
  eb.lower = e.a > 0.0;
  return eb;
}

// Narrows [lo, hi] by one edge at row j. Pixels more than kSlack pixel widths outside the edge
// are dropped (rounding here is far below that); the rest are left to the exact test.
[[gnu::always_inline]] inline void clipEdge(const EdgeBound& eb, const Edge& e, double y, int j,
                                            int resolution, int& lo, int& hi) {
  constexpr double kSlack = 1e-3;
  if (eb.horizontal) {
    if (e.b * y + e.c < 0.0) hi = lo - 1;
    return;
  }
  const double limit = resolution + 1.0;
  const double t = eb.t0 + eb.dt * j;
  if (eb.lower) {
    lo = std::max(lo, static_cast<int>(std::clamp(std::ceil(t - kSlack), -1.0, limit)));
  } else {
    hi = std::min(hi, static_cast<int>(std::clamp(std::floor(t + kSlack), -1.0, limit)));
  }
}

// The constraints that cut a primitive's pixel box: its edges, and the depth clip, that do not
// hold at every pixel centre in the box. The others are left out of the row clipping and the
// exact tests, which they would pass everywhere (a plane or a large face seen through the
// patch has none; a box corner has two edges).
struct Cuts {
  std::array<int, 4> edges{};
  int edge_count = 0;
  bool depth = false;
  double z_least = 0.0, z_most = 0.0;  // over the box
};

// The pixel-centre box of a primitive: x in [x0, x1], y in [y0, y1], and the largest |x|, |y|.
struct CentreBox {
  double x0, x1, y0, y1, reach_x, reach_y;
};

// The least of the affine c + dx x + dy y over the box: at the corner its slopes point away
// from.
[[gnu::always_inline]] inline double leastOverBox(double c, double dx, double dy,
                                                  const CentreBox& box) {
  const double x = dx >= 0.0 ? box.x0 : box.x1, y = dy >= 0.0 ? box.y0 : box.y1;
  return c + dx * x + dy * y;
}

// Whether the affine c + dx x + dy y stays above `floor` over the box, by a margin far above
// the rounding of evaluating it at a pixel centre.
[[gnu::always_inline]] inline bool aboveOverBox(double c, double dx, double dy, double floor,
                                                const CentreBox& box) {
  const double margin = 1e-9 * (std::abs(c) + std::abs(dx) * box.reach_x +
                                std::abs(dy) * box.reach_y + std::abs(floor));
  return leastOverBox(c, dx, dy, box) > floor + margin;
}

[[gnu::always_inline]] inline Cuts cutsWithin(const Volume& volume, const Planar& prim, int j0,
                                              int j1) {
  CentreBox box{volume.centreX(prim.i0),
                volume.centreX(prim.i1),
                volume.centreX(j0),
                volume.centreX(j1),
                0.0,
                0.0};
  box.reach_x = std::max(std::abs(box.x0), std::abs(box.x1));
  box.reach_y = std::max(std::abs(box.y0), std::abs(box.y1));
  Cuts cuts;
  for (int k = 0; k < prim.edge_count; ++k) {
    const Edge& e = prim.edges[static_cast<size_t>(k)];
    if (!aboveOverBox(e.c, e.a, e.b, 0.0, box))
      cuts.edges[static_cast<size_t>(cuts.edge_count++)] = k;
  }
  // |z| <= h: z > -h and -z > -h.
  const double h = volume.half_depth;
  cuts.depth = !aboveOverBox(prim.z.c, prim.z.dx, prim.z.dy, -h, box) ||
               !aboveOverBox(-prim.z.c, -prim.z.dx, -prim.z.dy, -h, box);
  cuts.z_least = leastOverBox(prim.z.c, prim.z.dx, prim.z.dy, box);
  cuts.z_most = -leastOverBox(-prim.z.c, -prim.z.dx, -prim.z.dy, box);
  return cuts;
}

// Notes the clip decisions of the pixel centres lo..hi of a row where z = zr + dx x. Each
// margin is least at an end of the row, or beside where z crosses -h or h.
[[gnu::always_inline]] inline void noteRow(const Volume& volume, double zr, double dx, double h,
                                           int lo, int hi, DepthMargins& depth) {
  auto note = [&](double i) {
    if (i >= lo && i <= hi) depth.note(zr + dx * volume.centreX(static_cast<int>(i)), h);
  };
  note(lo), note(hi);
  if (dx == 0.0) return;
  for (const double level : {-h, h}) {
    const double i = std::floor(((level - zr) / dx - volume.centreX(0)) / volume.pixel);
    note(i), note(i + 1);
  }
}

// The exact test (edges, depth clip) over the cutting constraints only (the others hold in
// the box).
[[gnu::always_inline]] inline bool insideCuts(const Planar& prim, const Cuts& cuts, double h,
                                              double x, double y) {
  for (int k = 0; k < cuts.edge_count; ++k) {
    if (!prim.edges[static_cast<size_t>(cuts.edges[static_cast<size_t>(k)])].inside(x, y)) {
      return false;
    }
  }
  return !cuts.depth || std::abs(prim.z.at(x, y)) <= h;
}

// Row j's pixels: the primitive's bounds within the window.
[[gnu::always_inline]] inline int rowLo(const Planar& prim, const SurfaceRaster& raster, int j) {
  return std::max(prim.i0, raster.win_lo[static_cast<size_t>(j)]);
}
[[gnu::always_inline]] inline int rowHi(const Planar& prim, const SurfaceRaster& raster, int j) {
  return std::min(prim.i1, raster.win_hi[static_cast<size_t>(j)]);
}

// Small primitives (mesh triangles near pixel size), rows j0..j1: the exact test per pixel.
[[gnu::always_inline]] inline void rasteriseSmallPlanar(const Volume& volume, const Planar& prim,
                                                        int32_t id, int j0, int j1,
                                                        SurfaceRaster& raster) {
  const int r = volume.resolution;
  const double h = volume.half_depth;
  const float sign = raster.side == Side::B ? 1.0f : -1.0f;
  for (int j = j0; j <= j1; ++j) {
    for (int i = rowLo(prim, raster, j); i <= rowHi(prim, raster, j); ++i) {
      const double x = volume.centreX(i), y = volume.centreX(j);
      if (!insideEdges(prim, x, y)) continue;
      const double z = prim.z.at(x, y);
      raster.depth.note(z, h);
      if (!(std::abs(z) <= h)) continue;
      raster.cover(j, i, i);
      const size_t idx = static_cast<size_t>(j * r + i);
      const float k = sign * static_cast<float>(z);
      if (k > raster.key[idx]) {
        raster.key[idx] = k;
        raster.primitive[idx] = id;
      }
    }
  }
}

// Narrows row j's span [lo, hi] (at y, depth zr + dx x) to the pixels inside the cutting
// constraints: the depth clip and every cutting edge bound x from one side or both, then the
// exact test trims the conservative ends. Notes the row's depth clip decisions.
[[gnu::always_inline]] inline void clipRow(const Volume& volume, const Planar& prim,
                                           const Cuts& cuts, const std::array<EdgeBound, 4>& bounds,
                                           int j, double y, double zr, int& lo, int& hi,
                                           DepthMargins& depth) {
  const double h = volume.half_depth;
  if (cuts.depth && lo <= hi) {
    noteRow(volume, zr, prim.z.dx, h, lo, hi, depth);
    clipSpan(volume, prim.z.dx, -h - zr, h - zr, lo, hi);
  }
  for (int k = 0; k < cuts.edge_count && lo <= hi; ++k) {
    const auto edge = static_cast<size_t>(cuts.edges[static_cast<size_t>(k)]);
    clipEdge(bounds[static_cast<size_t>(k)], prim.edges[edge], y, j, volume.resolution, lo, hi);
  }
  // Trim the conservative ends with the exact test.
  if (cuts.depth || cuts.edge_count > 0) {
    while (lo <= hi && !insideCuts(prim, cuts, h, volume.centreX(lo), y)) ++lo;
    while (lo <= hi && !insideCuts(prim, cuts, h, volume.centreX(hi), y)) --hi;
  }
}

// Inside row j's span lo..hi: keep the fragment nearest the other body.
[[gnu::always_inline]] inline void fillRow(const Volume& volume, const Planar& prim, int32_t id,
                                           int j, double zr, int lo, int hi,
                                           SurfaceRaster& raster) {
  const int r = volume.resolution;
  const float sign = raster.side == Side::B ? 1.0f : -1.0f;
  float* key = raster.key.data() + static_cast<size_t>(j * r);
  int32_t* primitive = raster.primitive.data() + static_cast<size_t>(j * r);
  const double step = prim.z.dx * volume.pixel;
  double z = zr + prim.z.dx * volume.centreX(lo);
  for (int i = lo; i <= hi; ++i, z += step) {
    const float k = sign * static_cast<float>(z);
    if (k > key[i]) {
      key[i] = k;
      primitive[i] = id;
    }
  }
}

[[gnu::always_inline]] inline void rasterisePlanarBody(const Volume& volume, const Planar& prim,
                                                       int32_t id, SurfaceRaster& raster) {
  const int j0 = std::max(prim.j0, raster.wj0), j1 = std::min(prim.j1, raster.wj1);
  // Small primitives: the exact test per pixel is cheaper than setting up the rows.
  if ((prim.i1 - prim.i0 + 1) * (j1 - j0 + 1) <= 9) {
    rasteriseSmallPlanar(volume, prim, id, j0, j1, raster);
    return;
  }
  if (j0 > j1) return;
  // The constraints that cut the pixel box, and each cutting edge's crossing per row.
  const Cuts cuts = cutsWithin(volume, prim, j0, j1);
  if (!cuts.depth) raster.depth.noteRange(cuts.z_least, cuts.z_most, volume.half_depth);
  std::array<EdgeBound, 4> bounds;
  for (int k = 0; k < cuts.edge_count; ++k) {
    const auto edge = static_cast<size_t>(cuts.edges[static_cast<size_t>(k)]);
    bounds[static_cast<size_t>(k)] = edgeBound(volume, prim.edges[edge]);
  }
  // Each row: its span within the constraints, covered and filled.
  for (int j = j0; j <= j1; ++j) {
    const double y = volume.centreX(j);
    int lo = rowLo(prim, raster, j), hi = rowHi(prim, raster, j);
    const double zr = prim.z.c + prim.z.dy * y;
    clipRow(volume, prim, cuts, bounds, j, y, zr, lo, hi, raster.depth);
    if (lo > hi) continue;
    raster.cover(j, lo, hi);
    fillRow(volume, prim, id, j, zr, lo, hi, raster);
  }
}

#if ASPERITY_AVX2_COPIES
// The AVX2 copy (math/simd.hpp): the row set-up's floors and ceilings are one instruction there
// (SSE4.1); the helpers above are always inlined, so they are compiled with AVX2 too.
ASPERITY_TARGET_AVX2 void rasterisePlanarAvx2(const Volume& volume, const Planar& prim, int32_t id,
                                              SurfaceRaster& raster) {
  rasterisePlanarBody(volume, prim, id, raster);
}
#endif

}  // namespace

void rasterisePlanar(const Volume& volume, const Planar& prim, int32_t id, SurfaceRaster& raster) {
#if ASPERITY_AVX2_COPIES
  if (simd::avx2(volume.simd)) return rasterisePlanarAvx2(volume, prim, id, raster);
#endif
  rasterisePlanarBody(volume, prim, id, raster);
}

}  // namespace asperity::patch
