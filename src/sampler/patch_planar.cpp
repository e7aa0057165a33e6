// The planar path's tables and footprint integrals (patch_planar.hpp).
#include "sampler/patch_planar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <new>
#include <random>
#include <string_view>
#include <type_traits>

#include "asperity/error.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "math/simd.hpp"
#include "parallel/thread_pool.hpp"
#include "sampler/patch_texture.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace asperity::patch {

namespace {

// Sample points per texel along each axis when a cell's mean is taken (midpoint rule over the
// bilinear patch): 4 x 4 per texel, whatever the cells.
constexpr int kSamplesPerTexel = 4;
// Cells per texel preferred where the tables stay within kFineBytes: a boundary cell then
// counts a quarter of a texel with its mean instead of a whole one. At 1, a cell straddling a
// sawtooth's steep face put crawling_worm's contacts (a 64 x 64 map) up to 58 % from the
// raster path (9 % at 2). Larger maps (128 x 128 and up at 16 angles) take one cell per texel:
// their tables (4 MB for 256 x 256) then stay within the caches' reach and each contact reads
// half the rows; stacking, oak_stacks and boxes_on_materials agree as closely at 1.
constexpr int kPreferredSub = 2;
constexpr size_t kFineBytes = size_t{4} << 20;
// Tabulated angles at least this many (a multiple of N): an angle step of 22.5 degrees. The
// interpolation between angles is exact except for fragments within one step of the kink of
// max(0, g . e); the agreement over the experiments' scenes (PlanarAgreement) is the same at 8,
// 16 and 32 angles (within 0.15 % of the mean), and 16 halves the tables of 32.
constexpr int kMinAngles = 16;

constexpr double kTwoPi = 2.0 * kPi;

// A secondary face whose clipped area is below this many pixels counts as covering no centre.
constexpr double kSliverPixels = 1e-3;

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

// Sutherland-Hodgman against a x + b y + c >= 0; in and out may not alias. Each vertex's
// a x + b y + c is taken once.
int clipHalfPlane(const Vec2* in, int count, double a, double b, double c, Vec2* out) {
  int n = 0;
  const double first = a * in[0].x() + b * in[0].y() + c;
  double ep = first;
  for (int k = 0; k < count; ++k) {
    const int next = k + 1 == count ? 0 : k + 1;
    const Vec2& p = in[k];
    const Vec2& q = in[next];
    const double eq = next == 0 ? first : a * q.x() + b * q.y() + c;
    if (ep >= 0.0) out[n++] = p;
    if ((ep >= 0.0) != (eq >= 0.0)) out[n++] = p + (ep / (ep - eq)) * (q - p);
    ep = eq;
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
bool keepsCentre(const Volume& volume, const Planar& prim, double x, double y, bool depth = true) {
  for (int k = 0; k < prim.edge_count; ++k) {
    if (!prim.edges[static_cast<size_t>(k)].inside(x, y)) return false;
  }
  return !depth || std::abs(prim.z.at(x, y)) <= volume.half_depth;
}

struct Polygon {
  std::array<Vec2, 24> v;  // the first count are set
  int count = 0;
};

// A convex polygon (either orientation) as two chains of edges from its lowest vertex to its
// highest, walked upwards: at each height each chain is on one edge, so a row's or a strip's
// span needs no search over the edges and no division per row.
class Chains {
 public:
  Chains(const Vec2* v, int n) : v_(v), n_(n) {
    for (int k = 1; k < n; ++k) {
      if (at(k).y() < at(bottom_).y()) bottom_ = k;
      if (at(k).y() > at(top_).y()) top_ = k;
    }
    left_ = {bottom_, bottom_ + 1 == n ? 0 : bottom_ + 1, 1, 0.0, false};
    right_ = {bottom_, bottom_ == 0 ? n - 1 : bottom_ - 1, -1, 0.0, false};
  }
  double ymin() const { return at(bottom_).y(); }
  double ymax() const { return at(top_).y(); }
  // Both chains onto the edges that reach above y (or the top); y never decreases.
  void advance(double y) {
    advance(left_, y);
    advance(right_, y);
  }
  // Where the first of the two current edges ends: the span is linear in y up to there.
  double nextVertexY() const { return std::min(at(left_.next).y(), at(right_.next).y()); }
  // The polygon's x interval at height y, on the current edges.
  void span(double y, double& lo, double& hi) const {
    lo = xAt(left_, y), hi = xAt(right_, y);
    if (lo > hi) std::swap(lo, hi);
  }
  // A current edge as a line: x at height y is x0 + (y - y0) slope (span's arithmetic).
  struct Line {
    double x0, y0, slope;
    double at(double y) const { return x0 + (y - y0) * slope; }
  };
  Line left() const { return lineOf(left_); }
  Line right() const { return lineOf(right_); }

 private:
  struct Chain {
    int at, next, dir;
    double slope;
    bool set;
  };
  const Vec2& at(int k) const { return v_[static_cast<size_t>(k)]; }
  Line lineOf(const Chain& c) const { return {at(c.at).x(), at(c.at).y(), c.slope}; }
  void advance(Chain& c, double y) const {
    bool moved = false;
    while (c.at != top_ && at(c.next).y() <= y) {
      c.at = c.next;
      c.next = c.next + c.dir;
      c.next = c.next == n_ ? 0 : (c.next < 0 ? n_ - 1 : c.next);
      moved = true;
    }
    if (moved || !c.set) {
      c.set = true;
      const Vec2& p = at(c.at);
      const Vec2& q = at(c.next);
      c.slope = q.y() > p.y() ? (q.x() - p.x()) / (q.y() - p.y()) : 0.0;
    }
  }
  double xAt(const Chain& c, double y) const { return at(c.at).x() + (y - at(c.at).y()) * c.slope; }

  const Vec2* v_;
  int n_, bottom_ = 0, top_ = 0;
  Chain left_{}, right_{};
};

Polygon patchSquare(const Volume& volume) {
  const double h = 0.5 * volume.width;
  Polygon p;
  p.v[0] = {-h, -h}, p.v[1] = {h, -h}, p.v[2] = {h, h}, p.v[3] = {-h, h};
  p.count = 4;
  return p;
}

void clipBy(Polygon& poly, const HalfPlanes& h) {
  // Ping-pong between poly and a scratch polygon; a half-plane that keeps every vertex is
  // skipped.
  Polygon scratch;
  Polygon* in = &poly;
  Polygon* out = &scratch;
  for (int k = 0; k < h.count && in->count > 0; ++k) {
    const auto& pl = h.plane[static_cast<size_t>(k)];
    bool all = true;
    for (int i = 0; i < in->count && all; ++i) {
      const Vec2& p = in->v[static_cast<size_t>(i)];
      all = pl[0] * p.x() + pl[1] * p.y() + pl[2] >= 0.0;
    }
    if (all) continue;
    out->count = clipHalfPlane(in->v.data(), in->count, pl[0], pl[1], pl[2], out->v.data());
    std::swap(in, out);
  }
  if (in != &poly) {
    poly.count = in->count;
    std::copy(in->v.begin(), in->v.begin() + in->count, poly.v.begin());
  }
}

double areaOf(const Polygon& poly) {
  double twice = 0.0;
  for (int k = 0; k < poly.count; ++k) {
    const Vec2& p = poly.v[static_cast<size_t>(k)];
    const Vec2& q = poly.v[static_cast<size_t>((k + 1) % poly.count)];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(twice);
}

// Pixel centres of row j inside `poly` and kept by every listed face, counted.
int centresInRow(const Volume& volume, const Polygon& poly, int j,
                 std::span<const Planar* const> faces, bool depth) {
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
      if (!keepsCentre(volume, *f, volume.centreX(i), y, depth)) return false;
    return true;
  };
  while (i0 <= i1 && !kept(i0)) ++i0;
  while (i1 >= i0 && !kept(i1)) --i1;
  return i1 - i0 + 1;
}

// Without `depth`, the faces' edge tests alone. The count stops once it reaches `enough` (a
// coverage test needs only the first row with a centre).
int centresIn(const Volume& volume, const Polygon& poly, std::span<const Planar* const> faces,
              bool depth = true, int enough = std::numeric_limits<int>::max()) {
  if (poly.count < 3) return 0;
  // Walked upwards row by row (a convex polygon's horizontal edges lie at ymin or ymax, where
  // the rows are counted the exact way).
  Chains chains(poly.v.data(), poly.count);
  const double ymin = chains.ymin(), ymax = chains.ymax();
  int j0 = 0, j1 = -1;
  pixelRange(volume, ymin - 1e-6 * volume.pixel, ymax + 1e-6 * volume.pixel, j0, j1);
  const double inv = 1.0 / volume.pixel, x0 = volume.centreX(0);
  const double tie = 1e-6 * volume.pixel;
  auto kept = [&](int i, double y) {
    for (const Planar* f : faces)
      if (!keepsCentre(volume, *f, volume.centreX(i), y, depth)) return false;
    return true;
  };
  int pixels = 0;
  for (int j = j0; j <= j1; ++j) {
    const double y = volume.centreX(j);
    if (y < ymin - tie || y > ymax + tie) continue;
    if (y - ymin <= tie || ymax - y <= tie) {
      pixels += centresInRow(volume, poly, j, faces, depth);
      continue;
    }
    chains.advance(y);
    double lo = 0.0, hi = 0.0;
    chains.span(y, lo, hi);
    // Centres within `tie` of an end take the faces' exact tests (top-left rule); the others
    // are inside or outside beyond rounding.
    const double a = (lo - x0) * inv, b = (hi - x0) * inv;
    int i0 = static_cast<int>(std::ceil(a - 1e-6)), i1 = static_cast<int>(std::floor(b + 1e-6));
    i0 = std::max(i0, 0), i1 = std::min(i1, volume.resolution - 1);
    if (i0 <= i1 && i0 - a < 1e-6 && !kept(i0, y)) ++i0;
    if (i1 >= i0 && b - i1 < 1e-6 && !kept(i1, y)) --i1;
    pixels += std::max(0, i1 - i0 + 1);
    if (pixels >= enough) break;
  }
  return pixels;
}

bool noCentreIn(const Volume& volume, const Polygon& poly, std::span<const Planar* const> faces,
                bool depth = true) {
  return centresIn(volume, poly, faces, depth, 1) == 0;
}

}  // namespace

void TableMemory::Free::operator()(float* p) const {
  std::free(p);
}

void TableMemory::assign(size_t count) {
  constexpr size_t kPage = size_t{2} << 20;
  const size_t bytes = std::max<size_t>(1, (count * sizeof(float) + kPage - 1) / kPage) * kPage;
  void* p = std::aligned_alloc(kPage, bytes);
  if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(p, bytes, MADV_HUGEPAGE);  // a hint: without it the tables are the same, slower
#endif
  data_.reset(static_cast<float*>(p));
  size_ = count;
}

size_t TableLayout::bytes(int width, int height) const {
  const int cols = width * sub, rows = height * sub;
  const int coarse = CoefficientTables::gradientCoarsening(cols, rows);
  const auto m = static_cast<size_t>(angles);
  const size_t f = static_cast<size_t>(rows) * static_cast<size_t>(cols + 1) * m;
  const size_t gradient_point = (CoefficientTables::kChannels - 1) * m;
  const size_t gradient =
      static_cast<size_t>(rows / coarse) * static_cast<size_t>(cols / coarse + 1) * gradient_point;
  const size_t coarser =
      CoefficientTables::coarserFloats(cols, rows, m) +
      CoefficientTables::coarserFloats(cols / coarse, rows / coarse, gradient_point);
  return (f + gradient + coarser) * sizeof(float);
}

TableLayout tableLayout(int width, int height, int directions) {
  if (width <= 0 || height <= 0 || directions <= 0) return {1, 0};
  // A multiple of N, so that all N directions share one interpolation weight.
  const int angles = directions * std::max(1, (kMinAngles + directions - 1) / directions);
  // Fewer angles only where the budget needs it, as many as fit (a multiple of N).
  for (int n = angles; n >= directions; n -= directions) {
    for (int sub = kPreferredSub; sub >= 1; sub /= 2) {
      const TableLayout layout{sub, n, directions};
      const size_t bytes = layout.bytes(width, height);
      if (bytes <= kTableBudgetBytes && (sub == 1 || bytes <= kFineBytes)) return layout;
    }
  }
  return {1, 0};
}

CoefficientTables::CoefficientTables(const NormalMap& map, const GainMask* mask, float mu_max,
                                     TableLayout layout, const ThreadPool* pool, SimdCopy copy)
    : cols_(map.width() * layout.sub),
      rows_(map.height() * layout.sub),
      sub_(layout.sub),
      angles_(layout.angles),
      map_width_(map.width()),
      map_height_(map.height()),
      copy_(copy) {
  if (map.empty() || angles_ <= 0 || sub_ <= 0 || kSamplesPerTexel % sub_ != 0) {
    throw Error("planar tables: empty map or bad layout (sub " + std::to_string(sub_) +
                ", angles " + std::to_string(angles_) + ")");
  }
  dx_.resize(static_cast<size_t>(angles_));
  dy_.resize(static_cast<size_t>(angles_));
  units_.resize(static_cast<size_t>(angles_));
  for (int a = 0; a < angles_; ++a) {
    const double t = kTwoPi * a / angles_;
    units_[static_cast<size_t>(a)] = Vec2(std::cos(t), std::sin(t));
    dx_[static_cast<size_t>(a)] = static_cast<float>(std::cos(t));
    dy_[static_cast<size_t>(a)] = static_cast<float>(std::sin(t));
  }
  sin_step_ = std::sin(kTwoPi / angles_);
  group_ = layout.group > 0 && angles_ % layout.group == 0 ? layout.group : angles_;
  phases_ = angles_ / group_;
  place_.resize(static_cast<size_t>(angles_));
  for (int a = 0; a < angles_; ++a)
    place_[static_cast<size_t>(a)] = static_cast<size_t>((a % phases_) * group_ + a / phases_);
  // f's sums, and apart the gradient's on cells `coarse` times larger (x and y side by side per
  // point): a flat face reads only the first, as dense as it was without the gradient.
  const auto m = static_cast<size_t>(angles_);
  coarse_ = gradientCoarsening(cols_, rows_);
  gradient_grid_ = {nullptr, (kChannels - 1) * m, cols_ / coarse_, rows_ / coarse_};
  sums_.assign(static_cast<size_t>(rows_) * static_cast<size_t>(cols_ + 1) * m);
  gradient_.assign(static_cast<size_t>(gradient_grid_.rows) *
                   static_cast<size_t>(gradient_grid_.cols + 1) * gradient_grid_.per_point);
  f_grid_ = {sums_.data(), m, cols_, rows_};
  gradient_grid_.table = gradient_.data();
  f_levels_ = {f_grid_};
  gradient_levels_ = {gradient_grid_};
  // Rows of gradient cells are independent: each thread writes its own running sums (and
  // those of f's rows within), in the same order of sums.
  std::vector<double> row_errors(static_cast<size_t>(rows_) * m, 0.0);  // per row and angle
  forEachOn(pool, static_cast<size_t>(gradient_grid_.rows), 2, [&](size_t row) {
    buildRows(map, mask, mu_max, copy, static_cast<int>(row), row_errors.data());
  });
  // The mean over the map, rows added in order (the same bits for any thread count); the
  // largest over the angles.
  std::vector<double> error(m, 0.0);
  for (size_t row = 0; row < static_cast<size_t>(rows_); ++row)
    for (size_t a = 0; a < m; ++a) error[a] += row_errors[row * m + a];
  const double samples =
      static_cast<double>(rows_) * cols_ * (kSamplesPerTexel / sub_) * (kSamplesPerTexel / sub_);
  tilt_error_ = *std::max_element(error.begin(), error.end()) / samples;
  // Coarser levels while a footprint's mean on them stays within kMaxLevelError of the finest
  // level's (the gradient's times the largest tilt it is multiplied by).
  std::vector<std::vector<float>> made;
  addCoarserLevels(f_levels_, 1, kMaxStripRows, 1.0, made);
  addCoarserLevels(gradient_levels_, coarse_, kMaxGradientRows, std::tan(kMaxTilt), made);
  // Into one block (the levels from 1 of f, then of the gradient, as made).
  size_t floats = 0;
  for (const auto& level : made) floats += level.size();
  coarser_.assign(floats);
  float* at = coarser_.data();
  auto it = made.begin();
  for (auto* levels : {&f_levels_, &gradient_levels_}) {
    for (size_t k = 1; k < levels->size(); ++k, ++it) {
      (*levels)[k].table = std::copy(it->begin(), it->end(), at) - it->size();
      at += it->size();
    }
  }
}

namespace {

// Whether a table of cols x rows cells has a coarser level (see coarserFloats).
bool halves(int cols, int rows, int level) {
  return level + 1 < CoefficientTables::kMaxLevels && cols % 2 == 0 && rows % 2 == 0 &&
         cols / 2 >= 4 && rows / 2 >= 4;
}

}  // namespace

size_t CoefficientTables::coarserFloats(int cols, int rows, size_t per_point) {
  size_t floats = 0;
  for (int level = 0; halves(cols, rows, level); ++level) {
    cols /= 2, rows /= 2;
    floats += static_cast<size_t>(rows) * static_cast<size_t>(cols + 1) * per_point;
  }
  return floats;
}

void CoefficientTables::addCoarserLevels(std::vector<Grid>& levels, int scale, int max_rows,
                                         double weight,
                                         std::vector<std::vector<float>>& made) const {
  // A coarse cell's mean is the mean of its 2 x 2 fine cells, so a coarse row's running sum
  // to point X is the mean of the two fine rows' sums to point 2 X (in coarse cells: a
  // quarter of their sum).
  while (halves(levels.back().cols, levels.back().rows, static_cast<int>(levels.size()) - 1)) {
    const Grid fine = levels.back();
    const size_t m = fine.per_point;
    const size_t fine_line = static_cast<size_t>(fine.cols + 1) * m;
    const size_t coarse_line = static_cast<size_t>(fine.cols / 2 + 1) * m;
    std::vector<float> sums(static_cast<size_t>(fine.rows / 2) * coarse_line);
    const Grid coarse{sums.data(), m, fine.cols / 2, fine.rows / 2};
    for (size_t r = 0; r < static_cast<size_t>(coarse.rows); ++r) {
      const float* a = fine.table + 2 * r * fine_line;
      const float* b = a + fine_line;
      float* out = sums.data() + r * coarse_line;
      for (size_t x = 0; x <= static_cast<size_t>(coarse.cols); ++x)
        for (size_t k = 0; k < m; ++k)
          out[x * m + k] = 0.25f * (a[2 * x * m + k] + b[2 * x * m + k]);
    }
    const int level = static_cast<int>(levels.size());
    if (weight * levelError(levels.front(), coarse, scale, level, max_rows) > kMaxLevelError)
      return;
    levels.push_back(coarse);
    made.push_back(std::move(sums));  // the vector's data does not move
  }
}

double CoefficientTables::levelError(const Grid& finest, const Grid& coarse, int scale, int level,
                                     int max_rows) const {
  // Squares turned at random, as small as footprints that take this level (about max_rows / 2
  // of its rows tall), anywhere on the map: the largest difference from the finest
  // level's mean at any angle. Random textures' boundary cells err each its own way; a
  // sawtooth's teeth err alike along a side (crawling_worm's skin: a 16-texel sawtooth, whose
  // contacts strayed up to 58 % from the raster path on cells of one texel).
  std::mt19937_64 random(12345);
  auto uniform = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
  const double side = 0.5 * max_rows * (scale << level) / std::sqrt(2.0);
  const Range all{0, static_cast<int>(finest.per_point)};
  std::vector<float> fine_sums(finest.per_point), coarse_sums(finest.per_point);
  double worst = 0.0;
  for (int k = 0; k < kLevelChecks; ++k) {
    const Vec2 centre(uniform() * cols_, uniform() * rows_);
    const double turn = uniform() * kTwoPi;
    const Vec2 along(std::cos(turn), std::sin(turn)), across(-along.y(), along.x());
    std::array<Vec2, 4> square;
    for (size_t c = 0; c < 4; ++c) {
      const double a = (c == 1 || c == 2) ? 0.5 : -0.5, b = c >= 2 ? 0.5 : -0.5;
      square[c] = centre + side * (a * along + b * across);
    }
    const double area =
        accumulateScaled(finest, scale, square, std::span<const Range>(&all, 1), fine_sums.data());
    accumulateScaled(coarse, scale << level, square, std::span<const Range>(&all, 1),
                     coarse_sums.data());
    for (size_t a = 0; a < finest.per_point; ++a)
      worst = std::max(worst, std::abs(static_cast<double>(coarse_sums[a] - fine_sums[a])) / area);
  }
  return worst;
}

int CoefficientTables::levelFor(double height, const std::vector<Grid>& levels, int scale,
                                int max_rows) {
  int level = 0;
  double rows = height / scale;
  while (rows > max_rows && level + 1 < static_cast<int>(levels.size())) {
    rows *= 0.5;
    ++level;
  }
  return level;
}

namespace {

// How a fragment's coefficient max(0, f) changes as its face tilts (see CoefficientTables): at
// tilt 0, where f > 0, the gradient of f in tau is -k (e + s (r . e) r). Unclamped (|g| below
// mu_max) f = (2 / pi) (p . e - tau . e) / (1 + p . tau) with p the slope m_xy / m_z, so k =
// 2 / pi, s = 1, r = p. Clamped f = mu_max (m . d) / |m_tb|, with m . d = q . e - m_z tau . e
// and |m_tb| = |q| - m_z (q . tau) / |q| to first order (q = m_xy): k = mu_max m_z / |q|, s = -1,
// r = q / |q|. Both times the gain.
struct TiltGradient {
  float k = 0.0f, s = 0.0f, rx = 0.0f, ry = 0.0f;
};

TiltGradient tiltGradientOf(const Vec3f& m, float gain, float mu_max) {
  constexpr float kTwoOverPi = static_cast<float>(2.0 / kPi);
  const float radius = std::hypot(m.x(), m.y());
  // The branch ploughingVector takes.
  if (m.z() > 0.0f && kTwoOverPi * radius <= mu_max * m.z()) {
    return {gain * kTwoOverPi, 1.0f, m.x() / m.z(), m.y() / m.z()};
  }
  if (!(radius > 0.0f)) return {};
  return {gain * mu_max * m.z() / radius, -1.0f, m.x() / radius, m.y() / radius};
}

// One sample added to a cell's sums at each of m angles (e = (dx, dy)): f = max(0, g . e), its
// gradient in the tilt where f > 0 (TiltGradient), and the first order's error bound at the
// largest tilt tan_max, channel after channel in `cell` (4 m floats).
[[gnu::always_inline]] inline void addSampleBody(float gx, float gy, const TiltGradient& t,
                                                 float tan_max, const float* __restrict dx,
                                                 const float* __restrict dy, size_t m,
                                                 float* __restrict cell) {
  float* __restrict cf = cell;
  float* __restrict cx = cell + m;
  float* __restrict cy = cell + 2 * m;
  float* __restrict ce = cell + 3 * m;
  const float k = t.k, rx = t.rx, ry = t.ry, srx = t.s * t.rx, sry = t.s * t.ry;
  for (size_t a = 0; a < m; ++a) {
    const float f = gx * dx[a] + gy * dy[a];
    const float along = rx * dx[a] + ry * dy[a];
    const float ux = -k * (dx[a] + along * srx), uy = -k * (dy[a] + along * sry);
    // 1 where f > 0, else 0 (f = 0 too: the tiny shift), without a comparison beside max(0,
    // f): GCC 12 vectorises this loop only so.
    const float on = 0.5f + std::copysign(0.5f, f - 1e-30f);
    cf[a] += std::max(0.0f, f);
    cx[a] += on * ux;
    cy[a] += on * uy;
    // First order errs only where the largest tilt can carry f across 0.
    ce[a] += std::max(0.0f, std::sqrt(ux * ux + uy * uy) * tan_max - std::abs(f));
  }
}

#if ASPERITY_AVX2_COPIES
// The AVX2 copy (math/simd.hpp): eight angles per register, the same bits.
ASPERITY_TARGET_AVX2 void addSampleAvx2(float gx, float gy, const TiltGradient& t, float tan_max,
                                        const float* dx, const float* dy, size_t m, float* cell) {
  addSampleBody(gx, gy, t, tan_max, dx, dy, m, cell);
}
#endif

void addSample(bool avx2, float gx, float gy, const TiltGradient& t, float tan_max, const float* dx,
               const float* dy, size_t m, float* cell) {
#if ASPERITY_AVX2_COPIES
  if (avx2) return addSampleAvx2(gx, gy, t, tan_max, dx, dy, m, cell);
#endif
  (void)avx2;
  addSampleBody(gx, gy, t, tan_max, dx, dy, m, cell);
}

}  // namespace

int CoefficientTables::gradientCoarsening(int cols, int rows) {
  return cols % kGradientCoarsening == 0 && rows % kGradientCoarsening == 0 ? kGradientCoarsening
                                                                            : 1;
}

void CoefficientTables::buildRows(const NormalMap& map, const GainMask* mask, float mu_max,
                                  SimdCopy copy, int gradient_row, double* row_errors) {
  const int q = kSamplesPerTexel / sub_;  // samples per cell along each axis
  const auto m = static_cast<size_t>(angles_);
  // A cell's sums in float (at most q x q = 16 samples) over the angles' two arrays: the loops
  // over angles vectorise, where they dominate the build. Channel by channel: f, its
  // gradient's x and y (kChannels), and the first order's error bound at kMaxTilt (tiltError).
  std::vector<float> cell((kChannels + 1) * m);
  const float* ce = cell.data() + kChannels * m;
  // The gradient cells of this row: the sums of their fine cells' means.
  const auto gradient_cols = static_cast<size_t>(gradient_grid_.cols);
  std::vector<double> gradient_cells(gradient_cols * 2 * m, 0.0);
  const auto tan_max = static_cast<float>(std::tan(kMaxTilt));
  const bool avx2 = simd::avx2(copy);
  const float* dx = dx_.data();
  const float* dy = dy_.data();
  const double inv_sub = 1.0 / sub_;
  const double per_sample = 1.0 / (q * q);
  std::vector<double> running(2 * m);
  for (int row = gradient_row * coarse_; row < (gradient_row + 1) * coarse_; ++row) {
    double* row_error = row_errors + static_cast<size_t>(row) * m;
    std::fill(running.begin(), running.begin() + static_cast<long>(m), 0.0);
    // Point x of the row holds the sums over cells [0, x).
    float* line = sums_.data() + static_cast<size_t>(row) * static_cast<size_t>(cols_ + 1) * m;
    std::fill(line, line + m, 0.0f);
    for (int c = 0; c < cols_; ++c) {
      std::fill(cell.begin(), cell.end(), 0.0f);
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
          addSample(avx2, g.x(), g.y(), tiltGradientOf(normal, gain, mu_max), tan_max, dx, dy, m,
                    cell.data());
        }
      }
      float* point = line + static_cast<size_t>(c + 1) * m;
      double* gradient_cell = gradient_cells.data() + static_cast<size_t>(c / coarse_) * 2 * m;
      for (size_t a = 0; a < m; ++a) {
        running[a] += static_cast<double>(cell[a]) * per_sample;
        point[place_[a]] = static_cast<float>(running[a]);
        row_error[a] += ce[a];
      }
      for (size_t k = 0; k < 2 * m; ++k) gradient_cell[k] += cell[m + k] * per_sample;
    }
  }
  // The gradient's running sums of its cells' means (each the mean of coarse x coarse cells).
  const double per_cell = 1.0 / (coarse_ * coarse_);
  std::fill(running.begin(), running.end(), 0.0);
  float* line = gradient_.data() + static_cast<size_t>(gradient_row) * (gradient_cols + 1) * 2 * m;
  std::fill(line, line + 2 * m, 0.0f);
  for (size_t c = 0; c < gradient_cols; ++c) {
    float* point = line + (c + 1) * 2 * m;
    for (size_t k = 0; k < 2 * m; ++k) {
      running[k] += gradient_cells[c * 2 * m + k] * per_cell;
      // x values, then y values, each at its angle's place.
      point[(k / m) * m + place_[k % m]] = static_cast<float>(running[k]);
    }
  }
}

