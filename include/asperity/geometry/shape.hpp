// Collision shapes in a body's local frame. Every shape carries the Surface of its faces.
// Local axes: capsules and cylinders run along local z; planes are {x : n.x = offset}.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "asperity/geometry/surface.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

enum class ShapeType { Box, Sphere, Capsule, Cylinder, Plane, ConvexHull, TriangleMesh };
inline constexpr std::pair<const char*, ShapeType> kShapeTypeNames[] = {
    {"box", ShapeType::Box},          {"sphere", ShapeType::Sphere},
    {"capsule", ShapeType::Capsule},  {"cylinder", ShapeType::Cylinder},
    {"plane", ShapeType::Plane},      {"convex_hull", ShapeType::ConvexHull},
    {"mesh", ShapeType::TriangleMesh}};

// Triangles with optional per-vertex UVs (meshes from OBJ keep theirs).
struct TriangleMeshData {
  std::vector<Vec3> vertices;
  std::vector<Vec2> uvs;  // empty or one per vertex
  // Empty, or one per vertex: the file's own unit vertex normal (glTF NORMAL, FBX, COLLADA),
  // which the per-vertex texture frames and shading follow. Without them, area-weighted face
  // normals. Contacts always use the triangle's own normal.
  std::vector<Vec3> normals;
  // Empty, or one per vertex: the file's own tangent (xyz, along +u) and bitangent sign (w: the
  // bitangent is w n x t), as glTF's TANGENT stores them. Without them, tangents come from the
  // UV gradients.
  std::vector<Vec4> tangents;
  std::vector<std::array<int, 3>> triangles;
  std::string source_file;  // OBJ path when loaded from a file (for saving scenes back)
};

struct Shape {
  ShapeType type = ShapeType::Box;
  Transform local;  // shape frame relative to the body frame (compounds = several shapes)

  Vec3 half_extents = Vec3(0.1, 0.1, 0.1);       // Box (unit: m)
  double radius = 0.1;                           // Sphere, Capsule, Cylinder (unit: m)
  double half_height = 0.1;                      // Capsule, Cylinder: half length of the axis (m)
  Vec3 plane_normal = Vec3::UnitZ();             // Plane (static bodies only)
  double plane_offset = 0.0;                     // Plane (m)
  std::shared_ptr<const TriangleMeshData> mesh;  // ConvexHull (points) or TriangleMesh
  // What renderers draw for a ConvexHull or TriangleMesh loaded from an asset: its full,
  // unsimplified mesh (collision uses `mesh`). Null: draw `mesh`.
  std::shared_ptr<const TriangleMeshData> display_mesh;

  double density = 1000.0;  // kg/m^3, for mass and inertia of dynamic bodies
  Surface surface;
};

// The resolver a C++ user calls before World::createBody for surfaces described by their
// source alone: resolveSurface for every shape, e.g.
//   resolveSurfaces(desc.shapes, world.diagnostics());
// Scenes need not: instantiate() resolves theirs (equal surfaces sharing one map). Throws
// asperity::Error naming the shape's index and the file.
void resolveSurfaces(std::span<Shape> shapes, Diagnostics& diagnostics);

}  // namespace asperity
