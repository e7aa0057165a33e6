// The planar path's tables and footprint integrals (patch_planar.hpp).
#include "sampler/patch_planar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asperity/error.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "parallel/thread_pool.hpp"
#include "sampler/patch_texture.hpp"

namespace asperity::patch {

namespace {

// Sample points per texel along each axis when a cell's mean is taken (midpoint rule over the
// bilinear patch): 4 x 4 per texel, whatever the cells.
constexpr int kSamplesPerTexel = 4;
// Cells per texel preferred when the budget allows: a boundary cell then counts a quarter of a
// texel with its mean instead of a whole one. At 1, a cell straddling a sawtooth's steep face
// put crawling_worm's contacts up to 58 % from the raster path (9 % at 2).
constexpr int kPreferredSub = 2;
// Tabulated angles at least this many (a multiple of N): an angle step of 11.25 degrees.
constexpr int kMinAngles = 32;

constexpr double kTwoPi = 2.0 * kPi;

int positiveMod(long long x, int m) {
  const long long r = x % m;
  return static_cast<int>(r < 0 ? r + m : r);
}

// The x interval of a convex polygon at height y (lo > hi when the line misses it).
void spanAt(std::span<const Vec2> poly, double y, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  const size_t n = poly.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec2& p = poly[k];
    const Vec2& q = poly[(k + 1) % n];
    if ((y < p.y() && y < q.y()) || (y > p.y() && y > q.y())) continue;
    if (p.y() == q.y()) {
      lo = std::min({lo, p.x(), q.x()});
      hi = std::max({hi, p.x(), q.x()});
      continue;
    }
    const double x = p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y());
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
}

// Sutherland-Hodgman against a x + b y + c >= 0; in and out may not alias.
int clipHalfPlane(const Vec2* in, int count, double a, double b, double c, Vec2* out) {
  int n = 0;
  for (int k = 0; k < count; ++k) {
    const Vec2& p = in[k];
    const Vec2& q = in[(k + 1) % count];
    const double ep = a * p.x() + b * p.y() + c;
    const double eq = a * q.x() + b * q.y() + c;
    if (ep >= 0.0) out[n++] = p;
    if ((ep >= 0.0) != (eq >= 0.0)) out[n++] = p + (ep / (ep - eq)) * (q - p);
  }
  return n;
}

// The half-planes a face keeps: its edges and both planes of the depth clip.
struct HalfPlanes {
  std::array<std::array<double, 3>, 6> plane{};
  int count = 0;
};

HalfPlanes halfPlanesOf(const Volume& volume, const Planar& prim) {
  HalfPlanes h;
  for (int k = 0; k < prim.edge_count; ++k) {
    const Edge& e = prim.edges[static_cast<size_t>(k)];
    h.plane[static_cast<size_t>(h.count++)] = {e.a, e.b, e.c};
  }
  // |z| <= half_depth with z = c + dx x + dy y.
  const Affine& z = prim.z;
  const double d = volume.half_depth;
  h.plane[static_cast<size_t>(h.count++)] = {-z.dx, -z.dy, d - z.c};
  h.plane[static_cast<size_t>(h.count++)] = {z.dx, z.dy, d + z.c};
  return h;
}

// The same test the raster path makes at a pixel centre: the face's edges (top-left rule) and
// the depth clip.
bool keepsCentre(const Volume& volume, const Planar& prim, double x, double y) {
  for (int k = 0; k < prim.edge_count; ++k) {
    if (!prim.edges[static_cast<size_t>(k)].inside(x, y)) return false;
  }
  return std::abs(prim.z.at(x, y)) <= volume.half_depth;
}

struct Polygon {
  std::array<Vec2, 24> v{};
  int count = 0;
};

Polygon patchSquare(const Volume& volume) {
  const double h = 0.5 * volume.width;
  Polygon p;
  p.v[0] = {-h, -h}, p.v[1] = {h, -h}, p.v[2] = {h, h}, p.v[3] = {-h, h};
  p.count = 4;
  return p;
}

void clipBy(Polygon& poly, const HalfPlanes& h) {
  for (int k = 0; k < h.count && poly.count > 0; ++k) {
    Polygon next;
    const auto& pl = h.plane[static_cast<size_t>(k)];
    next.count = clipHalfPlane(poly.v.data(), poly.count, pl[0], pl[1], pl[2], next.v.data());
    poly = next;
  }
}

// Pixel centres of row j inside `poly` and kept by every listed face, counted.
int centresInRow(const Volume& volume, const Polygon& poly, int j,
                 std::span<const Planar* const> faces) {
  const double y = volume.centreX(j);
  double lo = 0.0, hi = 0.0;
  spanAt(std::span<const Vec2>(poly.v.data(), static_cast<size_t>(poly.count)), y, lo, hi);
  if (lo > hi) return 0;
  // Widened by far more than rounding; the exact tests then trim the ends.
  const double slack = 1e-6 * volume.pixel, x0 = volume.centreX(0);
  int i0 = static_cast<int>(std::ceil((lo - slack - x0) / volume.pixel));
  int i1 = static_cast<int>(std::floor((hi + slack - x0) / volume.pixel));
  i0 = std::max(i0, 0), i1 = std::min(i1, volume.resolution - 1);
  auto kept = [&](int i) {
    for (const Planar* f : faces)
      if (!keepsCentre(volume, *f, volume.centreX(i), y)) return false;
    return true;
  };
  while (i0 <= i1 && !kept(i0)) ++i0;
  while (i1 >= i0 && !kept(i1)) --i1;
  return i1 - i0 + 1;
}

int centresIn(const Volume& volume, const Polygon& poly, std::span<const Planar* const> faces) {
  if (poly.count < 3) return 0;
  double ymin = poly.v[0].y(), ymax = ymin;
  for (int k = 1; k < poly.count; ++k) {
    ymin = std::min(ymin, poly.v[static_cast<size_t>(k)].y());
    ymax = std::max(ymax, poly.v[static_cast<size_t>(k)].y());
  }
  int j0 = 0, j1 = -1;
  pixelRange(volume, ymin - 1e-6 * volume.pixel, ymax + 1e-6 * volume.pixel, j0, j1);
  int pixels = 0;
  for (int j = j0; j <= j1; ++j) pixels += centresInRow(volume, poly, j, faces);
  return pixels;
}

}  // namespace