Vec2 CoefficientTables::cellOf(double u, double v) const {
  return {(u * map_width_ - 0.5) * sub_, (v * map_height_ - 0.5) * sub_};
}

namespace {

// A span's end in a row of running sums: the sums at the cell's start (the next point holds
// those at its end), the fraction of the cell, and the row's whole repeats before it.
struct SpanEnd {
  const float* cell;
  float fraction, repeats;
};
struct Strip {
  SpanEnd a, b;
  const float* total;  // the row's sums over one repeat
  float h;
};

// The whole repeats a strip spans (a span past the row's end): h times their number times
// the row's sums over one repeat.
inline float repeatWeight(const Strip& st) {
  return st.h * (st.b.repeats - st.a.repeats);
}

// The strips' h (R(b) - R(a)) over W values from `begin` of each point, added to out; with
// `repeats`, then each strip's whole repeats (repeatWeight), strip after strip.
template <int W>
[[gnu::always_inline]] inline void addStrips(const Strip* strips, size_t count, size_t stride,
                                             int begin, bool repeats, float* out) {
  float acc[W] = {};
  for (size_t s = 0; s < count; ++s) {
    const Strip& st = strips[s];
    const float* __restrict a0 = st.a.cell + begin;
    const float* __restrict b0 = st.b.cell + begin;
    const float fa = st.a.fraction, fb = st.b.fraction, h = st.h;
    for (int k = 0; k < W; ++k) {
      const float va = a0[k] + fa * (a0[stride + static_cast<size_t>(k)] - a0[k]);
      const float vb = b0[k] + fb * (b0[stride + static_cast<size_t>(k)] - b0[k]);
      acc[k] += h * (vb - va);
    }
  }
  for (int k = 0; k < W; ++k) acc[k] += out[k];
  for (size_t s = 0; s < count && repeats; ++s) {
    const float weight = repeatWeight(strips[s]);
    if (weight == 0.0f) continue;
    const float* __restrict total = strips[s].total + begin;
    for (int k = 0; k < W; ++k) acc[k] += weight * total[k];
  }
  for (int k = 0; k < W; ++k) out[k] = acc[k];
}

// addStrips<W> for the widths a contact reads (N or 2N floats); false for any other.
[[gnu::always_inline]] inline bool addStripsOfWidth(const Strip* strips, size_t count,
                                                    size_t stride, int begin, int len, bool repeats,
                                                    float* out) {
  switch (len) {
    case 4:
      addStrips<4>(strips, count, stride, begin, repeats, out);
      return true;
    case 8:
      addStrips<8>(strips, count, stride, begin, repeats, out);
      return true;
    case 16:
      addStrips<16>(strips, count, stride, begin, repeats, out);
      return true;
    case 32:
      addStrips<32>(strips, count, stride, begin, repeats, out);
      return true;
    default:
      return false;
  }
}

#if ASPERITY_AVX2_COPIES
// The AVX2 copy: eight floats an operation, and no FMA, so the same bits as the baseline's.
ASPERITY_TARGET_AVX2 bool addStripsAvx2(const Strip* strips, size_t count, size_t stride, int begin,
                                        int len, bool repeats, float* out) {
  return addStripsOfWidth(strips, count, stride, begin, len, repeats, out);
}
#endif

void addStrips(bool avx2, const Strip* strips, size_t count, size_t stride, int begin, int len,
               bool repeats, float* out) {
#if ASPERITY_AVX2_COPIES
  if (avx2 && addStripsAvx2(strips, count, stride, begin, len, repeats, out)) return;
#else
  (void)avx2;
#endif
  if (addStripsOfWidth(strips, count, stride, begin, len, repeats, out)) return;
  for (size_t s = 0; s < count; ++s) {
    const Strip& st = strips[s];
    const float* a0 = st.a.cell + begin;
    const float* b0 = st.b.cell + begin;
    for (int k = 0; k < len; ++k) {
      const float va = a0[k] + st.a.fraction * (a0[stride + static_cast<size_t>(k)] - a0[k]);
      const float vb = b0[k] + st.b.fraction * (b0[stride + static_cast<size_t>(k)] - b0[k]);
      out[k] += st.h * (vb - va);
    }
  }
  for (size_t s = 0; s < count && repeats; ++s) {
    const float weight = repeatWeight(strips[s]);
    if (weight == 0.0f) continue;
    for (int k = 0; k < len; ++k) out[k] += weight * strips[s].total[begin + k];
  }
}

}  // namespace

