// Collision stage: contact counts, normals (B to A), depths and witness points against the
// analytic geometry of resting shapes, from metres down to millimetres; keys, order, filters.
#include "collision/collision_detector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "asperity/error.hpp"
#include "collision_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;
using namespace collision_test;

// Contacts of one detect call on a fresh detector.
std::vector<Contact> detectOnce(const std::vector<Body>& bodies, CollisionSettings settings = {}) {
  CollisionDetector detector;
  detector.setBodies(bodies, settings);
  return detector.detect(bodies);
}

// The four corners of a box resting on the ground plane, penetrating by `depth`, at any yaw.
void expectBoxOnPlane(double half, double depth, double yaw, const Vec3& at, double tol) {
  const std::vector<Body> bodies = {
      groundPlane(), boxBody(Vec3::Constant(half), at + Vec3(0, 0, half - depth), yaw)};
  const auto contacts = detectOnce(bodies);
  ASSERT_EQ(contacts.size(), 4u) << "half " << half << " yaw " << yaw;
  std::set<std::pair<long, long>> corners;
  for (const Contact& c : contacts) {
    // The dynamic box is A, the ground B; n from B to A is +z.
    EXPECT_EQ(c.body_a, 1u);
    EXPECT_EQ(c.body_b, 0u);
    EXPECT_EQ(c.shape_a, 0);
    EXPECT_EQ(c.shape_b, 0);
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-9));
    EXPECT_TRUE(near(c.phi, depth, 0, tol));
    // Witness points: a corner of the box and its projection onto the plane.
    EXPECT_TRUE(near(c.witness_a.z(), at.z() - depth, 0, tol));
    EXPECT_TRUE(near(c.witness_b.z(), at.z(), 0, tol));
    const Vec3 local = Eigen::AngleAxisd(-yaw, Vec3::UnitZ()) * (c.witness_a - at);
    EXPECT_TRUE(near(std::abs(local.x()), half, 0, tol));
    EXPECT_TRUE(near(std::abs(local.y()), half, 0, tol));
    EXPECT_TRUE((c.point - 0.5 * (c.witness_a + c.witness_b)).norm() < 1e-12);
    EXPECT_EQ(c.feature_a, 5);  // the box's -z face
    corners.insert({std::lround(local.x() / half), std::lround(local.y() / half)});
  }
  EXPECT_EQ(corners.size(), 4u);
}

TEST(CollisionDetector, BoxRestsOnPlaneWithFourCornerContacts) {
  for (double yaw : {0.0, 0.3, kPi / 4, 1.0, 2.5})
    expectBoxOnPlane(0.1, 1e-3, yaw, Vec3::Zero(), 1e-6);
}

TEST(CollisionDetector, MillimetreBoxOnPlaneAwayFromTheOrigin) {
  // An M4-nut-sized cube (4 mm) penetrating 10 um, half a metre from the origin.
  expectBoxOnPlane(0.002, 1e-5, 0.2, Vec3(0.5, -0.3, 0), 1e-6);
  expectBoxOnPlane(0.002, 2e-4, 0.0, Vec3::Zero(), 1e-6);
}

TEST(CollisionDetector, MillimetreBoxStack) {
  // Two 4 mm cubes, the upper one 10 um into the lower, away from the origin.
  const double h = 0.002, d = 1e-5;
  const Vec3 at(0.3, 0.2, 0.1);
  const auto contacts =
      detectOnce({boxBody(Vec3::Constant(h), at, 0.0),
                  boxBody(Vec3::Constant(h), at + Vec3(0.0003, 0, 2 * h - d), 0.3)});
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-7));
    EXPECT_TRUE(near(c.normal.z(), -1.0, 0, 1e-6));
    EXPECT_TRUE(near(c.point.z(), at.z() + h - d / 2, 0, 1e-7));
  }
}