size_t TableLayout::bytes(int width, int height) const {
  const size_t axis = (static_cast<size_t>(height) * static_cast<size_t>(sub) + 1) *
                      (static_cast<size_t>(width) * static_cast<size_t>(sub) + 1);
  const size_t side = 2 * static_cast<size_t>(width) + 1;
  return (axis + (diagonal ? side * side : 0)) * static_cast<size_t>(angles) * sizeof(double);
}

TableLayout tableLayout(int width, int height, int directions) {
  if (width <= 0 || height <= 0 || directions <= 0) return {1, 0};
  // A multiple of N, so that all N directions share one interpolation weight.
  const int angles = directions * std::max(1, (kMinAngles + directions - 1) / directions);
  // Fewer angles only where the budget needs it, as many as fit (a multiple of N).
  for (int n = angles; n >= directions; n -= directions) {
    for (int sub = kPreferredSub; sub >= 1; sub /= 2) {
      TableLayout layout{sub, n, false, directions};
      if (layout.bytes(width, height) > kTableBudgetBytes) continue;
      layout.diagonal = width == height;
      if (layout.bytes(width, height) > kTableBudgetBytes) layout.diagonal = false;
      return layout;
    }
  }
  return {1, 0};
}

CoefficientTables::CoefficientTables(const NormalMap& map, const GainMask* mask, float mu_max,
                                     TableLayout layout, const ThreadPool* pool)
    : cols_(map.width() * layout.sub),
      rows_(map.height() * layout.sub),
      sub_(layout.sub),
      angles_(layout.angles),
      map_width_(map.width()),
      map_height_(map.height()),
      inv_cols_(1.0 / (map.width() * layout.sub)) {
  if (map.empty() || angles_ <= 0 || sub_ <= 0 || kSamplesPerTexel % sub_ != 0) {
    throw Error("planar tables: empty map or bad layout (sub " + std::to_string(sub_) +
                ", angles " + std::to_string(angles_) + ")");
  }
  directions_.resize(static_cast<size_t>(angles_));
  for (int a = 0; a < angles_; ++a) {
    const double t = kTwoPi * a / angles_;
    directions_[static_cast<size_t>(a)] =
        Vec2f(static_cast<float>(std::cos(t)), static_cast<float>(std::sin(t)));
  }
  group_ = layout.group > 0 && angles_ % layout.group == 0 ? layout.group : angles_;
  phases_ = angles_ / group_;
  if (layout.diagonal) diagonal_ = 2 * map.width();
  const size_t axis_values = static_cast<size_t>(rows_ + 1) * static_cast<size_t>(cols_ + 1) *
                             static_cast<size_t>(angles_);
  sat_.assign(axis_values, 0.0);
  diagonal_sat_.assign(layout.bytes(map.width(), map.height()) / sizeof(double) - axis_values, 0.0);
  // Rows are independent: each thread writes its own running sums, in the same order of sums.
  forEachOn(pool, static_cast<size_t>(rows_), 4,
            [&](size_t row) { buildRow(map, mask, mu_max, static_cast<int>(row)); });
  // Then the rows summed down the columns, on this thread: S(x, y) = the integral over
  // [0, x) x [0, y) in cells (double: a 1024^2 table's totals keep 1e-10 of a cell).
  sumColumns(axisGrid(), sat_.data());
  if (diagonal_ == 0) return;
  forEachOn(pool, static_cast<size_t>(diagonal_), 4,
            [&](size_t row) { buildDiagonalRow(map, mask, mu_max, static_cast<int>(row)); });
  sumColumns(diagonalGrid(), diagonal_sat_.data());
}