double CoefficientTables::accumulate(const Grid& grid, std::span<const Vec2> polygon,
                                     std::span<const Range> ranges, float* out) const {
  const int cols = grid.cols, rows = grid.rows;
  const double inv_cols = 1.0 / cols;
  const size_t vertices = std::min<size_t>(polygon.size(), 32);
  size_t width = 0;
  for (const Range& r : ranges) width += static_cast<size_t>(r.len);
  std::fill(out, out + width, 0.0f);
  if (vertices < 3) return 0.0;
  // Shifted by whole repeats so that the polygon starts in the table's first repeat.
  double xmin = polygon[0].x(), ymin = polygon[0].y();
  for (size_t k = 1; k < vertices; ++k)
    xmin = std::min(xmin, polygon[k].x()), ymin = std::min(ymin, polygon[k].y());
  const Vec2 shift(cols * std::floor(xmin * inv_cols), rows * std::floor(ymin / rows));
  // A strip's middle lies strictly between vertices, on one edge of each chain.
  const auto n = static_cast<int>(vertices);
  std::array<Vec2, 32> v;
  double area = 0.0;
  for (int k = 0; k < n; ++k) v[static_cast<size_t>(k)] = polygon[static_cast<size_t>(k)] - shift;
  for (int k = 0; k < n; ++k) {
    const Vec2& p = v[static_cast<size_t>(k)];
    const Vec2& q = v[static_cast<size_t>(k + 1 == n ? 0 : k + 1)];
    area += p.x() * q.y() - q.x() * p.y();
  }
  Chains chains(v.data(), n);
  ymin = chains.ymin();
  const double ymax = chains.ymax();
  const size_t m = grid.per_point;
  const size_t line = static_cast<size_t>(cols + 1) * m;
  auto endOf = [&](const float* row, double x) {
    // x < 2 cols nearly always (footprints far smaller than a repeat); any x is handled.
    const double repeats = x < cols ? 0.0 : std::floor(x * inv_cols);
    const double rem = x - repeats * cols;
    const int c = std::clamp(static_cast<int>(rem), 0, cols - 1);
    return SpanEnd{row + static_cast<size_t>(c) * m, static_cast<float>(rem - c),
                   static_cast<float>(repeats)};
  };
  // The same where x lies in [0, cols - 1) give or take rounding (the polygon within one
  // repeat, as nearly all are): the same bits, without the repeats' tests.
  auto endWithin = [m](const float* row, double x) {
    const int c = static_cast<int>(x);
    return SpanEnd{row + static_cast<size_t>(c) * m, static_cast<float>(x - c), 0.0f};
  };
  // Strips are gathered first and their sums read after, range by range, W floats at a time
  // in registers (addStrips).
  std::array<Strip, 64> strips;
  size_t gathered = 0;
  const bool avx2 = simd::avx2(copy_);
  bool repeats = false;
  auto flush = [&] {
    float* o = out;
    for (const Range& r : ranges) {
      addStrips(avx2, strips.data(), gathered, m, r.begin, r.len, repeats, o);
      o += r.len;
    }
    gathered = 0;
    repeats = false;
  };
  // Band by band (between the heights of two vertices both chains are on one edge each), and
  // within a band row by row of cells: a strip is a row's part of a band, in increasing height
  // (so the sums add in the same order as row by row).
  double xmax = 0.0;
  for (int k = 0; k < n; ++k) xmax = std::max(xmax, v[static_cast<size_t>(k)].x());
  auto gather = [&](auto within) {
    const auto end = [&](const float* row, double x) {
      if constexpr (decltype(within)::value) {
        return endWithin(row, x);
      } else {
        return endOf(row, x);
      }
    };
    double y = ymin;
    while (y < ymax) {
      chains.advance(y);
      const double top = chains.nextVertexY();
      if (!(top > y)) break;  // at the top
      const Chains::Line left = chains.left(), right = chains.right();
      auto r = static_cast<long long>(std::floor(y));
      int row_index = positiveMod(r, rows);
      for (; static_cast<double>(r) < top; ++r) {
        const float* row = grid.table + static_cast<size_t>(row_index) * line;
        row_index = row_index + 1 == rows ? 0 : row_index + 1;
        const double y0 = std::max(static_cast<double>(r), y);
        const double y1 = std::min(static_cast<double>(r + 1), top);
        const double mid = 0.5 * (y0 + y1);
        double lo = left.at(mid), hi = right.at(mid);
        if (lo > hi) std::swap(lo, hi);
        if (!(hi > lo)) continue;
        Strip& st = strips[gathered++];
        st = {end(row, lo), end(row, hi), row + static_cast<size_t>(cols) * m,
              static_cast<float>(y1 - y0)};
        if constexpr (!decltype(within)::value) {
          repeats = repeats || st.b.repeats != st.a.repeats;
        }
        if (gathered == strips.size()) flush();
      }
      y = top;
    }
  };
  if (xmax < cols - 1)
    gather(std::true_type{});
  else
    gather(std::false_type{});
  flush();
  return 0.5 * std::abs(area);
}

