// The planar path of the CPU sampler (docs/samplers.md, "Planar patches"): a flat patch on flat
// textured faces (box faces on planes and on each other) averages each direction's fragment
// coefficient over a convex footprint, which prefiltered tables give without shading pixels.
//
// The field tabulated is the one the raster path samples: at a point of the texture the normal
// map is blended bilinearly (unnormalised, as patch_texture.hpp does), turned into a ploughing
// vector g (fragment_model.hpp) and, through the gain mask, into max(0, g . e) for a direction e
// in the map's tangent plane. Averaging the texels' own coefficients is a different number
// (the ploughing term is not linear in the normal). The tables hold running sums (float) along
// each row of cells of the cells' means (a cell is 1 / sub of a texel, between texel centres, so
// its normals are one bilinear patch), at `angles` directions e evenly spaced in the tangent
// plane. A convex footprint is then a sum over the cell rows it crosses of one span each (two
// adjacent points of the row per end), so its cost is its height in cells, not R x R pixels.
//
// Approximations, each bounded in docs/samplers.md: (1) the footprint's mean of the field, not
// its mean at the pixel centres (the raster path's own sampling noise); (2) cells cut by the
// footprint's boundary count with their mean density; (3) a direction between two tabulated
// angles is interpolated with weights exact for every fragment whose g lies on the same side
// of both (the cosine law), so only fragments within one angle step of the kink of max(0, .)
// differ; (4) a face tilted against the contact plane by at most kMaxTilt is shaded to first
// order in its tilt (the tables' gradient channels).
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
#include "asperity/math/simd_copy.hpp"
#include "asperity/math/types.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity {
class ThreadPool;
}

namespace asperity::patch {

// Largest tilt (rad) of a face against the contact plane that the planar path takes. A tilt
// shifts every fragment's g . e by about -(2 / pi) tau . e (tau the contact normal's slope in
// the face's frame, |tau| = tan(tilt)); the tables hold each coefficient's gradient in tau,
// so a tilted face is shaded to first order (docs/samplers.md bounds the rest).
inline constexpr double kMaxTilt = 1e-2;
// What first-order shading may miss at most, in mu (CoefficientTables::tiltError at the face's
// tilt, times its gain), for a tilted face to take the planar path: below the raster path's own
// sampling noise (per contact, median 0.5 to 2.5 % of mu_d, which is at least mu0, 0.2 in the
// experiments).
inline constexpr double kMaxTiltError = 1e-3;

// Footprints with fewer pixel centres than this take the raster path: they are cheap to
// rasterise, and there the tables' boundary cells weigh most.
inline constexpr int kMinPlanarPixels = 32;

// At most this many bytes of tables per (texture, mask, mu_max, direction set).
inline constexpr size_t kTableBudgetBytes = size_t{64} << 20;

// Cells per texel along each axis and tabulated angles for a map and a direction count; angles
// 0 when no layout fits the budget (the raster path then samples that texture).
struct TableLayout {
  int sub = 1;
  int angles = 0;
  // Angles stored side by side per phase: N (the directions a contact reads together).
  int group = 0;
  size_t bytes(int width, int height) const;
};
TableLayout tableLayout(int width, int height, int directions);

// Floats (not set) on 2 MiB pages where the system gives them (Linux: madvise): a contact's
// strips read rows kilobytes apart, each a TLB miss on 4 KiB pages once the tables outgrow the
// TLB's reach (a few MB).
class TableMemory {
 public:
  void assign(size_t count);  // count floats, their values unset
  float* data() { return data_.get(); }
  const float* data() const { return data_.get(); }
  size_t size() const { return size_; }

 private:
  struct Free {
    void operator()(float* p) const;
  };
  std::unique_ptr<float[], Free> data_;
  size_t size_ = 0;
};

class CoefficientTables {
 public:
  // Builds the tables of `map` (and `mask`, null for none), rows in parallel on `pool` (null:
  // this thread); the same bits for any thread count and either SIMD copy, which the
  // integrals use too.
  CoefficientTables(const NormalMap& map, const GainMask* mask, float mu_max, TableLayout layout,
                    const ThreadPool* pool, SimdCopy copy = SimdCopy::Auto);