void CoefficientTables::sumColumns(const Grid& grid, double* sat) const {
  const size_t line = static_cast<size_t>(grid.cols + 1) * static_cast<size_t>(group_);
  for (int phase = 0; phase < phases_; ++phase) {
    double* plane = sat + static_cast<size_t>(phase) * grid.plane;
    for (size_t y = 2; y <= static_cast<size_t>(grid.rows); ++y) {
      double* row = plane + y * line;
      const double* below = row - line;
      for (size_t k = 0; k < line; ++k) row[k] += below[k];
    }
  }
}

void CoefficientTables::storeRow(const Grid& grid, double* sat, int row, int c,
                                 std::span<const double> running) const {
  // Point (c + 1, row + 1) of the grid: each angle in its phase's plane.
  const size_t point = (static_cast<size_t>(row + 1) * static_cast<size_t>(grid.cols + 1) +
                        static_cast<size_t>(c + 1)) *
                       static_cast<size_t>(group_);
  for (size_t a = 0; a < running.size(); ++a)
    sat[point + offsetOf(grid, static_cast<int>(a))] = running[a];
}

void CoefficientTables::addFieldAt(const NormalMap& map, const GainMask* mask, float mu_max,
                                   double tx, double ty, std::span<double> cell) const {
  const int jy = static_cast<int>(std::floor(ty));
  const float wy = static_cast<float>(ty - jy);
  const Vec3f* r0 = &map.at(0, wrapTexel(jy, map_height_));
  const Vec3f* r1 = &map.at(0, wrapTexel(jy + 1, map_height_));
  const int ix = static_cast<int>(std::floor(tx));
  const float wx = static_cast<float>(tx - ix);
  const int i0 = wrapTexel(ix, map_width_), i1 = wrapTexel(ix + 1, map_width_);
  // The blend sampleNormal makes (unnormalised).
  const Vec3f bottom = (1.0f - wx) * r0[i0] + wx * r0[i1];
  const Vec3f top = (1.0f - wx) * r1[i0] + wx * r1[i1];
  const Vec3f normal = (1.0f - wy) * bottom + wy * top;
  float gain = 1.0f;
  if (mask != nullptr) {
    gain = sampleMask(*mask, static_cast<float>((tx + 0.5) / map_width_),
                      static_cast<float>((ty + 0.5) / map_height_));
  }
  const Vec2f g = gain * ploughingVector(normal, Side::B, mu_max);
  for (size_t a = 0; a < cell.size(); ++a) cell[a] += std::max(0.0f, g.dot(directions_[a]));
}