double CoefficientTables::accumulateScaled(const Grid& grid, int scale,
                                           std::span<const Vec2> polygon,
                                           std::span<const Range> ranges, float* out) const {
  if (scale == 1) return accumulate(grid, polygon, ranges, out);
  // The polygon on the grid's cells; each of them counts scale^2 of f's.
  std::array<Vec2, 32> on_cells;
  const size_t n = std::min(polygon.size(), on_cells.size());
  const double inv = 1.0 / scale;  // a power of two: exact
  for (size_t k = 0; k < n; ++k) on_cells[k] = polygon[k] * inv;
  const double area = accumulate(grid, std::span<const Vec2>(on_cells.data(), n), ranges, out);
  size_t width = 0;
  for (const Range& r : ranges) width += static_cast<size_t>(r.len);
  const auto cells = static_cast<float>(scale * scale);
  for (size_t k = 0; k < width; ++k) out[k] *= cells;
  return area * scale * scale;
}

double CoefficientTables::integrateGroups(std::span<const Vec2> polygon, int phase, int count,
                                          bool gradient, float* out) const {
  const int first = phase % phases_;
  const int second = (first + 1) % phases_;
  std::array<Range, 4> ranges{};
  size_t used = 1;
  if (count < 2) {
    ranges[0] = {first * group_, group_};
  } else if (second == first + 1) {
    ranges[0] = {first * group_, 2 * group_};  // side by side: one range
  } else {
    ranges[0] = {first * group_, group_};
    ranges[1] = {second * group_, group_};
    used = 2;
  }
  // A tall footprint on a coarser level (kMaxStripRows, kMaxGradientRows).
  double ymin = polygon.empty() ? 0.0 : polygon[0].y(), ymax = ymin;
  for (const Vec2& p : polygon) ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  const int level = levelFor(ymax - ymin, f_levels_, 1, kMaxStripRows);
  const double area = accumulateScaled(f_levels_[static_cast<size_t>(level)], 1 << level, polygon,
                                       std::span<const Range>(ranges.data(), used), out);
  if (gradient) {
    // The same places in the gradient's x values and then in its y values.
    size_t width = 0;
    for (size_t r = 0; r < used; ++r) {
      width += static_cast<size_t>(ranges[r].len);
      ranges[used + r] = {ranges[r].begin + angles_, ranges[r].len};
    }
    const int g = levelFor(ymax - ymin, gradient_levels_, coarse_, kMaxGradientRows);
    accumulateScaled(gradient_levels_[static_cast<size_t>(g)], coarse_ << g, polygon,
                     std::span<const Range>(ranges.data(), 2 * used), out + width);
  }
  return area;
}

