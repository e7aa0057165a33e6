// The planar path of the CPU sampler (docs/samplers.md, "Planar patches"): a flat patch on flat
// textured faces (box faces on planes and on each other) averages each direction's fragment
// coefficient over a convex footprint, which prefiltered tables give without shading pixels.
//
// The field tabulated is the one the raster path samples: at a point of the texture the normal
// map is blended bilinearly (unnormalised, as patch_texture.hpp does), turned into a ploughing
// vector g (fragment_model.hpp) and, through the gain mask, into max(0, g . e) for a direction e
// in the map's tangent plane. Averaging the texels' own coefficients is a different number
// (the ploughing term is not linear in the normal). The tables hold a summed-area table (in
// double) of the cells' means (a cell is 1 / sub of a texel, between texel centres, so its
// normals are one bilinear patch), at `angles` directions e evenly spaced in the tangent plane.
// A footprint aligned with the texture's axes (boxes stacked square on each other) is then four
// corner reads per angle; any other convex footprint is a sum over the cell rows it crosses of
// one span each (two lines of the table per end), so its cost is its height in cells, not
// R x R pixels.
//
// Approximations, each bounded in docs/samplers.md: (1) the footprint's mean of the field, not
// its mean at the pixel centres (the raster path's own sampling noise); (2) cells cut by the
// footprint's boundary count with their mean density; (3) a direction between two tabulated
// angles is interpolated with weights exact for every fragment whose g lies on the same side
// of both (the cosine law), so only fragments within one angle step of the kink of max(0, .)
// differ; (4) a face tilted against the contact plane by at most kMaxTilt is shaded as if
// flat.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <tuple>
#include <vector>

#include "asperity/geometry/surface.hpp"
#include "asperity/math/types.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity {
class ThreadPool;
}

namespace asperity::patch {

// Largest tilt (rad) of a face against the contact plane that the planar path shades as flat:
// the meso normals then turn by at most this, g by at most about (2 / pi) kMaxTilt (6e-4).
inline constexpr double kMaxTilt = 1e-3;

// At most this many bytes of tables per (texture, mask, mu_max, direction set).
inline constexpr size_t kTableBudgetBytes = size_t{64} << 20;

// Cells per texel along each axis and tabulated angles for a map and a direction count; angles
// 0 when no layout fits the budget (the raster path then samples that texture).
struct TableLayout {
  int sub = 1;
  int angles = 0;
  // A second table on the grid turned by 45 degrees (square maps, where it fits the budget):
  // footprints turned by 45 degrees against the texture are rectangles there.
  bool diagonal = false;
  // Angles stored side by side per point: N (the directions a contact reads together).
  int group = 0;
  size_t bytes(int width, int height) const;
};
TableLayout tableLayout(int width, int height, int directions);

class CoefficientTables {
 public:
  // Builds the tables of `map` (and `mask`, null for none), rows in parallel on `pool` (null:
  // this thread); the same bits for any thread count.
  CoefficientTables(const NormalMap& map, const GainMask* mask, float mu_max, TableLayout layout,
                    const ThreadPool* pool);

  int angles() const { return angles_; }
  size_t bytes() const { return (sat_.size() + diagonal_sat_.size()) * sizeof(double); }

  // The integrals over a convex polygon given in cell coordinates (x = (u W - 1/2) sub, y the
  // same along v), counter-clockwise or clockwise, at the tabulated angles `which` (indices in
  // [0, angles)), into out (same length). Returns the polygon's area in cells.
  double integrate(std::span<const Vec2> polygon, std::span<const int> which,
                   std::span<double> out) const;

  // From texture coordinates (repeats) to the cell coordinates of integrate.
  Vec2 cellOf(double u, double v) const;