void CoefficientTables::buildDiagonalRow(const NormalMap& map, const GainMask* mask, float mu_max,
                                         int row) {
  // Cell (i, row) covers p in [i, i + 1), q in [row, row + 1) (texels); 2 x 2 points each (as
  // many per texel's area as the axis table at two cells per texel).
  constexpr int q = 2;
  const auto m = static_cast<size_t>(angles_);
  std::vector<double> cell(m), running(m, 0.0);
  const Grid grid = diagonalGrid();
  for (int c = 0; c < diagonal_; ++c) {
    std::fill(cell.begin(), cell.end(), 0.0);
    for (int sy = 0; sy < q; ++sy) {
      const double qq = row + (sy + 0.5) / q;
      for (int sx = 0; sx < q; ++sx) {
        const double p = c + (sx + 0.5) / q;
        addFieldAt(map, mask, mu_max, 0.5 * (p + qq), 0.5 * (p - qq), cell);
      }
    }
    for (size_t a = 0; a < m; ++a) running[a] += cell[a] / (q * q);
    storeRow(grid, diagonal_sat_.data(), row, c, running);
  }
}

void CoefficientTables::buildRow(const NormalMap& map, const GainMask* mask, float mu_max,
                                 int row) {
  const int q = kSamplesPerTexel / sub_;  // samples per cell along each axis
  const auto m = static_cast<size_t>(angles_);
  std::vector<double> cell(m), running(m, 0.0);
  // The row's running sums go to table row row + 1 (row 0 stays 0); the columns are summed
  // after every row is built.
  const Grid grid = axisGrid();
  const double inv_sub = 1.0 / sub_;
  for (int c = 0; c < cols_; ++c) {
    std::fill(cell.begin(), cell.end(), 0.0);
    for (int sy = 0; sy < q; ++sy) {
      // Texel coordinate along v, texel centres at integers (x = v H - 1/2).
      const double ty = (row + (sy + 0.5) / q) * inv_sub;
      const int jy = static_cast<int>(std::floor(ty));
      const float wy = static_cast<float>(ty - jy);
      const Vec3f* r0 = &map.at(0, wrapTexel(jy, map_height_));
      const Vec3f* r1 = &map.at(0, wrapTexel(jy + 1, map_height_));
      for (int sx = 0; sx < q; ++sx) {
        const double tx = (c + (sx + 0.5) / q) * inv_sub;
        const int ix = static_cast<int>(std::floor(tx));
        const float wx = static_cast<float>(tx - ix);
        const int i0 = wrapTexel(ix, map_width_), i1 = wrapTexel(ix + 1, map_width_);
        // The blend sampleNormal makes (unnormalised).
        const Vec3f bottom = (1.0f - wx) * r0[i0] + wx * r0[i1];
        const Vec3f top = (1.0f - wx) * r1[i0] + wx * r1[i1];
        const Vec3f normal = (1.0f - wy) * bottom + wy * top;
        float gain = 1.0f;
        if (mask != nullptr) {
          gain = sampleMask(*mask, static_cast<float>((tx + 0.5) / map_width_),
                            static_cast<float>((ty + 0.5) / map_height_));
        }
        const Vec2f g = gain * ploughingVector(normal, Side::B, mu_max);
        for (size_t a = 0; a < m; ++a) cell[a] += std::max(0.0f, g.dot(directions_[a]));
      }
    }
    for (size_t a = 0; a < m; ++a) running[a] += cell[a] / (q * q);
    storeRow(grid, sat_.data(), row, c, running);
  }
}

Vec2 CoefficientTables::cellOf(double u, double v) const {
  return {(u * map_width_ - 0.5) * sub_, (v * map_height_ - 0.5) * sub_};
}

CoefficientTables::RowPosition CoefficientTables::positionOf(int row, double x) const {
  // Whole repeats of the row, then the cell and the fraction within it.
  const auto m = static_cast<size_t>(group_);
  RowPosition p;
  p.repeats = std::floor(x * inv_cols_);
  const double rem = x - p.repeats * cols_;
  const int c = std::clamp(static_cast<int>(rem), 0, cols_ - 1);
  p.fraction = rem - c;
  const double* base = sat_.data() + static_cast<size_t>(row) * static_cast<size_t>(cols_ + 1) * m;
  p.cell = base + static_cast<size_t>(c) * m;
  p.total = base + static_cast<size_t>(cols_) * m;
  p.line = static_cast<size_t>(cols_ + 1) * m;
  return p;
}

