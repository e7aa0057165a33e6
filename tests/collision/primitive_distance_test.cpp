// Exact primitive signed distances: values and outward gradients inside and outside.
#include "collision/primitive_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"

namespace asperity::collision_detail {
namespace {

using test::near;

Shape primitive(ShapeType type) {
  Shape s;
  s.type = type;
  s.half_extents = Vec3(0.3, 0.2, 0.1);
  s.radius = 0.1;
  s.half_height = 0.2;
  return s;
}

void expectSample(const Shape& s, const Vec3& p, double distance, const Vec3& gradient) {
  const auto r = primitiveSample(s, p);
  ASSERT_TRUE(r.inside_grid);
  EXPECT_TRUE(near(r.distance, distance, 0, 1e-12)) << p.transpose();
  EXPECT_TRUE((r.gradient - gradient).norm() < 1e-12) << r.gradient.transpose();
}

TEST(PrimitiveDistance, Box) {
  const Shape box = primitive(ShapeType::Box);
  expectSample(box, Vec3(0.5, 0, 0), 0.2, Vec3::UnitX());
  expectSample(box, Vec3(0, -0.15, 0), -0.05, -Vec3::UnitY());
  expectSample(box, Vec3(0.1, 0.1, 0.08), -0.02, Vec3::UnitZ());
  expectSample(box, Vec3(0.6, 0.6, 0), 0.5, Vec3(0.6, 0.8, 0));  // edge region: 0.3, 0.4
}

TEST(PrimitiveDistance, SphereCapsuleCylinder) {
  expectSample(primitive(ShapeType::Sphere), Vec3(0, 0.06, 0.08), 0.0, Vec3(0, 0.6, 0.8));
  const Shape capsule = primitive(ShapeType::Capsule);
  expectSample(capsule, Vec3(0.05, 0, 0.1), -0.05, Vec3::UnitX());
  expectSample(capsule, Vec3(0, 0, 0.5), 0.2, Vec3::UnitZ());
  const Shape cylinder = primitive(ShapeType::Cylinder);
  expectSample(cylinder, Vec3(0, 0.3, 0), 0.2, Vec3::UnitY());
  expectSample(cylinder, Vec3(0.05, 0, -0.19), -0.01, -Vec3::UnitZ());
  expectSample(cylinder, Vec3(0, 0.13, 0.24), 0.05, Vec3(0, 0.6, 0.8));  // rim region
  EXPECT_FALSE(hasPrimitiveDistance(ShapeType::Plane));
  EXPECT_FALSE(primitiveSample(primitive(ShapeType::Plane), Vec3::Zero()).inside_grid);
}

TEST(PrimitiveDistance, BeyondOnlyWhereTheDistanceIsAtLeastTheReach) {
  // On a grid of points round each primitive: a point called beyond has at least the reach,
  // and most points at twice the reach or more are called beyond.
  for (const ShapeType type : {ShapeType::Sphere, ShapeType::Capsule, ShapeType::Cylinder}) {
    const Shape shape = primitive(type);
    const double reach = 0.03;
    int far = 0, called = 0;
    for (double x = -0.4; x <= 0.4; x += 0.01)
      for (double z = -0.4; z <= 0.4; z += 0.01) {
        const Vec3 p(x, 0.3 * x, z);
        const double distance = primitiveSample(shape, p).distance;
        const bool beyond = PrimitiveReach(shape, reach).beyond(p);
        if (beyond) {
          EXPECT_GE(distance, reach) << p.transpose();
        }
        far += distance >= 2 * reach;
        called += beyond && distance >= 2 * reach;
      }
    EXPECT_GT(far, 1000);
    EXPECT_EQ(called, far) << static_cast<int>(type);
  }
  EXPECT_FALSE(PrimitiveReach(primitive(ShapeType::Box), 0.0).beyond(Vec3(5, 5, 5)));
  EXPECT_FALSE(PrimitiveReach(primitive(ShapeType::Sphere), -1.0).beyond(Vec3(5, 5, 5)));
  EXPECT_FALSE(PrimitiveReach().beyond(Vec3(5, 5, 5)));
}

}  // namespace
}  // namespace asperity::collision_detail