double CoefficientTables::integrate(std::span<const Vec2> polygon, std::span<const int> which,
                                    std::span<double> out, int channel) const {
  std::fill(out.begin(), out.end(), 0.0);
  std::vector<float> all(static_cast<size_t>(angles_));
  double area = 0.0;
  if (channel == 0) {
    const Range range{0, angles_};
    area = accumulate(f_grid_, polygon, std::span<const Range>(&range, 1), all.data());
  } else {
    const Range range{(channel - 1) * angles_, angles_};
    area = accumulateScaled(gradient_grid_, coarse_, polygon, std::span<const Range>(&range, 1),
                            all.data());
  }
  for (size_t k = 0; k < which.size(); ++k) {
    const int a = which[k];
    out[k] = all[place_[static_cast<size_t>(a)]];
  }
  return area;
}

namespace {

// Every map's tables this process has built, by content: worlds made one after another (a
// sweep's runs, the tribometer's drags, a batch's worlds, a script's scenes) each load their
// textures anew, and would otherwise build the same tables again. An entry is kept while a
// sampler uses it and, beyond that, while the unused ones (tables, maps and masks) stay within
// kKeptBytes (the least recently used go first).
class SharedTables {
 public:
  static SharedTables& instance() {
    static SharedTables shared;
    return shared;
  }

