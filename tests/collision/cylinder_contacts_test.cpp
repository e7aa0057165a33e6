// Boxes, capsules and spheres against a cylinder's side: radial normals, exact depths, two
// points along a flat face, and the cases left to the general narrowphase.
#include "collision/cylinder_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace asperity::collision_detail {
namespace {

// A rod along world y through the origin, radius 20 mm, 1 m long.
Shape rod() {
  Shape s;
  s.type = ShapeType::Cylinder;
  s.radius = 0.02;
  s.half_height = 0.5;
  return s;
}
const Transform kRodWorld{Vec3::Zero(), Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitX()))};

Shape box(const Vec3& h) {
  Shape s;
  s.type = ShapeType::Box;
  s.half_extents = h;
  return s;
}

double axialPart(const Vec3& n) {
  return std::abs(n.y());
}

TEST(CylinderContacts, FlatPlateOnTopGetsTwoRadialPointsAtItsEdgesAlongTheAxis) {
  // A 5 mm plate, 25 mm along the rod, 40 mm across, 0.5 mm into the rod's top.
  const Transform plate{Vec3(0, 0.2, 0.02 + 0.0025 - 0.0005), Quat::Identity()};
  std::vector<CylinderSidePoint> pts;
  ASSERT_TRUE(
      cylinderSidePoints(rod(), kRodWorld, box(Vec3(0.02, 0.0125, 0.0025)), plate, 0.0, pts));
  ASSERT_EQ(pts.size(), 2u);
  for (const CylinderSidePoint& p : pts) {
    EXPECT_NEAR(p.depth, 0.0005, 1e-9);
    EXPECT_NEAR((p.normal - Vec3::UnitZ()).norm(), 0.0, 1e-9);
    EXPECT_NEAR(p.on_cylinder.z(), 0.02, 1e-9);
  }
  // At the plate's two edges along the rod.
  EXPECT_NEAR(std::abs(pts[0].on_shape.y() - pts[1].on_shape.y()), 0.025, 1e-6);
}

TEST(CylinderContacts, NormalsStayRadialForAPlateTiltedAlongTheAxis) {
  // The plate tilted 0.3 rad about x: its low edge touches; the normal has no axial part.
  const Transform plate{Vec3(0, 0, 0.022), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX()))};
  std::vector<CylinderSidePoint> pts;
  ASSERT_TRUE(
      cylinderSidePoints(rod(), kRodWorld, box(Vec3(0.02, 0.0125, 0.0025)), plate, 0.0, pts));
  ASSERT_FALSE(pts.empty());
  for (const CylinderSidePoint& p : pts) {
    EXPECT_LT(axialPart(p.normal), 1e-9);
    EXPECT_GT(p.depth, 0.0);
    // The depth is the shape's point's distance inside the side surface.
    EXPECT_NEAR(p.depth, 0.02 - Vec2(p.on_shape.x(), p.on_shape.z()).norm(), 1e-9);
  }
}

TEST(CylinderContacts, SphereAndCapsuleGetExactDepths) {
  Shape sphere;
  sphere.type = ShapeType::Sphere;
  sphere.radius = 0.01;
  std::vector<CylinderSidePoint> pts;
  // Sphere below-beside the rod, 1 mm in, at 30 degrees below the horizontal.
  const Vec3 dir(std::cos(-0.5), 0, std::sin(-0.5));
  ASSERT_TRUE(cylinderSidePoints(rod(), kRodWorld, sphere,
                                 Transform{0.029 * dir + Vec3(0, 0.1, 0), Quat::Identity()}, 0.0,
                                 pts));
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_NEAR(pts[0].depth, 0.001, 1e-9);
  EXPECT_NEAR((pts[0].normal - dir).norm(), 0.0, 1e-9);
  // A capsule lying along the rod on top: two points, 1 mm deep, at its core's ends.
  Shape capsule;
  capsule.type = ShapeType::Capsule;
  capsule.radius = 0.005;
  capsule.half_height = 0.02;
  const Transform along{Vec3(0, 0, 0.024), Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitX()))};
  ASSERT_TRUE(cylinderSidePoints(rod(), kRodWorld, capsule, along, 0.0, pts));
  ASSERT_EQ(pts.size(), 2u);
  for (const CylinderSidePoint& p : pts) EXPECT_NEAR(p.depth, 0.001, 1e-9);
  EXPECT_GT(std::abs(pts[0].on_shape.y() - pts[1].on_shape.y()), 0.03);
}

TEST(CylinderContacts, ApartGivesNoPointsCapsAndCrossingAxisGoElsewhere) {
  std::vector<CylinderSidePoint> pts;
  const Shape b = box(Vec3(0.01, 0.01, 0.01));
  // 5 mm above the rod: handled, no points.
  EXPECT_TRUE(cylinderSidePoints(rod(), kRodWorld, b,
                                 Transform{Vec3(0, 0, 0.035), Quat::Identity()}, 0.0, pts));
  EXPECT_TRUE(pts.empty());
  // Within reach: one gap point with a negative depth.
  EXPECT_TRUE(cylinderSidePoints(rod(), kRodWorld, b,
                                 Transform{Vec3(0, 0, 0.035), Quat::Identity()}, 0.01, pts));
  ASSERT_FALSE(pts.empty());
  EXPECT_NEAR(pts[0].depth, -0.005, 1e-9);
  // Beyond the rod's end, touching its rim: not the side.
  EXPECT_FALSE(cylinderSidePoints(rod(), kRodWorld, b,
                                  Transform{Vec3(0, 0.515, 0.024), Quat::Identity()}, 0.0, pts));
  // A long box the axis passes through: not the side.
  EXPECT_FALSE(cylinderSidePoints(rod(), kRodWorld, box(Vec3(0.05, 0.05, 0.05)),
                                  Transform{Vec3(0, 0.1, 0), Quat::Identity()}, 0.0, pts));
}

}  // namespace
}  // namespace asperity::collision_detail