TEST(CollisionDetector, MillimetrePrimitivesOnABox) {
  // Half-millimetre radii, 10 um deep: Bullet's GJK works in scaled units (bulletScale).
  const double r = 5e-4, hh = 1e-3, d = 1e-5;
  const Body table = boxBody(Vec3(0.01, 0.01, 0.001), Vec3(0, 0, -0.001), 0.0, BodyType::Static);
  const Quat lying(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
  const std::vector<Body> bodies[] = {
      {table, sphereBody(r, Vec3(0.001, 0, r - d))},
      {table, capsuleBody(r, hh, Vec3(0, 0, r - d), lying)},
      {table, cylinderBody(r, hh, Vec3(0, 0, hh - d), Quat::Identity())},
      {table, cylinderBody(r, hh, Vec3(0, 0, r - d), lying)}};
  for (const auto& scene : bodies) {
    const auto contacts = detectOnce(scene);
    ASSERT_GE(contacts.size(), 1u) << scene[1].shapes[0].radius;
    for (const Contact& c : contacts) {
      EXPECT_TRUE(near(c.phi, d, 0, 1e-8));
      EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-6));
      EXPECT_TRUE(near(c.witness_a.z(), -d, 0, 1e-8));
      EXPECT_TRUE(near(c.witness_b.z(), 0.0, 0, 1e-8));
    }
  }
}

TEST(CollisionDetector, KinematicBodyIsB) {
  // A kinematic box under a dynamic sphere with the higher id: the sphere is still A.
  const Body platform = boxBody(Vec3(1, 1, 0.1), Vec3(0, 0, -0.1), 0.0, BodyType::Kinematic);
  const auto contacts =
      detectOnce({sphereBody(0.1, Vec3(2, 0, 0.5)), platform, sphereBody(0.1, Vec3(0, 0, 0.098))});
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].body_a, 2u);
  EXPECT_EQ(contacts[0].body_b, 1u);
  EXPECT_TRUE(near(contacts[0].normal.z(), 1.0, 0, 1e-6));
  EXPECT_TRUE(near(contacts[0].phi, 0.002, 0, 1e-7));
  EXPECT_EQ(contacts[0].feature_b, 4);  // the platform's +z face
}

TEST(CollisionDetector, SphereOnPlaneHasOneContactWithDepthRadiusMinusHeight) {
  const double r = 0.1, height = 0.093;
  const std::vector<Body> bodies = {groundPlane(), sphereBody(r, Vec3(0.2, 0.1, height))};
  const auto contacts = detectOnce(bodies);
  ASSERT_EQ(contacts.size(), 1u);
  const Contact& c = contacts[0];
  EXPECT_TRUE(near(c.phi, r - height, 0, 1e-9));
  EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-9));
  EXPECT_TRUE((c.witness_a - Vec3(0.2, 0.1, height - r)).norm() < 1e-6);
  EXPECT_TRUE((c.witness_b - Vec3(0.2, 0.1, 0)).norm() < 1e-6);
  EXPECT_EQ(c.feature_a, -1);
}

TEST(CollisionDetector, SeparatedShapesGiveNoContacts) {
  const std::vector<Body> bodies = {groundPlane(), sphereBody(0.1, Vec3(0, 0, 0.1005)),
                                    boxBody(Vec3::Constant(0.1), Vec3(1, 0, 0.1002), 0.0)};
  EXPECT_TRUE(detectOnce(bodies).empty());
}

TEST(CollisionDetector, SphereSphereDepthAndNormal) {
  // Two dynamic spheres: the lower id is A, n points from B (id 1) to A (id 0).
  const Vec3 ca(0, 0, 1), cb(0.15, 0.05, 1.02);
  const std::vector<Body> bodies = {sphereBody(0.1, ca), sphereBody(0.08, cb)};
  const auto contacts = detectOnce(bodies);
  ASSERT_EQ(contacts.size(), 1u);
  const Contact& c = contacts[0];
  EXPECT_EQ(c.body_a, 0u);
  const Vec3 n = (ca - cb).normalized();
  EXPECT_TRUE(near(c.normal.dot(n), 1.0, 0, 1e-6));
  EXPECT_TRUE(near(c.phi, 0.18 - (ca - cb).norm(), 0, 1e-6));
  EXPECT_TRUE((c.witness_a - (ca - 0.1 * n)).norm() < 1e-6);
  EXPECT_TRUE((c.witness_b - (cb + 0.08 * n)).norm() < 1e-6);
}