  // Null when the layout does not fit the budget (nothing is kept then). Builds under the
  // lock: worlds that need the same texture at once wait for one build (a build runs only its
  // own pool's threads).
  std::shared_ptr<const CoefficientTables> get(const std::shared_ptr<const NormalMap>& map,
                                               const std::shared_ptr<const GainMask>& mask,
                                               float mu_max, int directions,
                                               const ThreadPool* pool) {
    const TableLayout layout = tableLayout(map->width(), map->height(), directions);
    if (layout.angles <= 0 || map->empty()) return nullptr;
    const size_t hash = contentHash(*map, mask.get(), mu_max, directions);
    std::lock_guard lock(mutex_);
    ++clock_;
    for (Entry& e : entries_) {
      if (e.hash == hash && e.mu_max == mu_max && e.directions == directions &&
          sameMap(*e.map, *map) && sameMask(e.mask.get(), mask.get())) {
        e.last_use = clock_;
        return e.tables;
      }
    }
    auto tables = std::make_shared<CoefficientTables>(*map, mask.get(), mu_max, layout, pool);
    Entry entry{hash, map, mask, mu_max, directions, std::move(tables), clock_};
    entries_.push_back(entry);
    forgetUnused();
    return entry.tables;
  }

 private:
  static constexpr size_t kKeptBytes = size_t{128} << 20;

