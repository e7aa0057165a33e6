// Boxes, capsules and spheres against a cylinder's side: radial normals, exact depths, two
// points along a flat face, and the cases left to the general narrowphase.
#include "collision/cylinder_contacts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// The chain bolas' link (5 x 25 x 40 mm) on a rod of radius 19.5 mm along world y.
constexpr double kLinkRod = 0.0195;
const Vec3 kLinkHalf(0.0025, 0.0125, 0.02);
Shape linkRod() {
  Shape s = rod();
  s.radius = kLinkRod;
  return s;
}

// The link's thin axis (local x) up, its width (local y) along the rod, its length (local z)
// across it; then turned `yaw` about the vertical, `roll` about its length and `turn` about
// the rod's axis.
Quat linkTurn(double yaw, double roll, double turn) {
  Mat3 base;
  base << Vec3::UnitZ(), Vec3::UnitY(), -Vec3::UnitX();
  const Quat q = Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ())) * Quat(base);
  return Quat(Eigen::AngleAxisd(turn, Vec3::UnitY())) *
         Quat(Eigen::AngleAxisd(roll, q * Vec3::UnitZ())) * q;
}

// Distance from the rod's axis (world y) to a point.
double fromAxis(const Vec3& p) {
  return std::hypot(p.x(), p.z());
}

// Brute force: the box's least distance from the axis, over a 0.5 mm grid on its faces and
// 10 micrometre steps along its edges (a flat face's nearest line is within 0.25 mm of a grid
// row: 1.6 micrometres of depth on this rod; an edge's nearest point within 5 micrometres of
// a step: nothing measurable).
double leastFromAxis(const Transform& world) {
  double least = 1e9;
  const Vec3& h = kLinkHalf;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    for (double sign : {-1.0, 1.0}) {
      const int na = static_cast<int>(std::ceil(2 * h[a] / 0.0005));
      const int nb = static_cast<int>(std::ceil(2 * h[b] / 0.0005));
      for (int i = 0; i <= na; ++i) {
        for (int j = 0; j <= nb; ++j) {
          Vec3 l;
          l[k] = sign * h[k], l[a] = -h[a] + 2 * h[a] * i / na, l[b] = -h[b] + 2 * h[b] * j / nb;
          least = std::min(least, fromAxis(world.apply(l)));
        }
      }
      for (double sign_b : {-1.0, 1.0}) {  // the four edges along axis a
        const int n = static_cast<int>(std::ceil(2 * h[a] / 1e-5));
        for (int i = 0; i <= n; ++i) {
          Vec3 l;
          l[k] = sign * h[k], l[b] = sign_b * h[b], l[a] = -h[a] + 2 * h[a] * i / n;
          least = std::min(least, fromAxis(world.apply(l)));
        }
      }
    }
  }
  return least;
}

// The link lowered onto the rod until its deepest point is `depth` inside (bisection on the
// brute-force distance).
Transform linkOnRod(const Quat& q, double along, double depth) {
  double lo = 0.0, hi = 0.1;
  for (int i = 0; i < 32; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kLinkRod - leastFromAxis(Transform{Vec3(0, along, mid), q}) > depth ? lo : hi) = mid;
  }
  return Transform{Vec3(0, along, 0.5 * (lo + hi)), q};
}