TEST(CollisionDetector, BoxStackGivesFourContactsPerInterface) {
  // Ground, box 1 on it, box 2 on box 1 (each penetrating 1 mm).
  const double h = 0.1, d = 1e-3;
  const std::vector<Body> bodies = {groundPlane(), boxBody(Vec3::Constant(h), Vec3(0, 0, h - d), 0),
                                    boxBody(Vec3::Constant(h), Vec3(0.01, 0, 3 * h - 2 * d), 0.1)};
  const auto contacts = detectOnce(bodies);
  int ground = 0, stacked = 0;
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, d, 0, 2e-6));
    if (c.body_b == 0) {
      ++ground;
      EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-9));
    } else {
      // Both dynamic: A = box 1 (lower id) below, so n from the upper box B points down.
      ++stacked;
      EXPECT_EQ(c.body_a, 1u);
      EXPECT_EQ(c.body_b, 2u);
      EXPECT_TRUE(near(c.normal.z(), -1.0, 0, 1e-5));
      EXPECT_TRUE(near(c.witness_a.z(), 2 * h - d, 0, 2e-6));
      EXPECT_EQ(c.feature_a, 4);  // lower box's +z face
      EXPECT_EQ(c.feature_b, 5);  // upper box's -z face
    }
  }
  EXPECT_EQ(ground, 4);
  EXPECT_EQ(stacked, 4);
}

TEST(CollisionDetector, CapsuleLyingAndStandingOnPlane) {
  const double r = 0.05, hh = 0.1, d = 2e-3;
  // Lying along x: contacts under the core segment, all at depth d.
  const Quat lying(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
  const auto lying_contacts =
      detectOnce({groundPlane(), capsuleBody(r, hh, Vec3(0, 0, r - d), lying)});
  ASSERT_GE(lying_contacts.size(), 2u);
  double min_x = 1, max_x = -1;
  for (const Contact& c : lying_contacts) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-6));
    EXPECT_TRUE(near(c.witness_a.z(), -d, 0, 1e-6));
    min_x = std::min(min_x, c.witness_a.x()), max_x = std::max(max_x, c.witness_a.x());
  }
  EXPECT_GT(max_x - min_x, hh);  // spread along the segment, not one point
  // Standing: one contact under the lower cap.
  const auto standing =
      detectOnce({groundPlane(), capsuleBody(r, hh, Vec3(0, 0, hh + r - d), Quat::Identity())});
  ASSERT_GE(standing.size(), 1u);
  for (const Contact& c : standing) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-6));
    EXPECT_TRUE((c.witness_a - Vec3(0, 0, -d)).norm() < 1e-6);
  }
}

TEST(CollisionDetector, CylinderStandingOnPlaneTouchesAtItsRim) {
  const double r = 0.05, hh = 0.08, d = 1e-3;
  const auto contacts =
      detectOnce({groundPlane(), cylinderBody(r, hh, Vec3(0, 0, hh - d), Quat::Identity())});
  ASSERT_GE(contacts.size(), 3u);
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-6));
    EXPECT_TRUE(near(Vec2(c.witness_a.x(), c.witness_a.y()).norm(), r, 0, 2e-3 * r));
  }
}

TEST(CollisionDetector, ConvexHullCubeOnPlaneAndOnBox) {
  const double h = 0.1, d = 1e-3;
  // Hull of a cube's corners on the plane: its four bottom corners at depth d.
  const auto on_plane = detectOnce({groundPlane(), hullBody(cubePoints(h), Vec3(0, 0, h - d))});
  ASSERT_EQ(on_plane.size(), 4u);
  for (const Contact& c : on_plane) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-5));
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-9));
  }
  // The same hull on a static box: face contact at depth d, normal +z.
  const Body table = boxBody(Vec3(1, 1, 0.1), Vec3(0, 0, -0.1), 0.0, BodyType::Static);
  const auto on_box = detectOnce({table, hullBody(cubePoints(h), Vec3(0, 0, h - d))});
  ASSERT_GE(on_box.size(), 3u);
  for (const Contact& c : on_box) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-4));
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-4));
  }
}

