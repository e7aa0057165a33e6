// An axis-aligned bounding-box tree over a mesh's triangles, built once per mesh, for finding
// the triangles near a contact patch (SPEC 3) without touching the rest of the mesh.
#pragma once

#include <array>
#include <limits>
#include <span>
#include <vector>

#include "asperity/math/types.hpp"

namespace asperity {

struct Aabb {
  Vec3f lo = Vec3f::Constant(std::numeric_limits<float>::max());
  Vec3f hi = Vec3f::Constant(-std::numeric_limits<float>::max());

  void grow(const Vec3f& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void grow(const Aabb& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool empty() const { return lo.x() > hi.x(); }
  bool overlaps(const Aabb& b) const {
    return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all();
  }
};

class TriangleBvh {
 public:
  TriangleBvh() = default;
  // Builds the tree (median split along the longest axis, leaves of at most 4 triangles).
  // Triangle indices must address `positions` (not checked here).
  TriangleBvh(std::span<const Vec3f> positions, std::span<const std::array<int, 3>> triangles);

  // Appends to `out` every triangle whose box overlaps `box` (a superset of the triangles that
  // touch it). `out` is not cleared.
  void query(const Aabb& box, std::vector<int>& out) const;

  Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_.front().box; }
  size_t nodeCount() const { return nodes_.size(); }

 private:
  struct Node {
    Aabb box;
    int first = 0;  // leaf: first index into order_; inner: index of the left child
    int count = 0;  // leaf: number of triangles (> 0); inner: 0 (right child = first + 1)
  };
  void build(int index, const std::vector<Vec3f>& centres, int begin, int end);

  std::vector<Node> nodes_;
  std::vector<int> order_;     // triangle indices, leaves own contiguous ranges
  std::vector<Aabb> tri_box_;  // per triangle, tested at the leaves
};

}  // namespace asperity
