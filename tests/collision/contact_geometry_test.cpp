// Witness points snapped onto the exact primitive surfaces, box faces, phi from witnesses.
#include "collision/contact_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

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

// The separating-axis test that lets a narrowphase skip neighbours, against the boxes' corners
// projected on each of the six face normals: apart exactly when one normal's two intervals of
// corner projections leave more than `gap` between them. Random sizes, turns and offsets around
// touching, plus the pile's case (two aligned cubes side by side, 5 cm apart).
TEST(ContactGeometry, BoxesApartAlongAFaceNormalAsTheirCornersAre) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), size(0.05, 0.5);
  auto random_turn = [&] {
    return Quat(
        Eigen::AngleAxisd(3.2 * unit(rng), Vec3(unit(rng), unit(rng), unit(rng)).normalized()));
  };
  auto corners = [](const Vec3& half, const Mat3& axes, const Vec3& centre) {
    std::vector<Vec3> out;
    for (int k = 0; k < 8; ++k) {
      const Vec3 local((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(),
                       (k & 4) ? half.z() : -half.z());
      out.push_back(centre + axes * local);
    }
    return out;
  };
  int apart = 0, near_touching = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec3 half_a(size(rng), size(rng), size(rng)), half_b(size(rng), size(rng), size(rng));
    const Mat3 axes_a = random_turn().toRotationMatrix(), axes_b = random_turn().toRotationMatrix();
    const Vec3 centre_a(unit(rng), unit(rng), unit(rng));
    const Vec3 centre_b = centre_a + 1.2 * Vec3(unit(rng), unit(rng), unit(rng));
    const double gap = trial % 2 == 0 ? 0.0 : 0.01;
    const auto ca = corners(half_a, axes_a, centre_a), cb = corners(half_b, axes_b, centre_b);
    double widest = -1e300;  // largest gap between the corner intervals over the six normals
    for (const Mat3* axes : {&axes_a, &axes_b}) {
      for (int i = 0; i < 3; ++i) {
        const Vec3 n = axes->col(i);
        double lo_a = 1e300, hi_a = -1e300, lo_b = 1e300, hi_b = -1e300;
        for (const Vec3& p : ca) lo_a = std::min(lo_a, n.dot(p)), hi_a = std::max(hi_a, n.dot(p));
        for (const Vec3& p : cb) lo_b = std::min(lo_b, n.dot(p)), hi_b = std::max(hi_b, n.dot(p));
        widest = std::max(widest, std::max(lo_b - hi_a, lo_a - hi_b));
      }
    }
    if (std::abs(widest - gap) < 1e-9) continue;  // within rounding of the threshold
    near_touching += std::abs(widest - gap) < 0.05;
    const bool expected = widest > gap;
    apart += expected;
    EXPECT_EQ(boxesApart(half_a, axes_a, centre_a, half_b, axes_b, centre_b, gap), expected)
        << "trial " << trial << ", widest gap " << widest;
  }
  // Both answers and the close calls were exercised.
  EXPECT_GT(apart, 400);
  EXPECT_LT(apart, 3600);
  EXPECT_GT(near_touching, 100);
  // The pile: neighbours apart, cubes of a column touching.
  const Vec3 cube(0.1, 0.1, 0.1);
  EXPECT_TRUE(boxesApart(cube, Mat3::Identity(), Vec3::Zero(), cube, Mat3::Identity(),
                         Vec3(0.25, 0, 0), 1e-4));
  EXPECT_FALSE(boxesApart(cube, Mat3::Identity(), Vec3::Zero(), cube, Mat3::Identity(),
                          Vec3(0, 0, 0.1999), 1e-4));
}

}  // namespace
}  // namespace asperity::collision_detail