  struct Entry {
    size_t hash = 0;
    std::shared_ptr<const NormalMap> map;  // compared texel for texel when the hashes match
    std::shared_ptr<const GainMask> mask;
    float mu_max = 0.0f;
    int directions = 0;
    std::shared_ptr<const CoefficientTables> tables;
    uint64_t last_use = 0;
    // What an unused entry keeps: its tables and the map and mask they are compared with.
    size_t bytes() const {
      return tables->bytes() + map->texels().size() * sizeof(Vec3f) +
             (mask ? mask->values.size() * sizeof(float) : 0);
    }
  };

  static std::string_view bytesOf(const void* data, size_t size) {
    return {static_cast<const char*>(data), size};
  }
  static size_t contentHash(const NormalMap& map, const GainMask* mask, float mu_max,
                            int directions) {
    size_t h = std::hash<std::string_view>{}(
        bytesOf(map.texels().data(), map.texels().size() * sizeof(Vec3f)));
    if (mask != nullptr)
      h ^= std::hash<std::string_view>{}(
               bytesOf(mask->values.data(), mask->values.size() * sizeof(float))) *
           31;
    return h ^ (std::hash<float>{}(mu_max)*7) ^ (static_cast<size_t>(directions) << 1);
  }
  static bool sameMap(const NormalMap& a, const NormalMap& b) {
    return &a == &b || (a.width() == b.width() && a.height() == b.height() &&
                        std::memcmp(a.texels().data(), b.texels().data(),
                                    a.texels().size() * sizeof(Vec3f)) == 0);
  }
  static bool sameMask(const GainMask* a, const GainMask* b) {
    if (a == b) return true;
    return a != nullptr && b != nullptr && a->width == b->width && a->height == b->height &&
           std::memcmp(a->values.data(), b->values.data(), a->values.size() * sizeof(float)) == 0;
  }

  // Drops the least recently used entries no sampler holds while those exceed kKeptBytes.
  void forgetUnused() {
    for (;;) {
      size_t unused_bytes = 0;
      auto oldest = entries_.end();
      for (auto it = entries_.begin(); it != entries_.end(); ++it) {
        if (it->tables.use_count() > 1) continue;
        unused_bytes += it->bytes();
        if (oldest == entries_.end() || it->last_use < oldest->last_use) oldest = it;
      }
      if (unused_bytes <= kKeptBytes || oldest == entries_.end()) return;
      entries_.erase(oldest);
    }
  }

  std::mutex mutex_;
  std::vector<Entry> entries_;
  uint64_t clock_ = 0;
};

}  // namespace

const CoefficientTables* TableCache::get(const std::shared_ptr<const NormalMap>& map,
                                         const std::shared_ptr<const GainMask>& mask, float mu_max,
                                         int directions, const ThreadPool* pool) {
  const Key key{map.get(), mask.get(), mu_max, directions};
  bool known = false;
  if (const CoefficientTables* tables = lookUp(key, known); known) return tables;
  Entry entry{SharedTables::instance().get(map, mask, mu_max, directions, pool), map, mask};
  const CoefficientTables* tables =
      entries_.emplace(key, std::move(entry)).first->second.tables.get();
  if (first_.size() < kFirst) first_.emplace_back(key, tables);
  return tables;
}

const CoefficientTables* TableCache::find(const NormalMap* map, const GainMask* mask, float mu_max,
                                          int directions) const {
  bool known = false;
  return lookUp(Key{map, mask, mu_max, directions}, known);
}

const CoefficientTables* TableCache::lookUp(const Key& key, bool& known) const {
  for (const auto& [k, tables] : first_) {
    if (k == key) {
      known = true;
      return tables;
    }
  }
  auto it = entries_.find(key);
  known = it != entries_.end();
  return known ? it->second.tables.get() : nullptr;
}

std::vector<TextureTables> TableCache::list() const {
  std::vector<TextureTables> out;
  std::vector<const CoefficientTables*> listed;
  for (const auto& [key, entry] : entries_) {
    const CoefficientTables* tables = entry.tables.get();
    if (!tables || std::find(listed.begin(), listed.end(), tables) != listed.end()) continue;
    listed.push_back(tables);
    out.push_back({entry.map.get(), entry.mask.get(), tables->bytes(), tables->levels()});
  }
  return out;
}

Vec2 tauOf(const Planar& prim) {
  return Vec2(prim.tbn[2].c, prim.tbn[5].c) / prim.tbn[8].c;
}

double tiltOf(const Planar& prim) {
  return tauOf(prim).norm();
}

bool isFlatFace(const Planar& prim) {
  // The face's normal (frame column N, contact frame) along the patch's normal.
  return !prim.smooth && std::abs(prim.tbn[8].c) >= std::cos(kMaxTilt);
}

