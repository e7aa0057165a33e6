// Triangle ids for hull and vertex contacts on meshes (see mesh_features.hpp).
#include "collision/mesh_features.hpp"

#include <algorithm>
#include <limits>

#include "collision/signed_distance_field.hpp"

namespace asperity::collision_detail {

MeshFeatures::MeshFeatures(std::shared_ptr<const TriangleMeshData> mesh) : mesh_(std::move(mesh)) {
  // The triangles of each vertex (counted, then filled in), and the tree over the triangles.
  const size_t n = mesh_->vertices.size();
  vertex_start_.assign(n + 1, 0);
  for (const auto& tri : mesh_->triangles) {
    for (int v : tri) ++vertex_start_[static_cast<size_t>(v) + 1];
  }
  for (size_t v = 0; v < n; ++v) vertex_start_[v + 1] += vertex_start_[v];
  vertex_list_.resize(mesh_->triangles.size() * 3);
  std::vector<int> fill(vertex_start_.begin(), vertex_start_.end() - 1);
  for (size_t t = 0; t < mesh_->triangles.size(); ++t) {
    for (int v : mesh_->triangles[t]) {
      vertex_list_[static_cast<size_t>(fill[static_cast<size_t>(v)]++)] = static_cast<int>(t);
    }
  }
  std::vector<Vec3f> positions;
  positions.reserve(n);
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh_->vertices) positions.push_back(v.cast<float>()), box.extend(v);
  if (!mesh_->triangles.empty()) bvh_ = TriangleBvh(positions, mesh_->triangles);
  size_ = n == 0 ? 0.0 : box.diagonal().norm();
}

double MeshFeatures::alignment(int t, const Vec3& outward) const {
  const auto& tri = mesh_->triangles[static_cast<size_t>(t)];
  const auto& v = mesh_->vertices;
  const Vec3& a = v[static_cast<size_t>(tri[0])];
  const Vec3 n = (v[static_cast<size_t>(tri[1])] - a).cross(v[static_cast<size_t>(tri[2])] - a);
  return n.norm() > 0 ? n.normalized().dot(outward) : -2.0;
}

int MeshFeatures::triangleAtVertex(int v, const Vec3& outward) const {
  if (v < 0 || v >= static_cast<int>(mesh_->vertices.size())) return -1;
  int best = -1;
  double best_align = -3.0;
  const auto begin = static_cast<size_t>(vertex_start_[static_cast<size_t>(v)]);
  const auto end = static_cast<size_t>(vertex_start_[static_cast<size_t>(v) + 1]);
  for (size_t i = begin; i < end; ++i) {
    const double align = alignment(vertex_list_[i], outward);
    if (align > best_align) best_align = align, best = vertex_list_[i];
  }
  return best;
}

int MeshFeatures::nearestTriangle(const Vec3& p, const Vec3& outward,
                                  NearestScratch& scratch) const {
  if (mesh_->triangles.empty()) return -1;
  std::vector<int>& candidates = scratch.candidates;
  std::vector<double>& dist = scratch.dist;
  // Any triangle within r of p overlaps the box of half size r: the nearest candidate at a
  // distance <= r is the nearest of all.
  // The last box (reach) holds the whole mesh, so the search always ends with an answer.
  const Aabb all = bvh_.bounds();
  const Vec3 outside =
      (all.lo.cast<double>() - p).cwiseMax(p - all.hi.cast<double>()).cwiseMax(0.0);
  const double reach = outside.norm() + size_ + 1e-12;
  int best = -1;
  for (double r = std::min(std::max(1e-3 * size_, 1e-12), reach);; r = std::min(4 * r, reach)) {
    Aabb box;
    box.grow((p - Vec3::Constant(r)).cast<float>());
    box.grow((p + Vec3::Constant(r)).cast<float>());
    candidates.clear();
    bvh_.query(box, candidates);
    // Nearest first; within a tolerance of it, the best aligned normal.
    dist.resize(candidates.size());
    double best_d = std::numeric_limits<double>::max();
    for (size_t i = 0; i < candidates.size(); ++i) {
      const auto& tri = mesh_->triangles[static_cast<size_t>(candidates[i])];
      const auto& v = mesh_->vertices;
      dist[i] =
          (closestPointOnTriangle(p, v[static_cast<size_t>(tri[0])], v[static_cast<size_t>(tri[1])],
                                  v[static_cast<size_t>(tri[2])]) -
           p)
              .norm();
      best_d = std::min(best_d, dist[i]);
    }
    double best_align = -3.0;
    for (size_t i = 0; i < candidates.size(); ++i) {
      if (dist[i] > best_d + 1e-9 * size_) continue;
      const double align = alignment(candidates[i], outward);
      if (align > best_align) best_align = align, best = candidates[i];
    }
    if ((best >= 0 && best_d <= r) || r >= reach) return best;
  }
}

}  // namespace asperity::collision_detail