TEST(CollisionDetector, ManyFacedHullStandsOnABoxOnItsCap) {
  // An 80-sided prism (82 faces: its contact axis comes from GJK/EPA, not the separating-axis
  // search) standing on a static box: its cap is clipped into points at depth d, normal +z.
  const double r = 0.05, h = 0.04, d = 1e-3;
  auto prism = std::make_shared<TriangleMeshData>();
  for (int i = 0; i < 80; ++i) {
    const double a = 2 * M_PI * i / 80;
    for (const double z : {-h, h})
      prism->vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
  const Body table = boxBody(Vec3(1, 1, 0.1), Vec3(0, 0, -0.1), 0.0, BodyType::Static);
  const auto contacts = detectOnce({table, hullBody(prism, Vec3(0, 0, h - d))});
  ASSERT_GE(contacts.size(), 3u);
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-4));
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-4));
  }
}

TEST(CollisionDetector, BoxOnStaticTriangleMeshReportsTriangles) {
  const double h = 0.1, d = 1e-3;
  const auto contacts =
      detectOnce({groundMesh(2.0), boxBody(Vec3::Constant(h), Vec3(0.3, 0.2, h - d), 0.4)});
  // The face is clipped against both triangles in one call (separating-axis path).
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, d, 0, 1e-7));
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-7));
    EXPECT_TRUE(near(c.witness_a.z(), -d, 0, 1e-7));
    EXPECT_TRUE(c.feature_b == 0 || c.feature_b == 1) << c.feature_b;
  }
}

TEST(CollisionDetector, SphereAndHullOnStaticTriangleMesh) {
  // Triangle margins are taken off: depths are the true ones.
  const auto sphere = detectOnce({groundMesh(2.0), sphereBody(0.1, Vec3(0.5, -0.2, 0.095))});
  ASSERT_EQ(sphere.size(), 1u);
  EXPECT_TRUE(near(sphere[0].phi, 0.005, 0, 1e-5));
  EXPECT_TRUE(near(sphere[0].witness_b.z(), 0.0, 0, 1e-5));
  EXPECT_TRUE(sphere[0].feature_b == 0 || sphere[0].feature_b == 1);
  const auto hull = detectOnce({groundMesh(2.0), hullBody(cubePoints(0.1), Vec3(0.2, 0.1, 0.099))});
  ASSERT_GE(hull.size(), 2u);
  for (const Contact& c : hull) {
    EXPECT_TRUE(near(c.phi, 1e-3, 0, 1e-5));
    EXPECT_TRUE(near(c.witness_a.z(), -1e-3, 0, 1e-5));
  }
}

TEST(CollisionDetector, SphereAgainstHullFace) {
  // Sphere (id 0, A) above a hull cube (id 1, B): n = +z, depth 2 mm.
  const auto contacts = detectOnce(
      {sphereBody(0.1, Vec3(0.02, 0.03, 0.198)), hullBody(cubePoints(0.1), Vec3::Zero())});
  ASSERT_EQ(contacts.size(), 1u);
  const Contact& c = contacts[0];
  EXPECT_EQ(c.body_a, 0u);
  EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-5));
  EXPECT_TRUE(near(c.phi, 0.002, 0, 1e-5));
  EXPECT_TRUE((c.witness_b - Vec3(0.02, 0.03, 0.1)).norm() < 1e-5);
}

TEST(CollisionDetector, DynamicMeshOnPlaneTouchesWithItsVertices) {
  // A dynamic closed cube mesh on the ground plane: its four bottom vertices.
  Body cube = meshBody(boxMesh(Vec3::Constant(0.1)), BodyType::Dynamic, Vec3(0, 0, 0.099));
  const auto contacts = detectOnce({groundPlane(), cube});
  ASSERT_EQ(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, 1e-3, 0, 1e-5));
    EXPECT_TRUE(c.feature_a == 0 || c.feature_a == 1) << c.feature_a;  // the -z face
  }
}

TEST(CollisionDetector, OpenDynamicMeshOnBoxReportsItsTriangles) {
  // A box mesh without its top (not closed): Bullet collides its hull; the contacts still
  // name the mesh's bottom triangles.
  auto open = std::make_shared<TriangleMeshData>(*boxMesh(Vec3::Constant(0.1)));
  open->triangles.erase(open->triangles.begin() + 2, open->triangles.begin() + 4);
  const Body table = boxBody(Vec3(1, 1, 0.1), Vec3(0, 0, -0.1), 0.0, BodyType::Static);
  const auto contacts = detectOnce({table, meshBody(open, BodyType::Dynamic, Vec3(0, 0, 0.099))});
  ASSERT_GE(contacts.size(), 3u);
  for (const Contact& c : contacts) {
    EXPECT_TRUE(near(c.phi, 1e-3, 0, 1e-5));
    EXPECT_TRUE(c.feature_a == 0 || c.feature_a == 1) << c.feature_a;
    EXPECT_EQ(c.feature_b, 4);
  }
}

