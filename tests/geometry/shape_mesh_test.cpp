// Shape meshes and the analytic texture mapping: frames are right-handed and outward, triangles
// wind counter-clockwise seen from outside, uv follows T and B at the texture's scale, and the
// mesh vertices carry the same mapping as surfaceFrameAt.
#include "asperity/geometry/shape_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

Shape makeShape(ShapeType type) {
  Shape s;
  s.type = type;
  s.half_extents = Vec3(0.1, 0.2, 0.3);
  s.radius = 0.15;
  s.half_height = 0.25;
  s.surface.texture_size = 0.5;
  return s;
}

std::shared_ptr<TriangleMeshData> tetrahedron(bool with_uvs) {
  auto m = std::make_shared<TriangleMeshData>();
  m->vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  if (with_uvs) m->uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(0.5, 0.5)};
  return m;
}

// Every triangle winds outward and its uv changes along the edges as dp.T and dp.B scaled
// (checked for flat-mapped triangles, where the frame is constant).
void expectConsistentMesh(const ShapeMesh& mesh, double uv_per_metre, bool flat_frames) {
  ASSERT_FALSE(mesh.triangles.empty());
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& tri = mesh.triangles[k];
    const Vec3 p0 = mesh.positions[tri[0]].cast<double>();
    const Vec3 p1 = mesh.positions[tri[1]].cast<double>();
    const Vec3 p2 = mesh.positions[tri[2]].cast<double>();
    const Vec3 n = mesh.normals[tri[0]].cast<double>();
    EXPECT_GT((p1 - p0).cross(p2 - p0).dot(n), 0.0) << "triangle " << k;
    if (!flat_frames) continue;
    const Vec3 t = mesh.tangents[tri[0]].cast<double>();
    const Vec3 b = mesh.bitangents[tri[0]].cast<double>();
    const Vec2 du = (mesh.uvs[tri[1]] - mesh.uvs[tri[0]]).cast<double>();
    EXPECT_NEAR(du.x(), uv_per_metre * (p1 - p0).dot(t), 1e-5);
    EXPECT_NEAR(du.y(), uv_per_metre * (p1 - p0).dot(b), 1e-5);
  }
  // Frames: unit, orthogonal, right-handed.
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3 t = mesh.tangents[i].cast<double>(), b = mesh.bitangents[i].cast<double>();
    const Vec3 n = mesh.normals[i].cast<double>();
    EXPECT_NEAR(std::abs(t.cross(b).dot(n)), 1.0, 1e-5) << "vertex " << i;
  }
}

TEST(ShapeMesh, BoxFacesFollowTheTableAndScale) {
  const Shape box = makeShape(ShapeType::Box);
  const ShapeMesh mesh = buildShapeMesh(box);
  EXPECT_EQ(mesh.triangleCount(), 12u);
  expectConsistentMesh(mesh, 2.0, true);
  // Top face: T = +x, B = +y, uv = (x, y) / 0.5.
  const SurfaceFrame top = surfaceFrameAt(box, -1, Vec3(0.05, -0.1, 0.3));
  EXPECT_TRUE(top.t.isApprox(Vec3::UnitX()));
  EXPECT_TRUE(top.n.isApprox(Vec3::UnitZ()));
  EXPECT_NEAR(top.uv.x(), 0.1, 1e-12);
  EXPECT_NEAR(top.uv.y(), -0.2, 1e-12);
  // Side +y: T = -x, B = +z; the face id of the collision stage wins over the point.
  const SurfaceFrame side = surfaceFrameAt(box, 2, Vec3(0.05, 0.2, 0.1));
  EXPECT_TRUE(side.t.isApprox(-Vec3::UnitX()));
  EXPECT_TRUE(side.b.isApprox(Vec3::UnitZ()));
  EXPECT_EQ(boxFaceAt(box.half_extents, Vec3(0.0, -0.19, 0.0)), 3);
}

TEST(ShapeMesh, VerticesCarryTheAnalyticMapping) {
  for (ShapeType type : {ShapeType::Box, ShapeType::Sphere, ShapeType::Cylinder, ShapeType::Capsule,
                         ShapeType::Plane}) {
    Shape s = makeShape(type);
    s.surface.texture_rotation = 0.3;
    const ShapeMesh mesh = buildShapeMesh(s, {.segments = 16, .rings = 8, .plane_size = 2.0});
    expectConsistentMesh(mesh, 2.0, type == ShapeType::Box || type == ShapeType::Plane);
    // Away from seams and poles the vertex attributes equal surfaceFrameAt.
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      const Vec3 p = mesh.positions[i].cast<double>();
      if (std::abs(std::abs(std::atan2(p.y(), p.x())) - kPi) < 1e-3) continue;
      if (std::hypot(p.x(), p.y()) < 1e-6) continue;
      const int feature = type == ShapeType::Box ? boxFaceAt(s.half_extents, p) : -1;
      const SurfaceFrame f = surfaceFrameAt(s, feature, p);
      if (type == ShapeType::Box && !f.n.isApprox(mesh.normals[i].cast<double>(), 1e-5)) continue;
      if (type == ShapeType::Cylinder && !f.n.isApprox(mesh.normals[i].cast<double>(), 1e-5)) {
        continue;  // rim vertices belong to side and cap
      }
      EXPECT_NEAR((f.uv - mesh.uvs[i].cast<double>()).norm(), 0.0, 1e-5) << "vertex " << i;
      EXPECT_NEAR((f.t - mesh.tangents[i].cast<double>()).norm(), 0.0, 1e-5);
      EXPECT_NEAR((f.n - mesh.normals[i].cast<double>()).norm(), 0.0, 1e-5);
    }
  }
}