 private:
  void buildRow(const NormalMap& map, const GainMask* mask, float mu_max, int row);
  // Where x (any real: the texture repeats) falls in row `row`, for its running sums.
  // A summed-area table of cols x rows cells (cols + 1 by rows + 1 values per angle) that
  // tiles the plane.
  //
  // Layout: the angles a contact reads together are side by side. Angle a is in phase
  // a % phases (a plane of its own) at place a / phases of its point, a point holding `group`
  // values: [(phase (rows + 1) + y) (cols + 1) + x] group + a / phases.
  struct Grid {
    const double* sat = nullptr;
    int cols = 0, rows = 0;
    size_t plane = 0;  // values per phase
  };
  Grid makeGrid(const double* sat, int cols, int rows) const {
    return {sat, cols, rows,
            static_cast<size_t>(rows + 1) * static_cast<size_t>(cols + 1) *
                static_cast<size_t>(group_)};
  }
  Grid axisGrid() const { return makeGrid(sat_.data(), cols_, rows_); }
  Grid diagonalGrid() const { return makeGrid(diagonal_sat_.data(), diagonal_, diagonal_); }
  size_t offsetOf(const Grid& grid, int angle) const {
    return static_cast<size_t>(angle % phases_) * grid.plane + static_cast<size_t>(angle / phases_);
  }
  void sumColumns(const Grid& grid, double* sat) const;
  void storeRow(const Grid& grid, double* sat, int row, int c,
                std::span<const double> running) const;
  void buildDiagonalRow(const NormalMap& map, const GainMask* mask, float mu_max, int row);
  // The field at texel coordinates (tx, ty) (texel centres at integers), added to cell.
  void addFieldAt(const NormalMap& map, const GainMask* mask, float mu_max, double tx, double ty,
                  std::span<double> cell) const;
  // A row's running sum is the difference of two lines of the 2D table (y = row, row + 1).
  struct RowPosition {
    const double* cell = nullptr;   // line `row` at the cell's start (angles side by side)
    const double* total = nullptr;  // line `row` at the row's end
    size_t line = 0;                // doubles from one line to the next
    double fraction = 0.0, repeats = 0.0;
    // angle: offsetOf's; stride: values per point.
    double sumAt(size_t angle, size_t stride) const {
      const size_t next = stride + angle;
      const double lo = cell[line + angle] - cell[angle];
      const double hi = cell[line + next] - cell[next];
      // Most footprints lie within one repeat: the row's total is then not read.
      const double whole = repeats != 0.0 ? repeats * (total[line + angle] - total[angle]) : 0.0;
      return whole + lo + fraction * (hi - lo);
    }
  };
  // The sums over [0, x] x [0, y] (x < 2 cols, y < 2 rows) at `which`, times sign, added to out.
  void cornerSums(const Grid& grid, double x, double y, std::span<const int> which, double sign,
                  std::span<double> out) const;
  // integrate for a rectangle aligned with the grid within one repeat; false for any other.
  bool integrateRectangle(const Grid& grid, std::span<const Vec2> polygon,
                          std::span<const int> which, std::span<double> out, double& area) const;
  RowPosition positionOf(int row, double x) const;

  int cols_ = 0, rows_ = 0, sub_ = 1, angles_ = 0, group_ = 1, phases_ = 1;
  int map_width_ = 0, map_height_ = 0;
  double inv_cols_ = 1.0;
  std::vector<Vec2f> directions_;  // the tabulated e
  // The summed-area table: S(x, y) = integral over [0, x) x [0, y) in cells, at
  // [(y (cols + 1) + x) angles + a], x in [0, cols], y in [0, rows].
  std::vector<double> sat_;
  // The diagonal table (layout.diagonal): cells of one texel along p = tx + ty and q = tx - ty
  // (half a texel's area), 2 W of them along each (the plane's period along both).
  int diagonal_ = 0;
  std::vector<double> diagonal_sat_;
};

// Tables by texture identity, shared by every body whose surface uses the same map. get() builds
// a missing entry: threads may share the cache only for entries already in it (prepare first).
class TableCache {
 public:
  // Null when the layout does not fit the budget.
  const CoefficientTables* get(const std::shared_ptr<const NormalMap>& map,
                               const std::shared_ptr<const GainMask>& mask, float mu_max,
                               int directions, const ThreadPool* pool);
  // Looks an entry up without building it (null when absent or over budget).
  const CoefficientTables* find(const NormalMap* map, const GainMask* mask, float mu_max,
                                int directions) const;
  size_t bytes() const;
  size_t size() const { return entries_.size(); }

 private:
  using Key = std::tuple<const NormalMap*, const GainMask*, float, int>;
  struct Entry {
    std::unique_ptr<CoefficientTables> tables;  // null: over budget
    std::shared_ptr<const NormalMap> map;       // kept alive: the key is its address
    std::shared_ptr<const GainMask> mask;
  };
  std::map<Key, Entry> entries_;
};

// One surface of a planar contact: its face and what its coefficients need.
struct PlanarSurface {
  const Planar* face = nullptr;
  const CoefficientTables* tables = nullptr;  // null: a flat surface (every coefficient 0)
};

// The footprint: the patch square clipped by both faces' edges and depth clips (contact frame
// x, y), and the number of pixel centres in it (the raster path's |P|).
struct Footprint {
  std::array<Vec2, 24> vertex{};
  int count = 0;
  int pixels = 0;
};

// Whether `prim` may stand for its surface in the planar path: flat-framed, tilted by at most
// kMaxTilt. Secondary primitives must cover no pixel centre (coversNoCentre).
bool isFlatFace(const Planar& prim);
// Whether no pixel centre lies in `prim` within the volume (its edges, the depth clip).
bool coversNoCentre(const Volume& volume, const Planar& prim);

// Notes in `depth` the depth clip's decisions on the face's pixels within the patch square
// (what the raster path notes; patch_reuse.hpp keeps a sample while they hold).
void noteDepthDecisions(const Volume& volume, const Planar& prim, DepthMargins& depth);

// The footprint of two faces; pixels counted with the edge tests' top-left rule.
Footprint footprintOf(const Volume& volume, const Planar& a, const Planar& b);

// Mean per direction of surface `side` over the footprint into mean (N = directions.size()):
// the tables at the directions' angles in the face's tangent plane.
void planarMeans(const Footprint& footprint, const PlanarSurface& surface, Side side,
                 std::span<const Vec2> directions, std::span<double> mean);

}  // namespace asperity::patch