TEST(CollisionDetector, CompoundBodyKeepsShapeIndices) {
  // A dumbbell: two spheres on one body; only the second touches the ground.
  BodyDesc dumbbell =
      shapeDesc(BodyType::Dynamic, Vec3(0, 0, 0.2), Quat::Identity(), sphereShape(0.05));
  Shape second = dumbbell.shapes[0];
  second.local.position = Vec3(0.3, 0, -0.16);
  dumbbell.shapes.push_back(second);
  const auto contacts = detectOnce({groundPlane(), makeBody(dumbbell)});
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].shape_a, 1);
  EXPECT_TRUE(near(contacts[0].phi, 0.01, 0, 1e-9));
  EXPECT_TRUE((contacts[0].witness_a - Vec3(0.3, 0, -0.01)).norm() < 1e-6);
}

TEST(CollisionDetector, DeterministicAndSorted) {
  std::vector<Body> bodies = {groundPlane()};
  for (int i = 0; i < 6; ++i) {
    bodies.push_back(
        boxBody(Vec3::Constant(0.1), Vec3(0.15 * i, 0.03 * i, 0.099 + 0.19 * (i % 2)), 0.2 * i));
  }
  const auto first = detectOnce(bodies);
  const auto second = detectOnce(bodies);
  ASSERT_FALSE(first.empty());
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].key, second[i].key);
    EXPECT_EQ(first[i].body_a, second[i].body_a);
    EXPECT_EQ(first[i].witness_a, second[i].witness_a);
    EXPECT_EQ(first[i].witness_b, second[i].witness_b);
    EXPECT_EQ(first[i].normal, second[i].normal);
    EXPECT_EQ(first[i].phi, second[i].phi);
    if (i > 0) {
      const Contact& p = first[i - 1];
      EXPECT_TRUE(std::tie(p.body_a, p.body_b, p.key) <
                  std::tie(first[i].body_a, first[i].body_b, first[i].key));
    }
  }
}

TEST(CollisionDetector, KeysPersistAcrossCallsWhenNothingMoves) {
  const std::vector<Body> bodies = {groundPlane(),
                                    boxBody(Vec3::Constant(0.1), Vec3(0, 0, 0.099), 0.3),
                                    sphereBody(0.1, Vec3(1, 0, 0.095))};
  CollisionDetector detector;
  detector.setBodies(bodies, {});
  const std::vector<Contact> first = detector.detect(bodies);
  const std::vector<Contact> second = detector.detect(bodies);
  ASSERT_EQ(first.size(), 5u);
  ASSERT_EQ(second.size(), first.size());
  std::set<uint64_t> keys;
  for (size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].key, second[i].key);
    EXPECT_TRUE((first[i].witness_a - second[i].witness_a).norm() < 1e-12);
    keys.insert(first[i].key);
  }
  EXPECT_EQ(keys.size(), first.size());
}

TEST(CollisionDetector, IgnoredPairsAndStaticPairsGiveNoContacts) {
  std::vector<Body> bodies = {groundPlane(), boxBody(Vec3::Constant(0.1), Vec3(0, 0, 0.099), 0),
                              boxBody(Vec3::Constant(0.1), Vec3(0, 0, 0.297), 0)};
  CollisionDetector detector;
  detector.setBodies(bodies, {});
  EXPECT_EQ(detector.detect(bodies).size(), 8u);
  // Ignoring after the pair was found removes its contacts at once.
  detector.ignorePair(2, 1);
  for (const Contact& c : detector.detect(bodies)) EXPECT_EQ(c.body_b, 0u);
  EXPECT_EQ(detector.detect(bodies).size(), 4u);
  // Static boxes overlapping the ground plane are never paired.
  bodies[1] = boxBody(Vec3::Constant(0.1), Vec3(0, 0, 0.099), 0, BodyType::Static);
  bodies[2] = boxBody(Vec3::Constant(0.1), Vec3(0, 0, 0.297), 0, BodyType::Kinematic);
  detector.setBodies(bodies, {});
  EXPECT_TRUE(detector.detect(bodies).empty());
}