void CoefficientTables::cornerSums(const Grid& grid, double x, double y, std::span<const int> which,
                                   double sign, std::span<double> out) const {
  // x in [0, 2 cols), y in [0, 2 rows) (see integrateRectangle): a coordinate past the table
  // adds the whole table's sums along it (the texture repeats).
  const int cols = grid.cols, rows = grid.rows;
  const auto m = static_cast<size_t>(group_);
  const size_t line = static_cast<size_t>(cols + 1) * m;
  const bool wrap_x = x > cols, wrap_y = y > rows;
  if (wrap_x) x -= cols;
  if (wrap_y) y -= rows;
  // The integral to (x, y) is bilinear within a cell: the cell's four corner sums, blended.
  const int i = std::min(static_cast<int>(x), cols - 1),
            j = std::min(static_cast<int>(y), rows - 1);
  const double fx = x - i, fy = y - j;
  const double w00 = (1.0 - fx) * (1.0 - fy), w10 = fx * (1.0 - fy), w01 = (1.0 - fx) * fy,
               w11 = fx * fy;
  const double* c00 = grid.sat + static_cast<size_t>(j) * line + static_cast<size_t>(i) * m;
  const double* c01 = c00 + line;
  // The whole table along x at height y (column cols), along y at x (row rows), and both.
  const double* tx0 = grid.sat + static_cast<size_t>(j) * line + static_cast<size_t>(cols) * m;
  const double* ty0 = grid.sat + static_cast<size_t>(rows) * line + static_cast<size_t>(i) * m;
  const double* txy = grid.sat + static_cast<size_t>(rows) * line + static_cast<size_t>(cols) * m;
  for (size_t k = 0; k < which.size(); ++k) {
    const size_t a = offsetOf(grid, which[k]);
    double v = w00 * c00[a] + w10 * c00[m + a] + w01 * c01[a] + w11 * c01[m + a];
    if (wrap_x) v += (1.0 - fy) * tx0[a] + fy * tx0[line + a];
    if (wrap_y) v += (1.0 - fx) * ty0[a] + fx * ty0[m + a];
    if (wrap_x && wrap_y) v += txy[a];
    out[k] += sign * v;
  }
}