TEST(ShapeMesh, CurvedSidesAreArcLengthMapped) {
  // Cylinder side: u = r * longitude, v = z (in repeats of 0.5 m); T east, B up, N radial.
  const Shape cyl = makeShape(ShapeType::Cylinder);
  const Vec3 p(0.15 * std::cos(0.5), 0.15 * std::sin(0.5), 0.1);
  const SurfaceFrame f = surfaceFrameAt(cyl, -1, p);
  EXPECT_NEAR(f.uv.x(), 0.15 * 0.5 / 0.5, 1e-12);
  EXPECT_NEAR(f.uv.y(), 0.2, 1e-12);
  EXPECT_TRUE(f.b.isApprox(Vec3::UnitZ()));
  EXPECT_NEAR(f.n.dot(Vec3(std::cos(0.5), std::sin(0.5), 0)), 1.0, 1e-12);
  // Capsule cap continues the side: v = h + r * latitude.
  const Shape cap = makeShape(ShapeType::Capsule);
  const SurfaceFrame top = surfaceFrameAt(cap, -1, Vec3(0.15, 0, 0.25));
  EXPECT_NEAR(top.uv.y(), 0.25 / 0.5, 1e-12);
  const SurfaceFrame pole = surfaceFrameAt(cap, -1, Vec3(0, 0, 0.4));
  EXPECT_NEAR(pole.uv.y(), (0.25 + 0.15 * kPi / 2) / 0.5, 1e-12);
}

TEST(ShapeMesh, RotationTurnsTheTextureAxes) {
  Shape box = makeShape(ShapeType::Box);
  box.surface.texture_rotation = kPi / 2;
  // +u now runs along the face's +v (y on the top face); uv' = (v, -u).
  const SurfaceFrame f = surfaceFrameAt(box, 4, Vec3(0.05, 0.1, 0.3));
  EXPECT_NEAR((f.t - Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f.b + Vec3::UnitX()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.uv.x(), 0.2, 1e-12);
  EXPECT_NEAR(f.uv.y(), -0.1, 1e-12);
}

TEST(ShapeMesh, PlaneAndHull) {
  const Shape plane = makeShape(ShapeType::Plane);
  const SurfaceFrame f = surfaceFrameAt(plane, -1, Vec3(1.0, 2.0, 0.0));
  EXPECT_NEAR(f.uv.x(), 2.0, 1e-12);
  EXPECT_NEAR(f.uv.y(), 4.0, 1e-12);
  // A hull of a cube's corners meshes to 12 outward triangles with box-like frames.
  Shape hull = makeShape(ShapeType::ConvexHull);
  auto data = std::make_shared<TriangleMeshData>();
  for (int i = 0; i < 8; ++i)
    data->vertices.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  hull.mesh = data;
  const ShapeMesh mesh = buildShapeMesh(hull);
  EXPECT_EQ(mesh.triangleCount(), 12u);
  expectConsistentMesh(mesh, 2.0, true);
}

TEST(ShapeMesh, TriangleMeshUvsAndFallback) {
  Shape s = makeShape(ShapeType::TriangleMesh);
  s.mesh = tetrahedron(false);
  expectConsistentMesh(buildShapeMesh(s), 2.0, true);
  // With UVs the bottom face (z = 0, u along x, v along y, seen from below) is mirrored.
  s.mesh = tetrahedron(true);
  const ShapeMesh mesh = buildShapeMesh(s);
  expectConsistentMesh(mesh, 1.0, false);
  const SurfaceFrame f = surfaceFrameAt(s, 0, Vec3(0.2, 0.3, 0.0));
  EXPECT_NEAR(f.uv.x(), 0.2, 1e-12);
  EXPECT_NEAR(f.uv.y(), 0.3, 1e-12);
  EXPECT_NEAR(f.t.dot(Vec3::UnitX()), 1.0, 1e-12);
  EXPECT_NEAR(f.b.dot(Vec3::UnitY()), 1.0, 1e-12);
}

TEST(ShapeMesh, BadInputThrows) {
  Shape s = makeShape(ShapeType::Box);
  s.surface.texture_size = 0.0;
  EXPECT_THROW(buildShapeMesh(s), Error);
  EXPECT_THROW(surfaceFrameAt(s, -1, Vec3::Zero()), Error);
  Shape m = makeShape(ShapeType::TriangleMesh);
  EXPECT_THROW(buildShapeMesh(m), Error);  // no data
  m.mesh = tetrahedron(false);
  EXPECT_THROW(surfaceFrameAt(m, 9, Vec3::Zero()), Error);
  auto bad = std::make_shared<TriangleMeshData>(*tetrahedron(false));
  bad->triangles.push_back({0, 1, 7});
  m.mesh = bad;
  EXPECT_THROW(buildShapeMesh(m), Error);
  auto uvs = std::make_shared<TriangleMeshData>(*tetrahedron(true));
  uvs->uvs.pop_back();
  m.mesh = uvs;
  EXPECT_THROW(buildShapeMesh(m), Error);
  EXPECT_THROW(buildShapeMesh(makeShape(ShapeType::Sphere), {.segments = 2}), Error);
}

}  // namespace
}  // namespace asperity