TEST(CollisionDetector, BadInputIsReported) {
  CollisionDetector detector;
  // A plane on a dynamic body, made by hand: makeBody refuses it too, and the detector must
  // not count on that.
  Body plane = groundPlane();
  plane.type = BodyType::Dynamic;
  const std::vector<Body> bad = {plane};
  EXPECT_THROW(detector.setBodies(bad, {}), Error);
  // A mesh shape without a mesh.
  const std::vector<Body> bad_mesh = {meshBody(nullptr, BodyType::Static, Vec3::Zero())};
  EXPECT_THROW(detector.setBodies(bad_mesh, {}), Error);
  // Settings out of range.
  for (int which = 0; which < 4; ++which) {
    CollisionSettings bad_settings;
    if (which == 0) bad_settings.sdf_max_contacts = 0;
    if (which == 1) bad_settings.sdf_resolution = 2;
    if (which == 2) bad_settings.contact_margin = -1e-3;
    if (which == 3) bad_settings.sdf_min_spacing = -1;
    EXPECT_THROW(detector.setBodies(std::vector<Body>{groundPlane()}, bad_settings), Error);
  }
  // After a failed setBodies the detector is empty.
  EXPECT_THROW(detector.setBodies(bad_mesh, {}), Error);
  EXPECT_THROW(detector.detect(bad_mesh), Error);
  EXPECT_TRUE(detector.detect(std::vector<Body>{}).empty());
  // detect with another body count than setBodies.
  const std::vector<Body> one = {groundPlane()};
  detector.setBodies(one, {});
  const std::vector<Body> two = {groundPlane(), groundPlane()};
  EXPECT_THROW(detector.detect(two), Error);
}

TEST(CollisionDetector, ReportGapsGivesNegativePhiWithinMargin) {
  CollisionSettings settings;
  settings.report_gaps = true;
  settings.contact_margin = 0.01;
  const auto contacts = detectOnce({groundPlane(), sphereBody(0.1, Vec3(0, 0, 0.104))}, settings);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_TRUE(near(contacts[0].phi, -0.004, 0, 1e-7));
}

// An M4-sized square nut (7 mm across, 2 mm bore half width) on a static square bolt.
// With `split_faces`, every triangle of the nut has its own vertices (splitAtFaces).
std::vector<Body> nutOnBolt(double shift_x, bool split_faces = false) {
  std::shared_ptr<const TriangleMeshData> nut = squareNutMesh(0.0035, 0.002, 0.0016);
  if (split_faces) nut = splitAtFaces(*nut);
  const auto bolt = boxMesh(Vec3(0.0018, 0.0018, 0.01));
  return {meshBody(bolt, BodyType::Static, Vec3::Zero()),
          meshBody(nut, BodyType::Dynamic, Vec3(shift_x, 0, 0.002))};
}

TEST(CollisionDetector, NutOnBoltUsesSignedDistance) {
  // Centred, the bore clears the bolt by 0.2 mm: no contact (its hull would fill the bore).
  EXPECT_TRUE(detectOnce(nutOnBolt(0.0), {}).empty());
  // Shifted by 0.25 mm, the bore's -x wall sinks 50 um into the bolt's -x face.
  const auto shifted = nutOnBolt(0.00025);
  const auto contacts = detectOnce(shifted, {});
  ASSERT_FALSE(contacts.empty());
  int face_contacts = 0;
  for (const Contact& c : contacts) {
    // The nut (dynamic) is A; n from the bolt toward the nut is -x (diagonal at the bolt's
    // vertical edges, where the two faces are equally near).
    EXPECT_EQ(c.body_a, 1u);
    EXPECT_LT(c.normal.x(), -0.7) << c.normal.transpose();
    EXPECT_GE(c.phi, 0.0);
    EXPECT_LE(c.phi, 5e-5 + 1e-7);
    EXPECT_TRUE(near(c.witness_a.x(), -0.00175, 0, 1e-7));
    EXPECT_TRUE(near(c.witness_b.x(), -0.0018, 0, 5e-5));
    EXPECT_GE(c.feature_a, 0);
    EXPECT_GE(c.feature_b, 0);
    // Away from the edges: the exact depth and normal.
    if (std::abs(c.point.y()) < 0.001) {
      ++face_contacts;
      EXPECT_TRUE(near(c.phi, 5e-5, 0, 1e-7));
      EXPECT_TRUE(near(c.normal.x(), -1.0, 0, 1e-6));
      EXPECT_TRUE(near(c.witness_b.x(), -0.0018, 0, 1e-7));
    }
  }
  EXPECT_GE(face_contacts, 4);
}

