// Bodies and meshes shared by the collision tests and the collision benchmark. Bodies are made
// as a program makes them: a description (the public builders of asperity/world/builders.hpp
// for the ground and boxes, shapeDesc for one shape of any other kind) made live by makeBody,
// so that the body frame sits at the centre of mass as it does in a World.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "asperity/dynamics/body.hpp"
#include "asperity/world/builders.hpp"

namespace asperity::collision_test {

// A body of `type` at (position, rotation) with one shape.
inline BodyDesc shapeDesc(BodyType type, const Vec3& position, const Quat& rotation, Shape shape) {
  BodyDesc desc;
  desc.name = "body";
  desc.type = type;
  desc.pose = {position, rotation};
  desc.shapes.push_back(std::move(shape));
  return desc;
}

inline Body shapeBody(BodyType type, const Vec3& position, const Quat& rotation, Shape shape) {
  return makeBody(shapeDesc(type, position, rotation, std::move(shape)));
}

// The static ground: the plane z = 0, normal +z.
inline Body groundPlane() {
  return makeBody(groundPlaneDesc());
}

// A box turned by `yaw` about z; dynamic unless `type` says otherwise.
inline Body boxBody(const Vec3& half, const Vec3& position, double yaw,
                    BodyType type = BodyType::Dynamic) {
  BodyDesc desc = boxDesc("box", half, {position, Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ()))});
  desc.type = type;
  return makeBody(desc);
}

// Shapes of the other kinds, and dynamic bodies of one of them.
inline Shape sphereShape(double radius) {
  Shape sphere;
  sphere.type = ShapeType::Sphere;
  sphere.radius = radius;
  return sphere;
}

// Capsules and cylinders along their local z.
inline Shape roundShape(ShapeType type, double radius, double half_height) {
  Shape shape;
  shape.type = type;
  shape.radius = radius;
  shape.half_height = half_height;
  return shape;
}

inline Body sphereBody(double radius, const Vec3& position) {
  return shapeBody(BodyType::Dynamic, position, Quat::Identity(), sphereShape(radius));
}

inline Body capsuleBody(double radius, double half_height, const Vec3& position, const Quat& q) {
  return shapeBody(BodyType::Dynamic, position, q,
                   roundShape(ShapeType::Capsule, radius, half_height));
}

inline Body cylinderBody(double radius, double half_height, const Vec3& position, const Quat& q,
                         BodyType type = BodyType::Dynamic) {
  return shapeBody(type, position, q, roundShape(ShapeType::Cylinder, radius, half_height));
}

// The corners of a cube of half size h.
inline std::shared_ptr<TriangleMeshData> cubePoints(double h) {
  auto mesh = std::make_shared<TriangleMeshData>();
  for (int i = 0; i < 8; ++i) {
    mesh->vertices.emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
  }
  return mesh;
}

inline Body hullBody(std::shared_ptr<const TriangleMeshData> points, const Vec3& position) {
  Shape hull;
  hull.type = ShapeType::ConvexHull;
  hull.mesh = std::move(points);
  return shapeBody(BodyType::Dynamic, position, Quat::Identity(), hull);
}

// A closed box mesh (12 outward-wound triangles) of half extents h.
inline std::shared_ptr<TriangleMeshData> boxMesh(const Vec3& h) {
  auto mesh = cubePoints(1.0);
  for (Vec3& v : mesh->vertices) v = v.cwiseProduct(h);
  // Faces as quads of corner indices (bit 0 = x, 1 = y, 2 = z), counter-clockwise outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh->triangles.push_back({q[0], q[1], q[2]});
    mesh->triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

inline Shape meshShape(std::shared_ptr<const TriangleMeshData> mesh) {
  Shape shape;
  shape.type = ShapeType::TriangleMesh;
  shape.mesh = std::move(mesh);
  return shape;
}

inline Body meshBody(std::shared_ptr<const TriangleMeshData> mesh, BodyType type,
                     const Vec3& position, const Quat& q = Quat::Identity()) {
  return shapeBody(type, position, q, meshShape(std::move(mesh)));
}

// A static ground made of two triangles, the square [-half, half]^2 at z = 0.
inline Body groundMesh(double half) {
  auto mesh = std::make_shared<TriangleMeshData>();
  mesh->vertices = {Vec3(-half, -half, 0), Vec3(half, -half, 0), Vec3(half, half, 0),
                    Vec3(-half, half, 0)};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  return meshBody(mesh, BodyType::Static, Vec3::Zero());
}

// A closed square "nut": outer half width `outer`, a square bore of half width `inner`,
// half height `hh`, along z (32 triangles).
inline std::shared_ptr<TriangleMeshData> squareNutMesh(double outer, double inner, double hh) {
  auto mesh = std::make_shared<TriangleMeshData>();
  // Rings of 4 corners: outer bottom 0-3, outer top 4-7, inner bottom 8-11, inner top 12-15.
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (double w : {outer, inner}) {
    for (double z : {-hh, hh}) {
      for (int c = 0; c < 4; ++c) mesh->vertices.emplace_back(w * sx[c], w * sy[c], z);
    }
  }
  auto quad = [&](int a, int b, int c, int d) {
    mesh->triangles.push_back({a, b, c});
    mesh->triangles.push_back({a, c, d});
  };
  for (int c = 0; c < 4; ++c) {
    const int n = (c + 1) % 4;
    quad(c, n, 4 + n, 4 + c);            // outer wall
    quad(8 + n, 8 + c, 12 + c, 12 + n);  // bore wall (faces the axis)
    quad(4 + c, 4 + n, 12 + n, 12 + c);  // top
    quad(n, c, 8 + c, 8 + n);            // bottom
  }
  return mesh;
}

// The same surface with every triangle's corners split off and given their own UVs, as a
// loader splits vertices per (position, uv) pair: no two triangles share a vertex index.
inline std::shared_ptr<TriangleMeshData> splitAtFaces(const TriangleMeshData& mesh) {
  auto out = std::make_shared<TriangleMeshData>();
  const Vec2 corner_uv[3] = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  for (const auto& tri : mesh.triangles) {
    const int first = static_cast<int>(out->vertices.size());
    for (size_t c = 0; c < 3; ++c) {
      out->vertices.push_back(mesh.vertices[static_cast<size_t>(tri[c])]);
      out->uvs.push_back(corner_uv[c]);
    }
    out->triangles.push_back({first, first + 1, first + 2});
  }
  return out;
}

}  // namespace asperity::collision_test