bool CoefficientTables::integrateRectangle(const Grid& grid, std::span<const Vec2> polygon,
                                           std::span<const int> which, std::span<double> out,
                                           double& area) const {
  // A rectangle aligned with the grid: every vertex within kSnap cells of its bounding box's
  // corners, and the polygon's area within kSnap x perimeter of the box's (three corners of a
  // box make a triangle). The box then differs from the polygon by at most that area: boxes
  // of a resting stack, yawed by up to about 3e-4 rad off square (or off 45 degrees, for the
  // diagonal table) as they settle, still take this path, the mean off by at most 0.04 / side
  // (in cells) of the largest cell value, far less for a field that does not sit on the
  // boundary.
  constexpr double kSnap = 1e-2;
  double x0 = polygon[0].x(), x1 = x0, y0 = polygon[0].y(), y1 = y0;
  for (const Vec2& p : polygon) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  for (const Vec2& p : polygon) {
    const bool on_x = std::abs(p.x() - x0) <= kSnap || std::abs(p.x() - x1) <= kSnap;
    const bool on_y = std::abs(p.y() - y0) <= kSnap || std::abs(p.y() - y1) <= kSnap;
    if (!on_x || !on_y) return false;
  }
  double twice = 0.0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec2& p = polygon[k];
    const Vec2& q = polygon[(k + 1) % polygon.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  const double box = (x1 - x0) * (y1 - y0);
  if (!(box > 0.0) || std::abs(0.5 * std::abs(twice) - box) > 2.0 * kSnap * (x1 - x0 + y1 - y0))
    return false;
  // Shifted by whole repeats so that x0 in [0, cols), y0 in [0, rows); beyond one repeat of
  // extent the strips handle it.
  const double cols = grid.cols, rows = grid.rows;
  if (x1 - x0 > cols || y1 - y0 > rows) return false;
  const double sx = cols * std::floor(x0 / cols), sy = rows * std::floor(y0 / rows);
  x0 = std::clamp(x0 - sx, 0.0, cols), x1 -= sx;
  y0 = std::clamp(y0 - sy, 0.0, rows), y1 -= sy;
  std::fill(out.begin(), out.end(), 0.0);
  cornerSums(grid, x1, y1, which, 1.0, out);
  cornerSums(grid, x0, y1, which, -1.0, out);
  cornerSums(grid, x1, y0, which, -1.0, out);
  cornerSums(grid, x0, y0, which, 1.0, out);
  area = (x1 - x0) * (y1 - y0);
  return true;
}

double CoefficientTables::integrate(std::span<const Vec2> polygon, std::span<const int> which,
                                    std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  if (polygon.size() < 3) return 0.0;
  double rect_area = 0.0;
  if (integrateRectangle(axisGrid(), polygon, which, out, rect_area)) return rect_area;
  if (diagonal_ > 0 && polygon.size() <= 32) {
    // Turned by 45 degrees against the texture: a rectangle in p = tx + ty, q = tx - ty (the
    // mean is the same in either measure: the area returned is in the diagonal cells).
    std::array<Vec2, 32> turned{};
    const double inv_sub = 1.0 / sub_;
    for (size_t k = 0; k < polygon.size(); ++k) {
      const double tx = polygon[k].x() * inv_sub, ty = polygon[k].y() * inv_sub;
      turned[k] = {tx + ty, tx - ty};
    }
    const Grid diagonal = diagonalGrid();
    if (integrateRectangle(diagonal, std::span<const Vec2>(turned.data(), polygon.size()), which,
                           out, rect_area))
      return rect_area;
  }
  double ymin = polygon[0].y(), ymax = ymin, area = 0.0;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec2& p = polygon[k];
    const Vec2& q = polygon[(k + 1) % polygon.size()];
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    area += p.x() * q.y() - q.x() * p.y();
  }
  // Each row of cells the polygon crosses, in strips between the row's bounds and the
  // polygon's vertices: a strip's span ends move linearly, so its middle span is its mean for a
  // uniform density (the running sums are exact along x; along y a row's density is its
  // cells').
  std::array<double, 32> ys{};
  const size_t vertices = std::min(polygon.size(), ys.size());
  for (size_t k = 0; k < vertices; ++k) ys[k] = polygon[k].y();
  std::sort(ys.begin(), ys.begin() + static_cast<long>(vertices));
  // The polygon's sloped edges as x = x0 + (y - y0) slope over [y0, y1]: a strip's middle lies
  // strictly between vertices, where exactly two of them cross it (no division per strip).
  struct Sloped {
    double y0, y1, x0, slope;
  };
  std::array<Sloped, 32> edges{};
  size_t sloped = 0;
  for (size_t k = 0; k < vertices; ++k) {
    Vec2 p = polygon[k], q = polygon[(k + 1) % vertices];
    if (p.y() == q.y()) continue;
    if (p.y() > q.y()) std::swap(p, q);
    edges[sloped++] = {p.y(), q.y(), p.x(), (q.x() - p.x()) / (q.y() - p.y())};
  }
  auto span = [&](double y, double& lo, double& hi) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (size_t k = 0; k < sloped; ++k) {
      const Sloped& e = edges[k];
      if (y < e.y0 || y > e.y1) continue;
      const double x = e.x0 + (y - e.y0) * e.slope;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  };
  // Strips are gathered first and their running sums read after: each strip's rows lie tens
  // of kilobytes apart in the tables, so their reads are prefetched together instead of
  // waiting for memory one strip at a time.
  struct Strip {
    RowPosition a, b;
    double h;
  };
  std::array<Strip, 64> strips;
  size_t gathered = 0;
  const Grid grid = axisGrid();
  std::array<size_t, 4 * kMaxDirections> offsets{};
  const size_t used = std::min(which.size(), offsets.size());
  for (size_t k = 0; k < used; ++k) offsets[k] = offsetOf(grid, which[k]);
  const auto stride = static_cast<size_t>(group_);
  auto flush = [&] {
    for (size_t s = 0; s < gathered; ++s) {
      const Strip& st = strips[s];
      for (size_t k = 0; k < used; ++k)
        out[k] += st.h * (st.b.sumAt(offsets[k], stride) - st.a.sumAt(offsets[k], stride));
    }
    gathered = 0;
  };
  // A point's angles of one phase lie side by side: the phases of the first two angles read.
  const size_t lines = (2 * stride * sizeof(double) + 63) / 64;
  auto prefetch = [&](const RowPosition& p) {
    for (size_t k = 0; k < std::min<size_t>(used, 2); ++k) {
      const double* c = p.cell + (offsets[k] / stride) * stride;
      for (size_t l = 0; l < lines; ++l) {
        __builtin_prefetch(c + 8 * l);
        __builtin_prefetch(c + p.line + 8 * l);
      }
    }
    if (p.repeats != 0.0) __builtin_prefetch(p.total + offsets[0]);
  };
  size_t next = 0;
  const auto first = static_cast<long long>(std::floor(ymin));
  for (long long r = first; static_cast<double>(r) < ymax; ++r) {
    const int row = positiveMod(r, rows_);
    double y0 = std::max(static_cast<double>(r), ymin);
    const double row_end = std::min(static_cast<double>(r + 1), ymax);
    while (y0 < row_end) {
      while (next < vertices && ys[next] <= y0) ++next;
      const double y1 = next < vertices ? std::min(ys[next], row_end) : row_end;
      double lo = 0.0, hi = 0.0;
      span(0.5 * (y0 + y1), lo, hi);
      if (hi > lo) {
        Strip& st = strips[gathered++];
        st = {positionOf(row, lo), positionOf(row, hi), y1 - y0};
        prefetch(st.a);
        prefetch(st.b);
        if (gathered == strips.size()) flush();
      }
      y0 = y1;
    }
  }
  flush();
  return 0.5 * std::abs(area);
}