TEST(CollisionDetector, NutWithUvSeamsOnBoltUsesSignedDistance) {
  // The nut with every triangle's vertices split (per-face UVs) is still closed: centred it
  // clears the bolt (its hull would not), shifted it touches exactly as the unsplit nut.
  EXPECT_TRUE(detectOnce(nutOnBolt(0.0, true)).empty());
  const auto whole = detectOnce(nutOnBolt(0.00025));
  const auto contacts = detectOnce(nutOnBolt(0.00025, true));
  ASSERT_FALSE(contacts.empty());
  ASSERT_EQ(contacts.size(), whole.size());
  for (size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_TRUE(near(contacts[i].phi, whole[i].phi, 0, 1e-12));
    EXPECT_TRUE((contacts[i].normal - whole[i].normal).norm() < 1e-12);
    EXPECT_TRUE((contacts[i].witness_a - whole[i].witness_a).norm() < 1e-12);
    EXPECT_EQ(contacts[i].feature_a, whole[i].feature_a);
  }
}

TEST(CollisionDetector, NutOnCylinderBolt) {
  // A static cylinder bolt (r 1.8 mm) through the dynamic nut's square bore.
  const Body bolt = cylinderBody(0.0018, 0.01, Vec3::Zero(), Quat::Identity(), BodyType::Static);
  const auto nut = squareNutMesh(0.0035, 0.002, 0.0016);
  EXPECT_TRUE(detectOnce({bolt, meshBody(nut, BodyType::Dynamic, Vec3(0, 0, 0.002))}).empty());
  // Shifted 0.25 mm: the bore's -x wall cuts 50 um into the rod at y = 0.
  const auto contacts =
      detectOnce({bolt, meshBody(nut, BodyType::Dynamic, Vec3(0.00025, 0, 0.002))});
  ASSERT_FALSE(contacts.empty());
  double deepest = 0;
  for (const Contact& c : contacts) {
    EXPECT_EQ(c.body_a, 1u);
    EXPECT_LT(c.normal.x(), -0.9) << c.normal.transpose();
    EXPECT_LE(c.phi, 5e-5 + 1e-6);
    // The rod's witness lies on the rod.
    EXPECT_TRUE(near(std::hypot(c.witness_b.x(), c.witness_b.y()), 0.0018, 0, 1e-7));
    deepest = std::max(deepest, c.phi);
  }
  EXPECT_TRUE(near(deepest, 5e-5, 0, 2e-6));
}

TEST(CollisionDetector, ConcaveMeshOnStaticBox) {
  // The nut lying on a static box table, 20 um deep: exact depth from the box's distance.
  const Body table = boxBody(Vec3(0.02, 0.02, 0.005), Vec3(0, 0, -0.005), 0.0, BodyType::Static);
  const auto nut = squareNutMesh(0.0035, 0.002, 0.0016);
  const auto contacts =
      detectOnce({table, meshBody(nut, BodyType::Dynamic, Vec3(0, 0, 0.0016 - 2e-5))});
  ASSERT_GE(contacts.size(), 4u);
  for (const Contact& c : contacts) {
    EXPECT_EQ(c.body_a, 1u);
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-9));
    EXPECT_TRUE(near(c.phi, 2e-5, 0, 1e-9));
    EXPECT_EQ(c.feature_b, 4);  // the table's +z face
  }
}

TEST(CollisionDetector, SignedDistanceKeysPersist) {
  const auto bodies = nutOnBolt(0.00025);
  CollisionDetector detector;
  detector.setBodies(bodies, {});
  const std::vector<Contact> first = detector.detect(bodies);
  const std::vector<Contact> second = detector.detect(bodies);
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i].key, second[i].key);
}

}  // namespace
}  // namespace asperity
