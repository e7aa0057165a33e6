// Contacts from a signed distance field queried with another shape's surface points (the
// vertices of its mesh plus points spread over its triangles, so that coarse meshes touching
// face to face are seen): the concave-mesh path of the collision stage.
#pragma once

#include <span>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "asperity/math/types.hpp"
#include "collision/primitive_distance.hpp"
#include "collision/signed_distance_field.hpp"

namespace asperity::collision_detail {

// The points grouped into blocks of nearby points (kSampleBlock each, in Morton order), so
// that a query skips the blocks that lie wholly outside the field.
struct SampleBlocks {
  std::vector<int> order;                   // point indices, block after block
  std::vector<Vec3> points;                 // the points in that order (read in sequence)
  std::vector<Eigen::AlignedBox3d> bounds;  // of each block's points
};
inline constexpr size_t kSampleBlock = 32;
SampleBlocks sampleBlocks(const std::vector<Vec3>& points);

// Points on a mesh's surface: its vertices and a barycentric grid on each triangle with
// about `spacing` between points (coarsened so that there are at most `max_points`).
struct SurfaceSamples {
  std::vector<Vec3> points;
  std::vector<int> triangle;  // the triangle each point lies on
  SampleBlocks blocks;
};
SurfaceSamples surfaceSamples(const TriangleMeshData& mesh, double spacing, size_t max_points);

// One surface point of the query shape inside (or near) the field's shape.
struct SdfHit {
  int vertex = -1;        // index of the query point
  int triangle = -1;      // closest triangle of the field's mesh
  Vec3 point;             // the query point (world)
  Vec3 surface;           // the nearest point of the field's surface (world)
  Vec3 outward;           // the field shape's outward normal (world)
  double distance = 0.0;  // signed distance of `point` (< 0 inside), m
};

struct SdfQuery {
  double max_distance = 0.0;  // report points with distance below this (m)
  int max_hits = 32;          // deepest first
  double min_spacing = 0.0;   // kept hits lie at least this far apart (m)
  // Where the field can report anything (field frame); points outside are skipped unseen.
  Eigen::AlignedBox3d bounds = Eigen::AlignedBox3d(Vec3::Constant(-1e300), Vec3::Constant(1e300));
};

// The signed distance the query points meet, in the field shape's frame: a grid (closed
// meshes) or a primitive's exact distance. Two cases, called per point: no std::function.
class FieldDistance {
 public:
  static FieldDistance grid(const SignedDistanceField& field) {
    FieldDistance d;
    d.grid_ = &field;
    return d;
  }
  // Points farther than `reach` from the primitive skip the exact distance.
  static FieldDistance primitive(const Shape& shape, double reach) {
    FieldDistance d;
    d.primitive_ = &shape;
    d.reach_ = reach;
    d.lane_reach_ = PrimitiveReach(shape, reach);
    return d;
  }

  // The sample at p; a distance at or above `below` may come alone (no gradient or triangle).
  // sdfHits asks only for points that beyond(p) below has not already ruled out.
  SignedDistanceField::Sample operator()(const Vec3& p, double below) const {
    if (grid_ != nullptr) return grid_->sample(p, below);
    return primitiveSample(*primitive_, p);
  }
  // True when every point within `radius` of `centre` lies certainly farther than the reach
  // from the primitive (a block of points skipped whole); a grid gives false.
  bool beyond(const Vec3& centre, double radius) const {
    return primitive_ != nullptr && PrimitiveReach(*primitive_, reach_ + radius).beyond(centre);
  }
  // Per lane, whether the point lies certainly farther than the reach (a grid: never).
  lanes::Mask beyond(const lanes::Lanes3& p) const { return lane_reach_.beyond(p); }

 private:
  const SignedDistanceField* grid_ = nullptr;
  const Shape* primitive_ = nullptr;
  double reach_ = 0.0;
  PrimitiveReach lane_reach_;
};

// Buffers of sdfHits, kept by the caller so that a step allocates nothing once they grew.
struct SdfHitBuffers {
  std::vector<SdfHit> hits, kept;
};

// Queries `points` (in the frame `points_world`) against `field` (in `field_world`) and
// returns the kept hits (in `buffers`, until their next use), deepest first (ties by vertex
// index, so the order is deterministic). `blocks`, when given, group the points
// (SurfaceSamples::blocks): a block outside query.bounds is skipped whole, with the same hits
// as testing each of its points.
const std::vector<SdfHit>& sdfHits(const FieldDistance& field, const Transform& field_world,
                                   std::span<const Vec3> points, const Transform& points_world,
                                   const SdfQuery& query, SdfHitBuffers& buffers,
                                   const SampleBlocks* blocks = nullptr);

}  // namespace asperity::collision_detail
