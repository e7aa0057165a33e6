// AABB tree over triangles (bvh.hpp).
#include "geometry/bvh.hpp"

#include <algorithm>

namespace asperity {

namespace {

constexpr int kLeafSize = 4;

}  // namespace

TriangleBvh::TriangleBvh(std::span<const Vec3f> positions,
                         std::span<const std::array<int, 3>> triangles) {
  // Per-triangle boxes and centroids, then the recursive split.
  const int n = static_cast<int>(triangles.size());
  tri_box_.resize(static_cast<size_t>(n));
  std::vector<Vec3f> centres(static_cast<size_t>(n));
  order_.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    Aabb box;
    for (int k : triangles[static_cast<size_t>(i)]) box.grow(positions[static_cast<size_t>(k)]);
    tri_box_[static_cast<size_t>(i)] = box;
    centres[static_cast<size_t>(i)] = 0.5f * (box.lo + box.hi);
    order_[static_cast<size_t>(i)] = i;
  }
  if (n == 0) return;
  nodes_.reserve(static_cast<size_t>(4 * n / kLeafSize + 1));
  nodes_.emplace_back();
  build(0, centres, 0, n);
}

void TriangleBvh::build(int index, const std::vector<Vec3f>& centres, int begin, int end) {
  // This node's box over its range of triangles.
  Aabb box, centre_box;
  for (int i = begin; i < end; ++i) {
    const auto tri = static_cast<size_t>(order_[static_cast<size_t>(i)]);
    box.grow(tri_box_[tri]);
    centre_box.grow(centres[tri]);
  }
  nodes_[static_cast<size_t>(index)].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[static_cast<size_t>(index)].first = begin;
    nodes_[static_cast<size_t>(index)].count = end - begin;
    return;
  }
  // Median split of the centroids along the longest axis; the children are stored as a pair.
  int axis = 0;
  (centre_box.hi - centre_box.lo).maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(
      order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](int a, int b) {
        return centres[static_cast<size_t>(a)][axis] < centres[static_cast<size_t>(b)][axis];
      });
  const int left = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[static_cast<size_t>(index)].first = left;
  build(left, centres, begin, mid);
  build(left + 1, centres, mid, end);
}

void TriangleBvh::query(const Aabb& box, std::vector<int>& out) const {
  if (nodes_.empty()) return;
  // Depth-first with a small explicit stack (depth stays below 64 for any mesh that fits).
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<size_t>(stack[--top])];
    if (!node.box.overlaps(box)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int tri = order_[static_cast<size_t>(i)];
        if (tri_box_[static_cast<size_t>(tri)].overlaps(box)) out.push_back(tri);
      }
      continue;
    }
    stack[top++] = node.first;
    stack[top++] = node.first + 1;
  }
}

}  // namespace asperity