  // Values per point of a row: f, and its gradient in the tilt (x, then y), each at every angle.
  static constexpr size_t kChannels = 3;
  // The gradient's cells are this many of f's cells along each axis (where the rows and columns
  // divide): it enters times the tilt's tangent, at most 0.01, so coarser cells at its
  // footprint's edge (error (2)) weigh a hundredth as much; it then takes a quarter of the
  // memory and of the rows a contact reads.
  static constexpr int kGradientCoarsening = 2;
  static int gradientCoarsening(int cols, int rows);
  // A footprint taller than this many rows of cells is integrated on a coarser level of the
  // tables (cells 2, 4, 8 times larger along each axis, each level's sums the means of the
  // finer level's 2 x 2 cells): a fine map seen through a wide patch (boxes_on_materials'
  // plaster, 80 texels across) then reads at most about this many strips, not one per texel
  // row. The boundary cells (error (2)) are larger by as much.
  static constexpr int kMaxStripRows = 16;
  // The same for the gradient: it enters times the tilt's tangent (at most 0.01), so its levels
  // pass the same check in mu (kMaxLevelError) on footprints a quarter as many rows tall, and
  // a tilted face reads a few rows of it instead of as many as of f (whose cost it doubled).
  static constexpr int kMaxGradientRows = 4;
  static constexpr int kMaxLevels = 4;
  // A level is used only while footprints read on it stay this close (in mu, before the
  // surface's gain) to the finest level, checked on kLevelChecks footprints at build time.
  static constexpr double kMaxLevelError = 5e-3;
  static constexpr int kLevelChecks = 32;
  // The floats of the coarser levels of a table of cols x rows cells (per_point floats a
  // point) at most: levels are made while both counts are even, down to 4 cells, at most
  // kMaxLevels, and kept while they pass (kMaxLevelError).
  static size_t coarserFloats(int cols, int rows, size_t per_point);

  int angles() const { return angles_; }
  // Levels of f's sums (1: the finest only) and of the gradient's (see kMaxStripRows).
  int levels() const { return static_cast<int>(f_levels_.size()); }
  int gradientLevels() const { return static_cast<int>(gradient_levels_.size()); }
  // A bound on what shading a face tilted by kMaxTilt to first order misses, per fragment in
  // the map's mean, at the worst angle: the mean over the map of max(0, |grad f| tan(kMaxTilt)
  // - |f|) (a fragment errs only where the tilt can carry its f across the kink of max(0, f)).
  // It grows at most linearly with the tilt. Large where many fragments lie at the kink: a
  // sawtooth seen across its teeth, flat plateaus, smooth maps.
  double tiltError() const { return tilt_error_; }
  // Angles per phase (see integrateGroups) and phases.
  int group() const { return group_; }
  int phases() const { return phases_; }
  size_t bytes() const {
    return (sums_.size() + gradient_.size() + coarser_.size()) * sizeof(float);
  }
  // Tabulated angle a's direction, and the sine of the step between angles.
  const Vec2& unit(int a) const { return units_[static_cast<size_t>(a)]; }
  double sinStep() const { return sin_step_; }

  // The integrals over a convex polygon given in cell coordinates (x = (u W - 1/2) sub, y the
  // same along v), counter-clockwise or clockwise, at the tabulated angles `which` (indices in
  // [0, angles)), into out (same length). Returns the polygon's area in cells.
  // `channel` 0 reads f, 1 and 2 its gradient in the tilt (see kChannels).
  double integrate(std::span<const Vec2> polygon, std::span<const int> which, std::span<double> out,
                   int channel = 0) const;

  // The same for every angle of `count` (1 or 2) consecutive phases from `phase` (the last
  // phase is followed by phase 0): angle a is in phase a % phases at place a / phases; out
  // holds count x group values, phase by phase; with `gradient`, then the same for the
  // gradient's x and then its y channel (integrals in f's cells too). Returns the area in cells.
  double integrateGroups(std::span<const Vec2> polygon, int phase, int count, bool gradient,
                         float* out) const;

  // From texture coordinates (repeats) to the cell coordinates of integrate.
  Vec2 cellOf(double u, double v) const;

 private:
  // The rows of f's cells within one row of gradient cells, and that row.
  // Each row's tilt error sums (per angle) go to row_errors + row x angles.
  void buildRows(const NormalMap& map, const GainMask* mask, float mu_max, SimdCopy copy,
                 int gradient_row, double* row_errors);
  // The row sums over [begin, begin + len) of a point's values in `table` (per_point floats a
  // point; at most 4 ranges), each times a strip's height, into out (ranges' values one after
  // the other).
  struct Range {
    int begin = 0, len = 0;
  };
  // A table of running sums: per_point floats a point, cols + 1 points a row.
  struct Grid {
    const float* table = nullptr;
    size_t per_point = 0;
    int cols = 0, rows = 0;
  };
  double accumulate(const Grid& grid, std::span<const Vec2> polygon, std::span<const Range> ranges,
                    float* out) const;
  // accumulate on a table whose cells are `scale` of f's cells along each axis, for a polygon
  // in f's cells (at most 32 vertices): the integrals and the area (returned) counted in f's
  // cells.
  double accumulateScaled(const Grid& grid, int scale, std::span<const Vec2> polygon,
                          std::span<const Range> ranges, float* out) const;
  // The finest of `levels` (level 0 of cells `scale` f cells wide) on which a footprint
  // `height` f cells tall spans at most `max_rows` rows, else the coarsest: its index.
  static int levelFor(double height, const std::vector<Grid>& levels, int scale, int max_rows);
  // Appends coarser levels of levels[0] (cells `scale` of f's), each's sums appended to
  // `made`, while levelError times `weight` stays within kMaxLevelError.
  void addCoarserLevels(std::vector<Grid>& levels, int scale, int max_rows, double weight,
                        std::vector<std::vector<float>>& made) const;
  // The largest difference, in a footprint's mean at any angle, between `coarse` (level
  // `level` of `finest`, whose cells are `scale` of f's) and `finest`, over kLevelChecks
  // turned squares as small as footprints that would read it (levelFor with `max_rows`).
  double levelError(const Grid& finest, const Grid& coarse, int scale, int level,
                    int max_rows) const;

