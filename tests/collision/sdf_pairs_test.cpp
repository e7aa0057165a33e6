// Which pairs take the signed-distance path, and the fields and samples it shares.
#include "collision/sdf_pairs.hpp"

#include <gtest/gtest.h>

#include "collision/signed_distance_field.hpp"
#include "collision_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity::collision_detail {
namespace {

using test::near;

ShapeRecord record(const Body& body, BodyId id) {
  ShapeRecord r;
  r.body = id;
  r.index = 0;
  r.body_type = body.type;
  r.shape = body.shapes[0];
  r.closed_mesh = r.shape.type == ShapeType::TriangleMesh && isClosedMesh(*r.shape.mesh);
  r.world = body.pose * r.shape.local;  // as the detector places it
  return r;
}

TEST(SdfPairs, OnlyDynamicClosedMeshesTakeThePath) {
  using namespace collision_test;
  const auto nut = squareNutMesh(0.0035, 0.002, 0.0016);
  const ShapeRecord dynamic_nut = record(meshBody(nut, BodyType::Dynamic, Vec3::Zero()), 1);
  const ShapeRecord static_nut = record(meshBody(nut, BodyType::Static, Vec3::Zero()), 2);
  const ShapeRecord box = record(boxBody(Vec3::Constant(0.1), Vec3::Zero(), 0), 3);
  const ShapeRecord ground = record(groundMesh(1.0), 4);  // open
  const ShapeRecord hull = record(hullBody(cubePoints(0.1), Vec3::Zero()), 5);
  EXPECT_TRUE(isSdfPair(dynamic_nut, static_nut));
  EXPECT_TRUE(isSdfPair(box, dynamic_nut));
  EXPECT_FALSE(isSdfPair(dynamic_nut, ground));
  EXPECT_FALSE(isSdfPair(dynamic_nut, hull));
  EXPECT_FALSE(isSdfPair(static_nut, box));
}

TEST(SdfPairs, FieldsAreSharedAndSamplesFollowTheResolution) {
  using namespace collision_test;
  const auto mesh = boxMesh(Vec3::Constant(0.1));
  const ShapeRecord a = record(meshBody(mesh, BodyType::Dynamic, Vec3::Zero()), 0);
  const ShapeRecord b = record(meshBody(mesh, BodyType::Dynamic, Vec3(1, 0, 0)), 1);
  CollisionSettings settings;
  settings.sdf_resolution = 20;
  SdfResources res;
  res.reset(settings);
  EXPECT_EQ(&res.field(a), &res.field(b));
  EXPECT_TRUE(near(res.field(a).cellSize(), 0.01, 1e-12));
  // Samples about one cell (1 cm) apart: the 0.28 m hypotenuse of each triangle is cut 29 times.
  const SurfaceSamples& s = res.samples(a);
  EXPECT_EQ(s.points.size(), 12u * 465u);
  EXPECT_EQ(&res.samples(a), &s);
}

TEST(SdfPairs, ContactsOfACubeMeshOnABox) {
  using namespace collision_test;
  // A closed cube mesh 2 mm into a static box: both directions, depth and normal exact.
  const ShapeRecord ground =
      record(boxBody(Vec3(1, 1, 0.1), Vec3(0, 0, -0.1), 0.0, BodyType::Static), 0);
  const ShapeRecord cube =
      record(meshBody(boxMesh(Vec3::Constant(0.1)), BodyType::Dynamic, Vec3(0, 0, 0.098)), 1);
  CollisionSettings settings;
  SdfResources res;
  res.reset(settings);
  std::vector<Contact> out;
  sdfPairContacts(ground, cube, settings, res, out);
  ASSERT_FALSE(out.empty());
  EXPECT_LE(out.size(), 2u * static_cast<size_t>(settings.sdf_max_contacts));
  for (const Contact& c : out) {
    EXPECT_EQ(c.body_a, 1u);
    EXPECT_TRUE(near(c.phi, 0.002, 0, 1e-9));
    EXPECT_TRUE(near(c.normal.z(), 1.0, 0, 1e-9));
    EXPECT_EQ(c.feature_b, 4);
  }
}

}  // namespace
}  // namespace asperity::collision_detail