bool coversNoCentre(const Volume& volume, const Planar& prim) {
  Polygon poly = patchSquare(volume);
  clipBy(poly, halfPlanesOf(volume, prim));
  if (poly.count < 3) return true;
  // A face seen edge-on (a box's side at the patch), its area within the depth clip far below
  // a pixel's: counted as covering none without testing the centres. It may still hold one
  // with probability about its area in pixels (1e-3), and then changes one pixel of P.
  if (areaOf(poly) < kSliverPixels * volume.pixel * volume.pixel) return true;
  const Planar* faces[] = {&prim};
  return noCentreIn(volume, poly, faces);
}

bool noteDepthDecisions(const Volume& volume, const Planar& prim, DepthMargins& depth,
                        bool coverage) {
  Polygon poly = patchSquare(volume);
  HalfPlanes planes = halfPlanesOf(volume, prim);
  HalfPlanes edges = planes;
  edges.count -= 2;  // the edges alone: the depth clip is what is being decided
  clipBy(poly, edges);
  if (poly.count < 3) return true;
  // A face seen edge-on (coversNoCentre's slivers), or cut by the clip with no pixel centre
  // within its edges (below), covers nothing while the clip moves in by less than the raster
  // path's margin for faces seen edge-on (noteEdgeOn in patch_raster.cpp: 0.005 w).
  const double edge_on = 0.005 * volume.width;
  const double sliver = kSliverPixels * volume.pixel * volume.pixel;
  if (areaOf(poly) < sliver) {
    depth.limitOutside(edge_on);
    return true;
  }
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
  const Planar* faces[] = {&prim};
  if (inside || beyond) {
    depth.noteRange(zmin, zmax, h);
  } else {
    // Cut by the clip: a secondary face with no pixel centre within its edges (a tilted
    // box's side seen nearly edge-on) has none within the clip however it moves.
    if (coverage && noCentreIn(volume, poly, faces, false)) {
      depth.limitOutside(edge_on);
      return true;
    }
    depth.forget();
  }
  if (!coverage) return false;
  // Whether it covers no pixel centre (coversNoCentre), from the same clipped polygon.
  if (beyond) return true;
  if (!inside) {
    HalfPlanes clip;
    clip.plane[0] = planes.plane[static_cast<size_t>(planes.count - 2)];
    clip.plane[1] = planes.plane[static_cast<size_t>(planes.count - 1)];
    clip.count = 2;
    clipBy(poly, clip);
    if (poly.count < 3 || areaOf(poly) < sliver) return true;
  }
  return noCentreIn(volume, poly, faces);
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
  // Within kOnGrid of a step of a tabulated angle, that angle (e off by at most 2e-3 rad for
  // 16 angles, g . e by 2e-3 |g|: boxes yawed by 3e-4 rad against the contact frame read N
  // angles, not 2N).
  constexpr double kOnGrid = 5e-3;
  if (w > 1.0 - kOnGrid) m0 = (m0 + 1) % angles, w = 0.0;
  const bool between = w > kOnGrid;
  // w0 = sin((1 - w) delta) / sin(delta), w1 = sin(w delta) / sin(delta): e's components
  // along the two tabulated directions, from cross products.
  double w0 = 1.0, w1 = 0.0;
  if (between) {
    const Vec2& ea = tables->unit(m0);
    const Vec2& eb = tables->unit((m0 + 1) % angles);
    const double scale = 1.0 / (std::hypot(ex, ey) * tables->sinStep());
    w0 = (ex * eb.y() - ey * eb.x()) * scale;
    w1 = (ea.x() * ey - ea.y() * ex) * scale;
  }
  // The face's tilt (the same tau for A and B). Below kFlat the gradient's channels are not
  // read.
  const Vec2 tau = tauOf(face);
  constexpr double kFlat = 1e-7;
  const bool tilted = tau.squaredNorm() > kFlat * kFlat;
  if (tables->group() != n) {
    // Tables laid out for another N (never from the cache, keyed by N): angle by angle.
    std::array<int, 2 * kMaxDirections> which{};
    const int per = between ? 2 : 1;
    for (int k = 0; k < n; ++k) {
      const int a =
          positiveMod(static_cast<long long>(m0) + static_cast<long long>(k) * step, angles);
      which[static_cast<size_t>(per * k)] = a;
      if (between) which[static_cast<size_t>(per * k + 1)] = (a + 1) % angles;
    }
    std::array<double, 2 * kMaxDirections> sums{}, grad_x{}, grad_y{};
    const auto used = static_cast<size_t>(per * n);
    const std::span<const Vec2> polygon(cells.data(), count);
    const std::span<const int> angles_used(which.data(), used);
    const double area =
        tables->integrate(polygon, angles_used, std::span<double>(sums.data(), used));
    if (!(area > 0.0)) return;
    if (tilted) {
      tables->integrate(polygon, angles_used, std::span<double>(grad_x.data(), used), 1);
      tables->integrate(polygon, angles_used, std::span<double>(grad_y.data(), used), 2);
      for (size_t k = 0; k < used; ++k) sums[k] += tau.x() * grad_x[k] + tau.y() * grad_y[k];
    }
    for (size_t k = 0; k < static_cast<size_t>(n); ++k) {
      const double s = between ? w0 * sums[2 * k] + w1 * sums[2 * k + 1] : sums[k];
      mean[k] = std::max(0.0, s / area);
    }
    return;
  }
  // Angle m0 + k step (step = +-phases) is in m0's phase at place m0 / phases +- k; angle
  // m0 + k step + 1 in the next phase at the same place, or, from the last phase, in phase 0
  // one place on.
  const int phases = tables->phases();
  const int phase = m0 % phases, place = m0 / phases;
  const int dir = step > 0 ? 1 : -1;
  const int carry = phase == phases - 1 ? 1 : 0;
  std::array<float, 2 * kMaxDirections * CoefficientTables::kChannels> sums{};
  // One phase (N = angles) holds both angles of each pair: read once.
  const bool second = between && phases > 1;
  const double area = tables->integrateGroups(std::span<const Vec2>(cells.data(), count), phase,
                                              second ? 2 : 1, tilted, sums.data());
  if (!(area > 0.0)) return;
  // f at a tabulated angle, to first order in the tilt: f + tau . (its gradient).
  const size_t block = static_cast<size_t>(second ? 2 * n : n);
  auto at_angle = [&](int i) {
    const auto k = static_cast<size_t>(i);
    if (!tilted) return static_cast<double>(sums[k]);
    return sums[k] + tau.x() * sums[block + k] + tau.y() * sums[2 * block + k];
  };
  const double inv_area = 1.0 / area;
  int at = place;
  for (int k = 0; k < n; ++k) {
    double s = at_angle(at);
    if (between) {
      const int next = at + carry == n ? 0 : at + carry;
      s = w0 * s + w1 * at_angle(second ? n + next : next);
    }
    // A mean of max(0, .) is not negative: first order may take it below 0 at fragments
    // tilted across the kink (within tiltError).
    mean[static_cast<size_t>(k)] = std::max(0.0, s * inv_area);
    at += dir;
    at = at == n ? 0 : (at < 0 ? n - 1 : at);
  }
}

}  // namespace asperity::patch
