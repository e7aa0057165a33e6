// Triangle lookup for contacts on meshes that collide through hulls or vertices.
#include "collision/mesh_features.hpp"

#include <gtest/gtest.h>

#include "collision_test_scenes.hpp"

namespace asperity::collision_detail {
namespace {

TEST(MeshFeatures, VertexContactsTakeTheTriangleFacingOut) {
  const MeshFeatures f(collision_test::boxMesh(Vec3::Constant(0.1)));
  // Corner 0 (-x, -y, -z) is shared by the -z, -y and -x faces (triangles 0-1, 4-5, 8-9).
  const int bottom = f.triangleAtVertex(0, -Vec3::UnitZ());
  EXPECT_TRUE(bottom == 0 || bottom == 1);
  const int side = f.triangleAtVertex(0, -Vec3::UnitX());
  EXPECT_TRUE(side == 8 || side == 9) << side;
  EXPECT_EQ(f.triangleAtVertex(99, Vec3::UnitZ()), -1);
}

TEST(MeshFeatures, NearestTriangleOfAFaceAndOfAnEdge) {
  const MeshFeatures f(collision_test::boxMesh(Vec3::Constant(0.1)));
  NearestScratch scratch;
  // Just above the middle of the +z face (triangles 2-3).
  const int top = f.nearestTriangle(Vec3(0.03, 0.02, 0.1001), Vec3::UnitZ(), scratch);
  EXPECT_TRUE(top == 2 || top == 3) << top;
  // On the edge between +z and +y: the outward direction decides.
  const int side = f.nearestTriangle(Vec3(0.0, 0.1, 0.1), Vec3::UnitY(), scratch);
  EXPECT_TRUE(side == 6 || side == 7) << side;
  // Far away: still the nearest face.
  const int far = f.nearestTriangle(Vec3(5, 0, 0), Vec3::UnitX(), scratch);
  EXPECT_TRUE(far == 10 || far == 11) << far;
}

}  // namespace
}  // namespace asperity::collision_detail
