// Contacts from a signed distance field queried with another shape's surface points (the
// vertices of its mesh plus points spread over its triangles, so that coarse meshes touching
// face to face are seen): the concave-mesh path of the collision stage.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "asperity/math/types.hpp"
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
  // Optional: true when every point within `radius` of `centre` (field frame) lies certainly
  // farther than max_distance from the field's shape; such blocks of points are skipped.
  std::function<bool(const Vec3& centre, double radius)> beyond;
};

// A signed distance in the field shape's frame: a grid field or an exact primitive.
using DistanceFn = std::function<SignedDistanceField::Sample(const Vec3&)>;

// Buffers of sdfHits, kept by the caller so that a step allocates nothing once they grew.
struct SdfHitBuffers {
  std::vector<SdfHit> hits, kept;
};

// Queries `points` (in the frame `points_world`) against `field` (in `field_world`) and
// returns the kept hits (in `buffers`, until their next use), deepest first (ties by vertex
// index, so the order is deterministic). `blocks`, when given, group the points
// (SurfaceSamples::blocks): a block outside query.bounds is skipped whole, with the same hits
// as testing each of its points.
const std::vector<SdfHit>& sdfHits(const DistanceFn& field, const Transform& field_world,
                                   std::span<const Vec3> points, const Transform& points_world,
                                   const SdfQuery& query, SdfHitBuffers& buffers,
                                   const SampleBlocks* blocks = nullptr);
const std::vector<SdfHit>& sdfHits(const SignedDistanceField& field, const Transform& field_world,
                                   std::span<const Vec3> points, const Transform& points_world,
                                   const SdfQuery& query, SdfHitBuffers& buffers);

}  // namespace asperity::collision_detail
