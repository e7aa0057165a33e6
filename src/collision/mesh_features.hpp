// Triangle ids for contacts on meshes whose collision geometry does not carry them: dynamic
// meshes and hulls collide through their convex hull or their vertices, but the patch
// samplers look up UVs and tangent frames by triangle (Contact::feature_*).
#pragma once

#include <memory>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "geometry/bvh.hpp"

namespace asperity::collision_detail {

// The buffers of nearestTriangle, kept by the caller (one per thread) between searches.
struct NearestScratch {
  std::vector<int> candidates;
  std::vector<double> dist;
  // At least as large as other's.
  void reserveLike(const NearestScratch& other) {
    candidates.reserve(other.candidates.capacity());
    dist.reserve(other.dist.capacity());
  }
};

class MeshFeatures {
 public:
  explicit MeshFeatures(std::shared_ptr<const TriangleMeshData> mesh);

  // Of the triangles using vertex v, the one whose normal is closest to `outward` (mesh
  // frame); -1 when none uses it.
  int triangleAtVertex(int v, const Vec3& outward) const;
  // The triangle nearest to p (mesh frame), found through a box that grows until the nearest
  // candidate lies inside it; among equally near ones (edges, corners) the one whose normal is
  // closest to `outward`. -1 for a mesh without triangles.
  int nearestTriangle(const Vec3& p, const Vec3& outward, NearestScratch& scratch) const;

 private:
  std::shared_ptr<const TriangleMeshData> mesh_;
  double alignment(int t, const Vec3& outward) const;

  std::vector<int> vertex_start_;  // triangles of vertex v: vertex_list_[start[v], start[v+1])
  std::vector<int> vertex_list_;
  TriangleBvh bvh_;
  double size_ = 0.0;  // diagonal of the mesh's box
};

}  // namespace asperity::collision_detail
