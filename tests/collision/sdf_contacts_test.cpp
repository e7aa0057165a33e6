// Surface samples of meshes and signed-distance hits (depth order, spacing, frames).
#include "collision/sdf_contacts.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "collision/primitive_distance.hpp"
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

// The points go through the field's frame two at a time and meet the bounds and a primitive's
// reach in the lanes: the hits must be those of moving and testing each point alone, bit for bit.
TEST(SdfContacts, PointsInLanesGiveTheHitsOfEachPointAlone) {
  const SurfaceSamples samples =
      surfaceSamples(*collision_test::boxMesh(Vec3(0.04, 0.03, 0.05)), 0.004, 100000);
  std::vector<Shape> shapes(3);
  shapes[0].type = ShapeType::Sphere;
  shapes[0].radius = 0.035;
  shapes[1].type = ShapeType::Capsule;
  shapes[1].radius = 0.02, shapes[1].half_height = 0.03;
  shapes[2].type = ShapeType::Cylinder;
  shapes[2].radius = 0.025, shapes[2].half_height = 0.02;
  const Transform field_world{Vec3(0.01, -0.02, 0.03),
                              Quat(Eigen::AngleAxisd(0.7, Vec3(-1, 2, 0.5).normalized()))};
  const Transform points_world{Vec3(0.004, 0.0, -0.003),
                               Quat(Eigen::AngleAxisd(0.4, Vec3(0.2, 1, -1).normalized()))};
  const Transform to_field = field_world.inverse() * points_world;
  for (const Shape& shape : shapes) {
    SdfQuery q;
    q.max_hits = 100000;
    q.max_distance = 0.003;
    const double r = std::max(shape.radius + shape.half_height, shape.radius) + q.max_distance;
    q.bounds = Eigen::AlignedBox3d(Vec3::Constant(-r), Vec3::Constant(r));
    SdfHitBuffers buffers;
    const auto& hits = sdfHits(FieldDistance::primitive(shape, q.max_distance), field_world,
                               samples.points, points_world, q, buffers, &samples.blocks);
    // Each point alone: Transform::apply, then the exact distance.
    std::vector<std::pair<double, int>> alone;
    for (size_t i = 0; i < samples.points.size(); ++i) {
      const Vec3 local = to_field.apply(samples.points[i]);
      const double d = primitiveSample(shape, local).distance;
      if (q.bounds.contains(local) && d < q.max_distance)
        alone.emplace_back(d, static_cast<int>(i));
    }
    std::sort(alone.begin(), alone.end());
    ASSERT_GT(alone.size(), 20u) << static_cast<int>(shape.type);
    ASSERT_LT(alone.size(), samples.points.size() / 2) << static_cast<int>(shape.type);
    ASSERT_EQ(hits.size(), alone.size()) << static_cast<int>(shape.type);
    for (size_t k = 0; k < hits.size(); ++k) {
      EXPECT_EQ(hits[k].vertex, alone[k].second);
      EXPECT_EQ(hits[k].distance, alone[k].first);
      EXPECT_EQ(
          hits[k].point,
          field_world.apply(to_field.apply(samples.points[static_cast<size_t>(hits[k].vertex)])));
    }
  }
}

}  // namespace
}  // namespace asperity::collision_detail