const CoefficientTables* TableCache::get(const std::shared_ptr<const NormalMap>& map,
                                         const std::shared_ptr<const GainMask>& mask, float mu_max,
                                         int directions, const ThreadPool* pool) {
  const Key key{map.get(), mask.get(), mu_max, directions};
  auto it = entries_.find(key);
  if (it != entries_.end()) return it->second.tables.get();
  Entry entry{nullptr, map, mask};
  const TableLayout layout = tableLayout(map->width(), map->height(), directions);
  if (layout.angles > 0 && !map->empty())
    entry.tables = std::make_unique<CoefficientTables>(*map, mask.get(), mu_max, layout, pool);
  return entries_.emplace(key, std::move(entry)).first->second.tables.get();
}

const CoefficientTables* TableCache::find(const NormalMap* map, const GainMask* mask, float mu_max,
                                          int directions) const {
  auto it = entries_.find(Key{map, mask, mu_max, directions});
  return it == entries_.end() ? nullptr : it->second.tables.get();
}

size_t TableCache::bytes() const {
  size_t total = 0;
  for (const auto& [key, entry] : entries_)
    if (entry.tables) total += entry.tables->bytes();
  return total;
}

bool isFlatFace(const Planar& prim) {
  // The face's normal (frame column N, contact frame) along the patch's normal.
  return !prim.smooth && std::abs(prim.tbn[8].c) >= std::cos(kMaxTilt);
}

bool coversNoCentre(const Volume& volume, const Planar& prim) {
  Polygon poly = patchSquare(volume);
  clipBy(poly, halfPlanesOf(volume, prim));
  const Planar* faces[] = {&prim};
  return centresIn(volume, poly, faces) == 0;
}

void noteDepthDecisions(const Volume& volume, const Planar& prim, DepthMargins& depth) {
  Polygon poly = patchSquare(volume);
  HalfPlanes edges = halfPlanesOf(volume, prim);
  edges.count -= 2;  // the edges alone: the depth clip is what is being decided
  clipBy(poly, edges);
  if (poly.count < 3) return;
  const double h = volume.half_depth;
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  for (int k = 0; k < poly.count; ++k) {
    const Vec2& p = poly.v[static_cast<size_t>(k)];
    const double z = prim.z.at(p.x(), p.y());
    zmin = std::min(zmin, z), zmax = std::max(zmax, z);
  }
  // Within the clip throughout, or beyond one plane throughout: the extremes bound every
  // pixel's margin (z is affine). Cut by the clip: pixels lie on its line, nothing is known.
  const bool inside = zmin >= -h && zmax <= h;
  const bool beyond = zmin > h || zmax < -h;
  if (inside || beyond)
    depth.noteRange(zmin, zmax, h);
  else
    depth.forget();
}

