// Surface parameterisation of every shape: the analytic texture mapping (uv and tangent frame at
// a point), and triangle meshes with per-vertex uv and tangent frames for samplers and renderers.
//
// Conventions (SPEC 6), shared by the patch samplers, the renderer and the frame stage:
//  - uv is in texture repeats: 1 = one Surface::texture_size of surface; analytic mappings give
//    metres / texture_size, mesh UVs are used as they are (their own repeats).
//  - The tangent frame is (T, B, N): T along +u, B along +v, N outward; for the analytic
//    mappings it is orthonormal and right-handed (T x B = N). A texel (x, y, z) of a normal map
//    is the meso normal x T + y B + z N.
//  - Surface::texture_rotation r turns the texture within the face: the texture's +u axis is
//    cos(r) T + sin(r) B of the face's own frame (counter-clockwise seen from outside), so
//    uv' = (cos r u + sin r v, -sin r u + cos r v), T' = cos r T + sin r B,
//    B' = -sin r T + cos r B.
//
// Face mappings (before the rotation), all in the shape frame:
//  - Box: face index 2 * axis + (outward normal along the negative axis ? 1 : 0) (the collision
//    stage's feature ids). +z: T = +x, B = +y. -z: T = +x, B = -y. Side faces wrap around z with
//    B = +z: +x: T = +y; +y: T = -x; -x: T = -y; -y: T = +x. uv = (p.T, p.B) / texture_size.
//  - Plane {n.x = offset}: T = x axis projected on the plane (y axis when n is within 25 degrees
//    of x), B = n x T, uv = (p.T, p.B) / texture_size.
//  - Sphere: u = r * longitude (atan2(y, x)), v = r * latitude; T east, B north.
//  - Cylinder, capsule (axis z): sides u = r * atan2(y, x), v = z, T = around the axis
//    counter-clockwise seen from +z, B = +z. Cylinder caps like the box's z faces. Capsule caps
//    continue the side: v = +-half_height + r * latitude of the cap sphere.
//    Longitude seams sit at atan2 = +-pi (a texture seam unless 2 pi r is a whole number of
//    repeats).
//  - Convex hull, and triangle meshes without UVs: planar projection per triangle along the
//    dominant axis of its normal, with the box face's T projected onto the triangle's plane.
//  - Triangle meshes with UVs: their own UVs; tangents from UV gradients, accumulated per
//    vertex and orthogonalised against the vertex normal (MikkTSpace-like; B = sign N x T,
//    sign -1 where the UVs are mirrored).
#pragma once

#include <array>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

// The texture mapping at one point of a surface, in the shape frame.
struct SurfaceFrame {
  Vec2 uv = Vec2::Zero();  // texture repeats
  Vec3 t = Vec3::UnitX();  // +u
  Vec3 b = Vec3::UnitY();  // +v
  Vec3 n = Vec3::UnitZ();  // outward normal
};

// The analytic mapping at `local_point` (shape frame, on or near the surface). `feature` is the
// collision stage's feature id: the box face (derived from the point when outside 0..5) or the
// triangle of a TriangleMesh / ConvexHull with triangles (when -1, the frame of the dominant
// axis of the point's direction from the shape origin is used). Throws asperity::Error for a
// mesh shape without mesh data or a triangle index out of range.
SurfaceFrame surfaceFrameAt(const Shape& shape, int feature, const Vec3& local_point);

// The box face (0..5, see above) whose plane is nearest to `local_point`.
int boxFaceAt(const Vec3& half_extents, const Vec3& local_point);

// The face frame of a box face before texture rotation (T, B, N of the table above).
SurfaceFrame boxFaceFrame(int face);

// Applies Surface::texture_rotation (radians) to a face frame.
SurfaceFrame rotateTexture(const SurfaceFrame& frame, double rotation);

// A triangle mesh of a shape in its shape frame, with per-vertex attributes. Triangles are
// counter-clockwise seen from outside. Vertices are split where uv or frame jump (box edges,
// seams, flat-shaded triangles).
struct ShapeMesh {
  std::vector<Vec3f> positions;
  std::vector<Vec2f> uvs;  // texture repeats (rotation applied)
  std::vector<Vec3f> tangents;
  std::vector<Vec3f> bitangents;
  std::vector<Vec3f> normals;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> features;  // per triangle: box face, mesh triangle, hull face (else -1)

  size_t triangleCount() const { return triangles.size(); }
};

struct ShapeMeshOptions {
  int segments = 64;  // around the axis (sphere, capsule, cylinder)
  int rings = 32;     // pole to pole (sphere; capsule caps get rings / 2 each)
  // Planes: a finite square of this side (m) centred on the plane point nearest `centre`
  // (both in the shape frame), split into `plane_tiles` x `plane_tiles` quads.
  double plane_size = 10.0;
  Vec3 plane_centre = Vec3::Zero();
  int plane_tiles = 1;
};

// Throws asperity::Error for a mesh shape without data, a bad triangle index, UVs whose count
// differs from the vertex count, or options below 3 segments / 2 rings / 1 tile.
ShapeMesh buildShapeMesh(const Shape& shape, const ShapeMeshOptions& options = {});

}  // namespace asperity
