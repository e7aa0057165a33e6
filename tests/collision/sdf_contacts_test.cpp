// Surface samples of meshes and signed-distance hits (depth order, spacing, frames).
#include "collision/sdf_contacts.hpp"

#include <gtest/gtest.h>

#include "collision_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity::collision_detail {
namespace {

using test::near;

TEST(SdfContacts, SurfaceSamplesCoverTrianglesAtTheSpacing) {
  const auto box = collision_test::boxMesh(Vec3::Constant(0.5));
  const SurfaceSamples fine = surfaceSamples(*box, 0.1, 100000);
  // Each triangle (legs 1, hypotenuse sqrt 2) is cut 15 times: 136 points, 12 triangles.
  EXPECT_EQ(fine.points.size(), 12u * 136u);
  for (size_t i = 0; i < fine.points.size(); ++i) {
    EXPECT_TRUE(near(fine.points[i].cwiseAbs().maxCoeff(), 0.5, 0, 1e-12));
    EXPECT_GE(fine.triangle[i], 0);
  }
  // A cap on the count coarsens the spacing.
  EXPECT_LE(surfaceSamples(*box, 0.001, 500).points.size(), 500u);
}

TEST(SdfContacts, HitsAreDeepestFirstAndSpreadOut) {
  const auto field = SignedDistanceField::build(*collision_test::boxMesh(Vec3::Constant(0.1)), 32);
  // Query points along x at depths 0 .. 4 mm inside the +z face, 1 cm apart.
  std::vector<Vec3> points;
  for (int i = 0; i < 5; ++i) points.emplace_back(-0.04 + 0.01 * i, 0, 0.1 - 0.001 * i);
  points.emplace_back(0.0, 0, 0.2);  // far outside
  const Transform field_world{Vec3(1, 0, 0), Quat::Identity()};
  SdfQuery q;
  q.max_hits = 3;
  q.min_spacing = 0.015;
  SdfHitBuffers buffers;
  const auto& hits =
      sdfHits(FieldDistance::grid(*field), field_world, points, field_world, q, buffers);
  // Depths 4, 2 and 0 mm... no: the spacing drops the 3 mm and 1 mm neighbours.
  ASSERT_EQ(hits.size(), 3u);
  EXPECT_EQ(hits[0].vertex, 4);
  EXPECT_EQ(hits[1].vertex, 2);
  EXPECT_EQ(hits[2].vertex, 0);
  EXPECT_TRUE(near(hits[0].distance, -0.004, 0, 1e-9));
  EXPECT_TRUE((hits[0].outward - Vec3::UnitZ()).norm() < 1e-9);
  EXPECT_TRUE((hits[0].surface - Vec3(1.0, 0, 0.1)).norm() < 1e-9);
}

TEST(SdfContacts, SkippingBlocksOutsideTheFieldKeepsEveryHit) {
  // A fine box's samples, turned and half inside a smaller box's field: the runs of points
  // outside the field's grid are skipped whole (blocks of nearby points), and the hits are those of
  // testing each point.
  const SurfaceSamples samples =
      surfaceSamples(*collision_test::boxMesh(Vec3::Constant(0.1)), 0.01, 100000);
  ASSERT_EQ(samples.blocks.bounds.size(),
            (samples.points.size() + kSampleBlock - 1) / kSampleBlock);
  ASSERT_EQ(samples.blocks.order.size(), samples.points.size());
  const auto field = SignedDistanceField::build(*collision_test::boxMesh(Vec3::Constant(0.05)), 32);
  const Transform field_world{Vec3(0.02, -0.01, 0.13),
                              Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()))};
  const Transform points_world{Vec3::Zero(), Quat(Eigen::AngleAxisd(-0.2, Vec3::UnitZ()))};
  SdfQuery q;
  q.max_hits = 1000;
  q.max_distance = 0.002;
  const Vec3 span =
      field->cellSize() * Vec3(field->nodes(0) - 1, field->nodes(1) - 1, field->nodes(2) - 1);
  q.bounds = Eigen::AlignedBox3d(field->origin(), field->origin() + span);
  const FieldDistance distance = FieldDistance::grid(*field);
  SdfHitBuffers each_buffers, blocked_buffers;
  const auto& each = sdfHits(distance, field_world, samples.points, points_world, q, each_buffers);
  const auto& blocked = sdfHits(distance, field_world, samples.points, points_world, q,
                                blocked_buffers, &samples.blocks);
  ASSERT_GT(each.size(), 10u);
  ASSERT_EQ(blocked.size(), each.size());
  for (size_t i = 0; i < each.size(); ++i) {
    EXPECT_EQ(blocked[i].vertex, each[i].vertex);
    EXPECT_EQ(blocked[i].distance, each[i].distance);
  }
}

}  // namespace
}  // namespace asperity::collision_detail
