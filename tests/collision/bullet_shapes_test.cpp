// Bullet shapes from asperity shapes: sizes, margins that follow the size, axis conventions,
// and the errors for shapes that cannot be built.
#include "collision/bullet_shapes.hpp"

#include <gtest/gtest.h>

#include "asperity/error.hpp"
#include "collision_test_scenes.hpp"
#include "support/test_support.hpp"

namespace asperity::collision_detail {
namespace {

using test::near;

TEST(BulletShapes, MarginsFollowTheSize) {
  // 2% of the smallest dimension, at most 4 cm.
  EXPECT_TRUE(near(marginFor(0.004), 8e-5, 1e-12));
  EXPECT_TRUE(near(marginFor(0.2), 0.004, 1e-12));
  EXPECT_TRUE(near(marginFor(10.0), 0.04, 1e-12));
  Shape box;
  box.type = ShapeType::Box;
  box.half_extents = Vec3(0.002, 0.01, 0.03);
  EXPECT_TRUE(near(shapeSize(box), 0.004, 1e-12));
  const BulletShape built = makeBulletShape(box, BodyType::Dynamic);
  EXPECT_TRUE(near(built.shape->getMargin(), 8e-5, 1e-6));
  // A flat ground mesh takes its smallest non-zero extent.
  EXPECT_TRUE(near(shapeSize(collision_test::groundMesh(2.0).shapes[0]), 4.0, 1e-12));
}

TEST(BulletShapes, ScaleBringsMillimetrePartsToDecimetres) {
  Body part = collision_test::sphereBody(0.0005, Vec3::Zero());  // 1 mm across
  const std::vector<Body> small = {collision_test::groundPlane(), part};
  EXPECT_EQ(bulletScale(small), 256.0);  // 1 mm x 256 = 0.256 units
  const std::vector<Body> cubes = {collision_test::boxBody(Vec3::Constant(0.1), Vec3::Zero(), 0)};
  EXPECT_EQ(bulletScale(cubes), 1.0);
  const Shape scaled = scaledShape(part.shapes[0], 256.0);
  EXPECT_EQ(scaled.radius, 0.128);
  const btTransform t = toBt(Transform{Vec3(0.001, 0, 0), Quat::Identity()}, 256.0);
  EXPECT_FLOAT_EQ(t.getOrigin().x(), 0.256f);
}

TEST(BulletShapes, CapsulesAndCylindersRunAlongLocalZ) {
  Shape capsule;
  capsule.type = ShapeType::Capsule;
  capsule.radius = 0.01;
  capsule.half_height = 0.05;
  const BulletShape c = makeBulletShape(capsule, BodyType::Dynamic);
  btVector3 lo, hi;
  c.shape->getAabb(btTransform::getIdentity(), lo, hi);
  EXPECT_TRUE(near(hi.z(), 0.06, 1e-5));
  EXPECT_TRUE(near(hi.x(), 0.01, 1e-5));
  Shape cylinder = capsule;
  cylinder.type = ShapeType::Cylinder;
  const BulletShape y = makeBulletShape(cylinder, BodyType::Dynamic);
  y.shape->getAabb(btTransform::getIdentity(), lo, hi);
  EXPECT_TRUE(near(hi.z(), 0.05, 1e-3));
  EXPECT_TRUE(near(hi.x(), 0.01, 1e-3));
}

TEST(BulletShapes, MeshesAreBvhWhenStaticAndHullsWhenDynamic) {
  Shape mesh;
  mesh.type = ShapeType::TriangleMesh;
  mesh.mesh = collision_test::boxMesh(Vec3::Constant(0.1));
  EXPECT_EQ(makeBulletShape(mesh, BodyType::Static).shape->getShapeType(),
            TRIANGLE_MESH_SHAPE_PROXYTYPE);
  EXPECT_EQ(makeBulletShape(mesh, BodyType::Dynamic).shape->getShapeType(),
            CONVEX_HULL_SHAPE_PROXYTYPE);
}

TEST(BulletShapes, ShapesThatCannotBeBuiltThrow) {
  Shape plane;
  plane.type = ShapeType::Plane;
  EXPECT_THROW(makeBulletShape(plane, BodyType::Dynamic), Error);
  EXPECT_NO_THROW(makeBulletShape(plane, BodyType::Static));
  // Hulls: too few points, or all in one plane.
  Shape hull;
  hull.type = ShapeType::ConvexHull;
  EXPECT_THROW(makeBulletShape(hull, BodyType::Dynamic), Error);
  auto flat = std::make_shared<TriangleMeshData>();
  flat->vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0.5, 0.2, 0)};
  hull.mesh = flat;
  EXPECT_THROW(makeBulletShape(hull, BodyType::Dynamic), Error);
  // Meshes: no triangles, or an index out of range.
  Shape mesh;
  mesh.type = ShapeType::TriangleMesh;
  mesh.mesh = flat;
  EXPECT_THROW(makeBulletShape(mesh, BodyType::Static), Error);
  auto bad = std::make_shared<TriangleMeshData>(*flat);
  bad->triangles = {{0, 1, 7}};
  mesh.mesh = bad;
  EXPECT_THROW(makeBulletShape(mesh, BodyType::Static), Error);
}

}  // namespace
}  // namespace asperity::collision_detail
