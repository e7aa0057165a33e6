// Signed distance fields: values and normals against the analytic distance of a box, the sign
// inside a nut's bore, closedness, and bad input.
#include "collision/signed_distance_field.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "asperity/error.hpp"
#include "collision_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// Exact signed distance to an axis-aligned box of half extents h.
double boxDistance(const Vec3& p, const Vec3& h) {
  const Vec3 q = p.cwiseAbs() - h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

TEST(SignedDistanceField, MatchesTheBoxDistanceNearItsFaces) {
  const Vec3 h(0.1, 0.06, 0.04);
  const auto field = SignedDistanceField::build(*collision_test::boxMesh(h), 40);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double cell = field->cellSize();
  for (int i = 0; i < 300; ++i) {
    // Points within a cell of a face and two cells clear of its edges, where trilinear
    // interpolation is exact. (One draw per statement: the order of evaluation of a
    // constructor's arguments differs between compilers, and the points with it.)
    const int axis = i % 3;
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = u(rng) * (h[k] - 2.0 * cell);
    const double side = u(rng) > 0 ? 1.0 : -1.0;
    p[axis] = side * (h[axis] + 0.9 * cell * u(rng));
    const auto s = field->sample(p);
    ASSERT_TRUE(s.inside_grid);
    EXPECT_TRUE(near(s.distance, boxDistance(p, h), 0, 1e-9)) << p.transpose();
    EXPECT_TRUE(near(std::abs(s.gradient[axis]), 1.0, 0, 1e-6));
    EXPECT_GT(s.gradient[axis] * p[axis], 0);  // outward
    EXPECT_GE(s.triangle, 0);
  }
}

TEST(SignedDistanceField, SignEverywhereAndDistanceFarFromTheSurface) {
  const Vec3 h(0.1, 0.1, 0.1);
  const auto field = SignedDistanceField::build(*collision_test::boxMesh(h), 32);
  // Every node: the sign of the box distance, and its value within a cell.
  for (int k = 0; k < field->nodes(2); ++k) {
    for (int j = 0; j < field->nodes(1); ++j) {
      for (int i = 0; i < field->nodes(0); ++i) {
        const Vec3 x = field->origin() + field->cellSize() * Vec3(i, j, k);
        const double exact = boxDistance(x, h);
        EXPECT_TRUE(near(field->nodeValue(i, j, k), exact, 0, 1e-9)) << x.transpose();
      }
    }
  }
  EXPECT_FALSE(field->sample(Vec3(10, 0, 0)).inside_grid);
}

TEST(SignedDistanceField, NutBoreIsOutside) {
  const auto nut = collision_test::squareNutMesh(0.0035, 0.002, 0.0016);
  EXPECT_TRUE(isClosedMesh(*nut));
  const auto field = SignedDistanceField::build(*nut, 64);
  // In the bore 0.5 mm from its wall, in the wall 0.5 mm deep, outside 0.25 mm away.
  EXPECT_TRUE(near(field->sample(Vec3(0.0015, 0, 0)).distance, 0.0005, 0, 1e-9));
  EXPECT_TRUE(near(field->sample(Vec3(0.0025, 0, 0)).distance, -0.0005, 0, 1e-9));
  EXPECT_TRUE(near(field->sample(Vec3(0.00375, 0, 0)).distance, 0.00025, 0, 1e-9));
  // On the axis and mid-wall (medial ridges) trilinear values are within a third of a cell.
  EXPECT_TRUE(near(field->sample(Vec3::Zero()).distance, 0.002, 0, field->cellSize() / 3));
  EXPECT_TRUE(
      near(field->sample(Vec3(0.00275, 0, 0)).distance, -0.00075, 0, field->cellSize() / 3));
  // Beyond the padding the field says nothing.
  EXPECT_FALSE(field->sample(Vec3(0.005, 0, 0)).inside_grid);
}

TEST(SignedDistanceField, ClosednessAndBadInput) {
  EXPECT_TRUE(isClosedMesh(*collision_test::boxMesh(Vec3::Constant(1))));
  TriangleMeshData open;
  open.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  open.triangles = {{0, 1, 2}};
  EXPECT_FALSE(isClosedMesh(open));
  EXPECT_FALSE(isClosedMesh(TriangleMeshData{}));
  EXPECT_THROW(SignedDistanceField::build(TriangleMeshData{}, 32), Error);
  EXPECT_THROW(SignedDistanceField::build(*collision_test::boxMesh(Vec3::Constant(1)), 3), Error);
}

TEST(SignedDistanceField, VerticesSplitAtUvSeamsAreWeldedForTopology) {
  // Every triangle with its own corners: closed by welded positions, open with one removed.
  const auto nut = collision_test::squareNutMesh(0.0035, 0.002, 0.0016);
  const auto split_nut = collision_test::splitAtFaces(*nut);
  const auto split_box = collision_test::splitAtFaces(*collision_test::boxMesh(Vec3(1, 2, 3)));
  EXPECT_TRUE(isClosedMesh(*split_nut));
  EXPECT_TRUE(isClosedMesh(*split_box));
  TriangleMeshData holed = *split_box;
  holed.triangles.pop_back();
  EXPECT_FALSE(isClosedMesh(holed));
  // Welding maps each split corner back to one index per position (16 corners of the nut).
  std::set<int> used;
  for (const auto& tri : weldedTriangles(*split_nut)) used.insert(tri.begin(), tri.end());
  EXPECT_EQ(used.size(), nut->vertices.size());
  // The field, signs included, is the unsplit mesh's node for node.
  const auto whole = SignedDistanceField::build(*nut, 48);
  const auto split = SignedDistanceField::build(*split_nut, 48);
  ASSERT_EQ(whole->nodes(0), split->nodes(0));
  for (int k = 0; k < whole->nodes(2); ++k) {
    for (int j = 0; j < whole->nodes(1); ++j) {
      for (int i = 0; i < whole->nodes(0); ++i) {
        ASSERT_EQ(whole->nodeValue(i, j, k), split->nodeValue(i, j, k)) << i << " " << j;
      }
    }
  }
  EXPECT_LT(split->sample(Vec3(0.0025, 0, 0)).distance, 0);  // in the wall
  EXPECT_GT(split->sample(Vec3(0.0015, 0, 0)).distance, 0);  // in the bore
}

TEST(SignedDistanceField, ClosestPointOnTriangleRegions) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE((closestPointOnTriangle(Vec3(0.2, 0.2, 1), a, b, c) - Vec3(0.2, 0.2, 0)).norm() <
              1e-15);
  EXPECT_EQ(closestPointOnTriangle(Vec3(-1, -1, 0), a, b, c), a);
  EXPECT_EQ(closestPointOnTriangle(Vec3(2, -1, 0), a, b, c), b);
  EXPECT_TRUE((closestPointOnTriangle(Vec3(0.5, -1, 0), a, b, c) - Vec3(0.5, 0, 0)).norm() < 1e-15);
  EXPECT_TRUE((closestPointOnTriangle(Vec3(1, 1, 0), a, b, c) - Vec3(0.5, 0.5, 0)).norm() < 1e-15);
}

}  // namespace
}  // namespace asperity