// A face lying along the rod touches it along a line: two points, at that line's ends on the
// face, each as deep as the link is, with the face's own normal. Over yaws from across the rod
// (0) to along it (90 degrees) and turns about the rod that move the line off the face's
// middle. The line's ends come from stepping along it in 1 micrometre steps.
TEST(CylinderContacts, FlatLinkOnTheRodGetsTheEndsOfTheLineItTouchesAlong) {
  for (double yaw_deg : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0}) {
    for (double turn_deg : {-20.0, 0.0, 12.0}) {
      const Quat q = linkTurn(yaw_deg * kPi / 180, 0.0, turn_deg * kPi / 180);
      const Transform link = linkOnRod(q, 0.1, 0.0005);
      std::vector<CylinderSidePoint> pts;
      ASSERT_TRUE(cylinderSidePoints(linkRod(), kRodWorld, box(kLinkHalf), link, 0.0, pts));
      ASSERT_EQ(pts.size(), 2u) << yaw_deg << " deg yaw, " << turn_deg << " deg turn";
      // The face's inward normal and the line: where the face's plane is nearest the axis.
      const Vec3 up = q * Vec3::UnitX();
      const Vec3 face_centre = link.position - kLinkHalf.x() * up;
      const double plane = face_centre.dot(up);  // the plane's distance from the axis
      const Vec3 foot = plane * up;              // the line passes here, along y
      double lo = 1e9, hi = -1e9;
      for (double y = link.position.y() - 0.03; y <= link.position.y() + 0.03; y += 1e-6) {
        const Vec3 l = link.applyInverse(foot + Vec3(0, y, 0));
        if (std::abs(l.y()) <= kLinkHalf.y() && std::abs(l.z()) <= kLinkHalf.z())
          lo = std::min(lo, y), hi = std::max(hi, y);
      }
      std::vector<double> ys;
      for (const CylinderSidePoint& p : pts) {
        EXPECT_NEAR(p.depth, 0.0005, 2e-6) << yaw_deg << " deg yaw, " << turn_deg << " turn";
        EXPECT_NEAR((p.normal - up).norm(), 0.0, 1e-9);
        EXPECT_NEAR((p.on_shape - foot).cross(Vec3::UnitY()).norm(), 0.0, 1e-9);
        ys.push_back(p.on_shape.y());
      }
      std::sort(ys.begin(), ys.end());
      EXPECT_NEAR(ys[0], lo, 2e-6) << yaw_deg << " deg yaw, " << turn_deg << " deg turn";
      EXPECT_NEAR(ys[1], hi, 2e-6) << yaw_deg << " deg yaw, " << turn_deg << " deg turn";
    }
  }
}

// A link lying along the rod on one of its long edges (rolled 30 to 60 degrees about its
// length) touches along that edge: two points at its ends, 40 mm apart, as deep as the link.
TEST(CylinderContacts, LinkOnAnEdgeAlongTheRodGetsThatEdgesEnds) {
  for (double roll_deg : {30.0, 45.0, 60.0}) {
    const Transform link = linkOnRod(linkTurn(kPi / 2, roll_deg * kPi / 180, 0.0), -0.05, 0.0005);
    std::vector<CylinderSidePoint> pts;
    ASSERT_TRUE(cylinderSidePoints(linkRod(), kRodWorld, box(kLinkHalf), link, 0.0, pts));
    ASSERT_EQ(pts.size(), 2u) << roll_deg << " deg roll";
    for (const CylinderSidePoint& p : pts) EXPECT_NEAR(p.depth, 0.0005, 2e-6) << roll_deg;
    EXPECT_NEAR(std::abs(pts[0].on_shape.y() - pts[1].on_shape.y()), 0.04, 1e-9) << roll_deg;
  }
}

// However the link lies (yaw, roll about its length, turn about the rod), the deepest point it
// gets is as deep as the link is (brute force over its surface), every point lies on the
// link's surface, and every normal is radial.
TEST(CylinderContacts, DeepestPointOfALinkIsTheLinksDepthAtAnyPose) {
  for (double yaw_deg : {0.0, 30.0, 60.0, 90.0}) {
    for (double roll_deg : {0.0, 15.0, 35.0}) {
      for (double turn_deg : {-15.0, 8.0}) {
        const Quat q = linkTurn(yaw_deg * kPi / 180, roll_deg * kPi / 180, turn_deg * kPi / 180);
        const Transform link = linkOnRod(q, 0.0, 0.0004);
        std::vector<CylinderSidePoint> pts;
        ASSERT_TRUE(cylinderSidePoints(linkRod(), kRodWorld, box(kLinkHalf), link, 0.0, pts));
        ASSERT_FALSE(pts.empty());
        double deepest = -1.0;
        for (const CylinderSidePoint& p : pts) {
          deepest = std::max(deepest, p.depth);
          EXPECT_LT(axialPart(p.normal), 1e-9);
          const Vec3 l = link.applyInverse(p.on_shape);
          EXPECT_NEAR((l.cwiseAbs() - kLinkHalf).maxCoeff(), 0.0, 1e-9);
          EXPECT_LE((l.cwiseAbs() - kLinkHalf).maxCoeff(), 1e-9);
        }
        EXPECT_NEAR(deepest, 0.0004, 2e-6)
            << yaw_deg << " deg yaw, " << roll_deg << " deg roll, " << turn_deg << " deg turn";
      }
    }
  }
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