  int cols_ = 0, rows_ = 0, sub_ = 1, angles_ = 0, group_ = 1, phases_ = 1;
  double tilt_error_ = 0.0;
  int map_width_ = 0, map_height_ = 0;
  SimdCopy copy_ = SimdCopy::Auto;  // the build's and the integrals' copy (the same bits)
  std::vector<float> dx_, dy_;      // the tabulated e, as two arrays (the build's loop vectorises)
  std::vector<size_t> place_;       // where angle a lies among a point's values (see sums_)
  std::vector<Vec2> units_;         // the same in double
  double sin_step_ = 0.0;
  // Running sums along each row of cells (float: a row's values stay small): R(row, x) = the
  // integral over [0, x) of the row, at [(row (cols + 1) + x) angles + place], x in
  // [0, cols]; place = (a % phases) group + a / phases (a phase's angles side by side).
  TableMemory sums_;
  // The same running sums of f's gradient in the tilt over cells coarse_ times larger: per
  // point the angles' x components, then their y components, at the places of sums_.
  TableMemory gradient_;
  int coarse_ = 1;  // gradientCoarsening
  Grid f_grid_, gradient_grid_;
  // Level k of f's and of the gradient's sums (cells 2^k as large; level 0 is f_grid_ and
  // gradient_grid_); the levels from 1 live in coarser_.
  std::vector<Grid> f_levels_, gradient_levels_;
  TableMemory coarser_;
};

// Tables by texture identity, shared by every body whose surface uses the same map. get() builds
// a missing entry: threads may share the cache only for entries already in it (prepare first).
// The tables themselves come from a store shared by the process, by the map's content: a world
// made after another with the same textures finds them built.
class TableCache {
 public:
  // Null when the layout does not fit the budget.
  const CoefficientTables* get(const std::shared_ptr<const NormalMap>& map,
                               const std::shared_ptr<const GainMask>& mask, float mu_max,
                               int directions, const ThreadPool* pool);
  // Looks an entry up without building it (null when absent or over budget).
  const CoefficientTables* find(const NormalMap* map, const GainMask* mask, float mu_max,
                                int directions) const;
  // Every texture's tables, each once (maps equal in content share theirs).
  std::vector<TextureTables> list() const;

 private:
  using Key = std::tuple<const NormalMap*, const GainMask*, float, int>;
  struct Entry {
    std::shared_ptr<const CoefficientTables> tables;  // null: over budget
    std::shared_ptr<const NormalMap> map;             // kept alive: the key is its address
    std::shared_ptr<const GainMask> mask;
  };
  std::map<Key, Entry> entries_;
  // The first entries made, scanned before the map: every fresh contact of a step looks up
  // its shapes' few textures again, on every thread. Entries are never removed, so neither
  // are these.
  static constexpr size_t kFirst = 16;
  std::vector<std::pair<Key, const CoefficientTables*>> first_;
  // An entry's tables (null: over budget), `known` false when there is none.
  const CoefficientTables* lookUp(const Key& key, bool& known) const;
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

// tau = (T . n, B . n) / (N . n) of a flat primitive: the contact normal's slope in its frame,
// the same formula for A and B (docs/samplers.md, "Tilted faces").
Vec2 tauOf(const Planar& prim);
// |tau|: the tangent of its tilt against the contact plane (0 when it lies in it).
double tiltOf(const Planar& prim);

// Whether `prim` may stand for its surface in the planar path: flat-framed, tilted by at most
// kMaxTilt. Secondary primitives must cover no pixel centre (coversNoCentre).
bool isFlatFace(const Planar& prim);
// Whether no pixel centre lies in `prim` within the volume (its edges, the depth clip).
bool coversNoCentre(const Volume& volume, const Planar& prim);

// Notes in `depth` the depth clip's decisions on the face's pixels within the patch square
// (what the raster path notes; patch_reuse.hpp keeps a sample while they hold).
// With `coverage`, returns coversNoCentre(volume, prim) from the same clipping (else false).
bool noteDepthDecisions(const Volume& volume, const Planar& prim, DepthMargins& depth,
                        bool coverage = false);

// The footprint of two faces; pixels counted with the edge tests' top-left rule.
Footprint footprintOf(const Volume& volume, const Planar& a, const Planar& b);

// Mean per direction of surface `side` over the footprint into mean (N = directions.size()):
// the tables at the directions' angles in the face's tangent plane.
void planarMeans(const Footprint& footprint, const PlanarSurface& surface, Side side,
                 std::span<const Vec2> directions, std::span<double> mean);

}  // namespace asperity::patch