Footprint footprintOf(const Volume& volume, const Planar& a, const Planar& b) {
  Polygon poly = patchSquare(volume);
  clipBy(poly, halfPlanesOf(volume, a));
  clipBy(poly, halfPlanesOf(volume, b));
  Footprint f;
  f.count = std::min(poly.count, static_cast<int>(f.vertex.size()));
  std::copy(poly.v.begin(), poly.v.begin() + f.count, f.vertex.begin());
  const Planar* faces[] = {&a, &b};
  f.pixels = centresIn(volume, poly, faces);
  return f;
}

void planarMeans(const Footprint& footprint, const PlanarSurface& surface, Side side,
                 std::span<const Vec2> directions, std::span<double> mean) {
  std::fill(mean.begin(), mean.end(), 0.0);
  const CoefficientTables* tables = surface.tables;
  if (tables == nullptr || footprint.count < 3) return;
  const Planar& face = *surface.face;
  // The footprint in the map's cells (uv is affine over the face).
  std::array<Vec2, 24> cells{};
  const auto count = static_cast<size_t>(footprint.count);
  for (size_t k = 0; k < count; ++k) {
    const Vec2& p = footprint.vertex[k];
    cells[k] = tables->cellOf(face.u.at(p.x(), p.y()), face.v.at(p.x(), p.y()));
  }
  // Direction d in the map's tangent plane: e = s (T . d, B . d), s = -1 for A (it faces -n:
  // ploughingVector flips its g), T and B the face's frame in the contact plane. Directions
  // evenly spaced turn e by the same step, in the sense of the frame's handedness.
  const double sign = side == Side::A ? -1.0 : 1.0;
  const double tx = face.tbn[0].c, ty = face.tbn[1].c, bx = face.tbn[3].c, by = face.tbn[4].c;
  const int n = static_cast<int>(directions.size()), angles = tables->angles();
  const int step = (tx * by - ty * bx >= 0.0 ? 1 : -1) * (angles / n);
  const Vec2& d0 = directions[0];
  const double ex = sign * (tx * d0.x() + ty * d0.y()), ey = sign * (bx * d0.x() + by * d0.y());
  double f = std::atan2(ey, ex) / kTwoPi * angles;
  f -= angles * std::floor(f / angles);
  int m0 = std::min(static_cast<int>(f), angles - 1);
  double w = f - m0;
  // Weights exact for a * cos + b * sin (every fragment away from the kink of max(0, .)).
  // Within kOnGrid of a step of a tabulated angle, that angle (e off by at most 1e-3 rad for
  // 32 angles, g . e by 1e-3 |g|: boxes yawed by 3e-4 rad against the contact frame read N
  // angles, not 2N).
  constexpr double kOnGrid = 5e-3;
  if (w > 1.0 - kOnGrid) m0 = (m0 + 1) % angles, w = 0.0;
  const bool between = w > kOnGrid;
  const double delta = kTwoPi / angles;
  const double w0 = between ? std::sin((1.0 - w) * delta) / std::sin(delta) : 1.0;
  const double w1 = between ? std::sin(w * delta) / std::sin(delta) : 0.0;
  std::array<int, 2 * kMaxDirections> which{};
  const int per = between ? 2 : 1;
  for (int k = 0; k < n; ++k) {
    const int a =
        positiveMod(static_cast<long long>(m0) + static_cast<long long>(k) * step, angles);
    which[static_cast<size_t>(per * k)] = a;
    if (between) which[static_cast<size_t>(per * k + 1)] = (a + 1) % angles;
  }
  std::array<double, 2 * kMaxDirections> sums{};
  const auto used = static_cast<size_t>(per * n);
  const double area = tables->integrate(std::span<const Vec2>(cells.data(), count),
                                        std::span<const int>(which.data(), used),
                                        std::span<double>(sums.data(), used));
  if (!(area > 0.0)) return;
  for (size_t k = 0; k < static_cast<size_t>(n); ++k) {
    const double s = between ? w0 * sums[2 * k] + w1 * sums[2 * k + 1] : sums[k];
    mean[k] = s / area;
  }
}

}  // namespace asperity::patch
