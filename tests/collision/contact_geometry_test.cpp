// Witness points snapped onto the exact primitive surfaces, box faces, phi from witnesses.
#include "collision/contact_geometry.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace asperity::collision_detail {
namespace {

using test::near;

TEST(ContactGeometry, SnapsOntoSpheresCapsulesBoxesAndCylinders) {
  const Transform world{Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(0.4, Vec3::UnitZ()))};
  Shape s;
  s.type = ShapeType::Sphere;
  s.radius = 0.5;
  EXPECT_TRUE((snapToSurface(s, world, Vec3::Zero(), -Vec3::UnitZ()) - Vec3(1, 2, 2.5)).norm() <
              1e-15);
  // Capsule along local z: the core point below the witness, pushed out by the radius.
  s.type = ShapeType::Capsule;
  s.half_height = 1.0;
  const Vec3 side = world.apply(Vec3(0.45, 0, 0.3));
  const Vec3 out = world.rotation * Vec3::UnitX();
  EXPECT_TRUE((snapToSurface(s, world, side, out) - world.apply(Vec3(0.5, 0, 0.3))).norm() < 1e-12);
  // Box: a point just inside the +y face goes onto it; one outside is clamped.
  s.type = ShapeType::Box;
  s.half_extents = Vec3(1, 0.5, 0.25);
  EXPECT_TRUE((snapToSurface(s, world, world.apply(Vec3(0.2, 0.49, 0)), out) -
               world.apply(Vec3(0.2, 0.5, 0)))
                  .norm() < 1e-12);
  EXPECT_TRUE(
      (snapToSurface(s, world, world.apply(Vec3(2, 0, 0)), out) - world.apply(Vec3(1, 0, 0)))
          .norm() < 1e-12);
  // Cylinder: a point rounded inside near the bottom rim goes onto the cap.
  s.type = ShapeType::Cylinder;
  s.radius = 0.3;
  s.half_height = 0.2;
  EXPECT_TRUE((snapToSurface(s, world, world.apply(Vec3(0.29, 0, -0.199)), out) -
               world.apply(Vec3(0.29, 0, -0.2)))
                  .norm() < 1e-12);
}

TEST(ContactGeometry, BoxFacesAndFinishedPlaneContact) {
  const Transform yawed{Vec3::Zero(), Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()))};
  EXPECT_EQ(boxFace(yawed, Vec3::UnitY()), 0);   // local +x faces world +y
  EXPECT_EQ(boxFace(yawed, -Vec3::UnitZ()), 5);  // local -z
  // A box corner 1 mm into a plane: phi, point, faces and the plane's exact normal.
  Shape box, plane;
  box.type = ShapeType::Box;
  plane.type = ShapeType::Plane;
  Contact c;
  c.normal = Vec3(1e-4, 0, 1).normalized();
  c.witness_a = Vec3(0.1, 0.1, -0.001);
  c.witness_b = Vec3(0.1, 0.1, 0.0);
  finishContact(c, box, Transform{Vec3(0, 0, 0.099), Quat::Identity()}, plane, Transform{});
  EXPECT_EQ(c.normal, Vec3::UnitZ());
  EXPECT_TRUE(near(c.phi, 0.001, 0, 1e-15));
  EXPECT_TRUE((c.point - Vec3(0.1, 0.1, -0.0005)).norm() < 1e-15);
  EXPECT_EQ(c.feature_a, 5);
}

}  // namespace
}  // namespace asperity::collision_detail
