// The triangle BVH returns exactly what a brute-force box test returns.
#include "geometry/bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace asperity {
namespace {

TEST(TriangleBvh, QueryMatchesBruteForce) {
  // A random soup of small triangles in the unit cube.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), small(-0.02f, 0.02f);
  std::vector<Vec3f> positions;
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i < 2000; ++i) {
    const Vec3f c(unit(rng), unit(rng), unit(rng));
    const int base = static_cast<int>(positions.size());
    for (int k = 0; k < 3; ++k) positions.push_back(c + Vec3f(small(rng), small(rng), small(rng)));
    triangles.push_back({base, base + 1, base + 2});
  }
  const TriangleBvh bvh(positions, triangles);
  EXPECT_GT(bvh.nodeCount(), 500u);
  // Random query boxes: same triangle sets as testing every triangle.
  for (int q = 0; q < 50; ++q) {
    Aabb box;
    box.grow(Vec3f(unit(rng), unit(rng), unit(rng)));
    box.grow(Vec3f(box.lo + Vec3f::Constant(0.1f * unit(rng))));
    std::vector<int> got;
    bvh.query(box, got);
    std::vector<int> want;
    for (size_t t = 0; t < triangles.size(); ++t) {
      Aabb tb;
      for (int k : triangles[t]) tb.grow(positions[static_cast<size_t>(k)]);
      if (tb.overlaps(box)) want.push_back(static_cast<int>(t));
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want) << "query " << q;
  }
}

TEST(TriangleBvh, EmptyMeshFindsNothing) {
  const TriangleBvh bvh({}, {});
  std::vector<int> out;
  Aabb box;
  box.grow(Vec3f::Zero());
  bvh.query(box, out);
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(bvh.bounds().empty());
}

}  // namespace
}  // namespace asperity
