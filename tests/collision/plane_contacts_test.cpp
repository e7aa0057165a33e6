// Convex shapes against planes: candidate points and the reduction to four spread points.
#include "collision/plane_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"

namespace asperity::collision_detail {
namespace {

using test::near;

Shape cylinder(double r, double hh) {
  Shape s;
  s.type = ShapeType::Cylinder;
  s.radius = r;
  s.half_height = hh;
  return s;
}

TEST(PlaneContacts, WorldPlaneOfATiltedOffsetPlane) {
  Shape plane;
  plane.type = ShapeType::Plane;
  plane.plane_normal = Vec3(0, 0, 2);  // normalised on use
  plane.plane_offset = 0.5;
  const Transform world{Vec3(0, 0, 1), Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()))};
  const WorldPlane p = worldPlane(plane, world);
  EXPECT_TRUE((p.normal - Vec3(0, -1, 0)).norm() < 1e-12);
  // The plane passes through world (0, -0.5, 1).
  EXPECT_TRUE(near(p.offset, 0.5, 0, 1e-12));
}

TEST(PlaneContacts, CylinderLyingTouchesAtBothRimEnds) {
  const Transform world{Vec3(0, 0, 0.049), Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()))};
  PlaneScratch scratch;
  const auto& pts = planePoints(cylinder(0.05, 0.1), world, WorldPlane{}, 0.0, scratch);
  ASSERT_EQ(pts.size(), 2u);
  for (const PlanePoint& p : pts) {
    EXPECT_TRUE(near(p.distance, -0.001, 0, 1e-12));
    EXPECT_TRUE(near(std::abs(p.point.x()), 0.1, 0, 1e-12));
  }
}

TEST(PlaneContacts, TiltedCylinderTouchesAtItsLowestRimPoint) {
  const double tilt = 0.2, r = 0.05, hh = 0.1;
  // Lowest rim point at z = center - hh cos(tilt) - r sin(tilt).
  const double z = hh * std::cos(tilt) + r * std::sin(tilt) - 0.002;
  const Transform world{Vec3(0, 0, z), Quat(Eigen::AngleAxisd(tilt, Vec3::UnitX()))};
  PlaneScratch scratch;
  const auto& pts = planePoints(cylinder(r, hh), world, WorldPlane{}, 0.0, scratch);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_TRUE(near(pts[0].distance, -0.002, 0, 1e-12));
}

TEST(PlaneContacts, ManyCoplanarVerticesReduceToFourSpreadOnes) {
  // A 32-gon prism's bottom face on the plane: keep 4 points spanning most of the disc.
  auto mesh = std::make_shared<TriangleMeshData>();
  for (int i = 0; i < 32; ++i) {
    const double a = 2 * kPi * i / 32;
    for (double z : {-0.1, 0.1}) mesh->vertices.emplace_back(std::cos(a), std::sin(a), z);
  }
  Shape hull;
  hull.type = ShapeType::ConvexHull;
  hull.mesh = mesh;
  PlaneScratch scratch;
  const auto& pts =
      planePoints(hull, Transform{Vec3(0, 0, 0.099), Quat::Identity()}, WorldPlane{}, 0.0, scratch);
  ASSERT_EQ(pts.size(), 4u);
  // The quadrilateral covers at least 90% of the largest one inscribed (a square of area 2).
  Eigen::Matrix<double, 2, 4> xy;
  for (int i = 0; i < 4; ++i) xy.col(i) = pts[static_cast<size_t>(i)].point.head<2>();
  double best = 0;
  int order[4] = {0, 1, 2, 3};
  do {
    double area = 0;
    for (int i = 0; i < 4; ++i) {
      const Vec2 a = xy.col(order[i]), b = xy.col(order[(i + 1) % 4]);
      area += a.x() * b.y() - a.y() * b.x();
    }
    best = std::max(best, 0.5 * std::abs(area));
  } while (std::next_permutation(order + 1, order + 4));
  EXPECT_GT(best, 0.9 * 2.0);
}

}  // namespace
}  // namespace asperity::collision_detail
