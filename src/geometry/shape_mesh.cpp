// Triangle meshes of shapes with uv and tangent frames (shape_mesh.hpp).
#include "asperity/geometry/shape_mesh.hpp"

#include <LinearMath/btConvexHullComputer.h>

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "geometry/shape_mesh_internal.hpp"

namespace asperity {

namespace {

// Collects vertices (frames in metres or repeats, see `add`) and triangles.
class MeshBuilder {
 public:
  MeshBuilder(ShapeMesh& mesh, double uv_scale) : mesh_(mesh), scale_(uv_scale) {}

  int add(const Vec3& p, const SurfaceFrame& f) {
    mesh_.positions.push_back(p.cast<float>());
    mesh_.uvs.push_back((f.uv * scale_).cast<float>());
    mesh_.tangents.push_back(f.t.cast<float>());
    mesh_.bitangents.push_back(f.b.cast<float>());
    mesh_.normals.push_back(f.n.cast<float>());
    return static_cast<int>(mesh_.positions.size()) - 1;
  }
  void triangle(int a, int b, int c, int feature) {
    mesh_.triangles.push_back({a, b, c});
    mesh_.features.push_back(feature);
  }
  // A quad a-b-c-d counter-clockwise seen from outside.
  void quad(int a, int b, int c, int d, int feature) {
    triangle(a, b, c, feature);
    triangle(a, c, d, feature);
  }

 private:
  ShapeMesh& mesh_;
  double scale_;
};

void buildBox(const Shape& s, MeshBuilder& out) {
  // Each face: four corners at -+T, -+B from the face centre, counter-clockwise around N.
  for (int face = 0; face < 6; ++face) {
    const SurfaceFrame f = boxFaceFrame(face);
    const Vec3 h = s.half_extents;
    const Vec3 centre = f.n.cwiseProduct(h);
    const Vec3 et = f.t.cwiseProduct(h), eb = f.b.cwiseProduct(h);
    int v[4];
    const double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
      const Vec3 p = centre + su[k] * et + sv[k] * eb;
      v[k] = out.add(p, {Vec2(p.dot(f.t), p.dot(f.b)), f.t, f.b, f.n});
    }
    out.quad(v[0], v[1], v[2], v[3], face);
  }
}

// Latitude band [lat0, lat1] of a sphere of `radius` centred at z = zc on the axis, with v
// continuing from v_offset. Rows of (segments + 1) vertices; pole rows skip degenerate triangles.
void buildSphereBand(double radius, double zc, double lat0, double lat1, int rows, int segments,
                     double v_offset, MeshBuilder& out, int feature) {
  int first = -1;
  for (int j = 0; j <= rows; ++j) {
    const double lat = lat0 + (lat1 - lat0) * j / rows;
    for (int i = 0; i <= segments; ++i) {
      const double lon = -kPi + 2.0 * kPi * i / segments;
      const SurfaceFrame f = detail::sphereFrame(radius, lon, lat, v_offset);
      const int id = out.add(Vec3(0, 0, zc) + radius * f.n, f);
      if (first < 0) first = id;
    }
  }
  // East x north is outward: (i, j) -> (i+1, j) -> (i+1, j+1) is counter-clockwise.
  const int stride = segments + 1;
  for (int j = 0; j < rows; ++j) {
    const double lat_lo = lat0 + (lat1 - lat0) * j / rows;
    const double lat_hi = lat0 + (lat1 - lat0) * (j + 1) / rows;
    for (int i = 0; i < segments; ++i) {
      const int a = first + j * stride + i, b = a + 1, c = b + stride, d = a + stride;
      if (std::abs(lat_lo) < kPi / 2 - 1e-9) out.triangle(a, b, c, feature);
      if (std::abs(lat_hi) < kPi / 2 - 1e-9) out.triangle(a, c, d, feature);
    }
  }
}

// The side of a cylinder or capsule: two rows, v = z.
void buildSide(double radius, double half_height, int segments, MeshBuilder& out) {
  int base = -1;
  for (int j = 0; j < 2; ++j) {
    const double z = j == 0 ? -half_height : half_height;
    for (int i = 0; i <= segments; ++i) {
      const double lon = -kPi + 2.0 * kPi * i / segments;
      const SurfaceFrame f = detail::sphereFrame(radius, lon, 0.0, z);
      const int id = out.add(Vec3(radius * f.n.x(), radius * f.n.y(), z), f);
      if (base < 0) base = id;
    }
  }
  for (int i = 0; i < segments; ++i) {
    const int a = base + i, b = a + 1;
    out.quad(a, b, b + segments + 1, a + segments + 1, -1);
  }
}

// A flat cap of a cylinder at z = +-half_height, mapped like the box's z faces.
void buildCap(double radius, double half_height, bool top, int segments, MeshBuilder& out) {
  const SurfaceFrame f = boxFaceFrame(top ? 4 : 5);
  const Vec3 centre(0, 0, top ? half_height : -half_height);
  const int c = out.add(centre, {Vec2(centre.dot(f.t), centre.dot(f.b)), f.t, f.b, f.n});
  int first = -1;
  for (int i = 0; i <= segments; ++i) {
    const double lon = -kPi + 2.0 * kPi * i / segments;
    const Vec3 p = centre + radius * Vec3(std::cos(lon), std::sin(lon), 0.0);
    const int id = out.add(p, {Vec2(p.dot(f.t), p.dot(f.b)), f.t, f.b, f.n});
    if (first < 0) first = id;
  }
  // Counter-clockwise seen from outside: increasing longitude on top, decreasing below.
  for (int i = 0; i < segments; ++i) {
    if (top)
      out.triangle(c, first + i, first + i + 1, -1);
    else
      out.triangle(c, first + i + 1, first + i, -1);
  }
}

// One flat-shaded triangle with the dominant-axis planar projection (metres).
void addPlanarTriangle(const std::array<Vec3, 3>& v, MeshBuilder& out, int feature) {
  const Vec3 cross = (v[1] - v[0]).cross(v[2] - v[0]);
  if (!(cross.squaredNorm() > 0.0)) return;  // degenerate
  const SurfaceFrame f = detail::dominantAxisFrame(cross.normalized());
  int id[3];
  for (int k = 0; k < 3; ++k)
    id[k] = out.add(v[k], {Vec2(v[k].dot(f.t), v[k].dot(f.b)), f.t, f.b, f.n});
  out.triangle(id[0], id[1], id[2], feature);
}

void buildHull(const TriangleMeshData& data, MeshBuilder& out) {
  if (data.vertices.size() < 4) throw Error("convex hull needs at least 4 points");
  btConvexHullComputer hull;
  hull.compute(data.vertices.front().data(), static_cast<int>(sizeof(Vec3)),
               static_cast<int>(data.vertices.size()), 0.0, 0.0);
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : data.vertices) centroid += p;
  centroid /= static_cast<double>(data.vertices.size());
  auto vertex = [&](int i) {
    const btVector3& q = hull.vertices[i];
    return Vec3(q.x(), q.y(), q.z());
  };
  // Fan-triangulate every face; orient each triangle away from the centroid.
  for (int face = 0; face < hull.faces.size(); ++face) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[face]];
    const Vec3 v0 = vertex(first->getSourceVertex());
    const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace();
    while (e->getTargetVertex() != first->getSourceVertex()) {
      std::array<Vec3, 3> tri{v0, vertex(e->getSourceVertex()), vertex(e->getTargetVertex())};
      if ((tri[1] - tri[0]).cross(tri[2] - tri[0]).dot(tri[0] - centroid) < 0.0) {
        std::swap(tri[1], tri[2]);
      }
      addPlanarTriangle(tri, out, face);
      e = e->getNextEdgeOfFace();
    }
  }
}

// Triangle mesh with its own UVs: shared vertices, area-weighted normals, and the file's tangents
// or else UV-gradient tangents accumulated per vertex (MikkTSpace's convention: t along +u, the
// bitangent's sign kept, so mirrored UV islands stay mirrored).
void buildUvMesh(const TriangleMeshData& data, ShapeMesh& mesh) {
  const size_t nv = data.vertices.size();
  std::vector<Vec3> n(nv, Vec3::Zero()), t(nv, Vec3::Zero()), b(nv, Vec3::Zero());
  // Accumulate per-triangle normals (area weighted) and UV gradients.
  for (const auto& tri : data.triangles) {
    const std::array<Vec3, 3> v{data.vertices[tri[0]], data.vertices[tri[1]],
                                data.vertices[tri[2]]};
    const std::array<Vec2, 3> uv{data.uvs[tri[0]], data.uvs[tri[1]], data.uvs[tri[2]]};
    const Vec3 cross = (v[1] - v[0]).cross(v[2] - v[0]);
    if (!(cross.squaredNorm() > 0.0)) continue;
    const SurfaceFrame f = detail::gradientFrame(v, uv, cross.normalized());
    for (int k = 0; k < 3; ++k) {
      n[tri[k]] += cross;
      t[tri[k]] += f.t;
      b[tri[k]] += f.b;
    }
  }
  // Per vertex: orthogonalise.
  MeshBuilder out(mesh, 1.0);
  for (size_t i = 0; i < nv; ++i) {
    const Vec3 ni = !data.normals.empty()      ? data.normals[i]
                    : n[i].squaredNorm() > 0.0 ? n[i].normalized()
                                               : Vec3::UnitZ();
    if (!data.tangents.empty()) {
      t[i] = data.tangents[i].head<3>();
      b[i] = data.tangents[i].w() * ni.cross(t[i]);
    }
    SurfaceFrame f = detail::orthogonalFrame(t[i], b[i], ni);
    f.uv = data.uvs[i];
    out.add(data.vertices[i], f);
  }
  for (size_t k = 0; k < data.triangles.size(); ++k) {
    const auto& tri = data.triangles[k];
    out.triangle(tri[0], tri[1], tri[2], static_cast<int>(k));
  }
}

void buildTriangleMesh(const TriangleMeshData& data, ShapeMesh& mesh, double scale) {
  // Check indices and UV count first.
  const int nv = static_cast<int>(data.vertices.size());
  for (size_t k = 0; k < data.triangles.size(); ++k) {
    for (int idx : data.triangles[k]) {
      if (idx < 0 || idx >= nv) {
        throw Error("triangle mesh: triangle " + std::to_string(k) + " uses vertex " +
                    std::to_string(idx) + " (mesh has " + std::to_string(nv) + ")");
      }
    }
  }
  if (!data.uvs.empty() && data.uvs.size() != data.vertices.size()) {
    throw Error("triangle mesh: " + std::to_string(data.uvs.size()) + " UVs for " +
                std::to_string(nv) + " vertices");
  }
  if (!data.normals.empty() && data.normals.size() != data.vertices.size())
    throw Error("triangle mesh: " + std::to_string(data.normals.size()) + " normals for " +
                std::to_string(nv) + " vertices");
  if (!data.tangents.empty() && (data.tangents.size() != data.vertices.size() || data.uvs.empty()))
    throw Error("triangle mesh: " + std::to_string(data.tangents.size()) + " tangents for " +
                std::to_string(nv) + " vertices" + (data.uvs.empty() ? " without UVs" : ""));
  if (!data.uvs.empty()) return buildUvMesh(data, mesh);
  // Without UVs: flat-shaded planar projection per triangle.
  MeshBuilder out(mesh, scale);
  for (size_t k = 0; k < data.triangles.size(); ++k) {
    const auto& tri = data.triangles[k];
    addPlanarTriangle({data.vertices[tri[0]], data.vertices[tri[1]], data.vertices[tri[2]]}, out,
                      static_cast<int>(k));
  }
}

void buildPlane(const Shape& s, const ShapeMeshOptions& o, MeshBuilder& out) {
  // A square of plane_size around the plane point nearest plane_centre, in tiles.
  const SurfaceFrame f = detail::planeFrame(s.plane_normal);
  const Vec3 origin = o.plane_centre - (o.plane_centre.dot(f.n) - s.plane_offset) * f.n;
  const int n = o.plane_tiles;
  int base = -1;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Vec3 p =
          origin + o.plane_size * ((double(i) / n - 0.5) * f.t + (double(j) / n - 0.5) * f.b);
      const int id = out.add(p, {Vec2(p.dot(f.t), p.dot(f.b)), f.t, f.b, f.n});
      if (base < 0) base = id;
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = base + j * (n + 1) + i;
      out.quad(a, a + 1, a + n + 2, a + n + 1, -1);
    }
  }
}

// Applies the surface's texture rotation to every vertex.
void rotateAll(ShapeMesh& mesh, double rotation) {
  if (rotation == 0.0) return;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    SurfaceFrame f{mesh.uvs[i].cast<double>(), mesh.tangents[i].cast<double>(),
                   mesh.bitangents[i].cast<double>(), mesh.normals[i].cast<double>()};
    f = rotateTexture(f, rotation);
    mesh.uvs[i] = f.uv.cast<float>();
    mesh.tangents[i] = f.t.cast<float>();
    mesh.bitangents[i] = f.b.cast<float>();
  }
}

}  // namespace

ShapeMesh buildShapeMesh(const Shape& shape, const ShapeMeshOptions& o) {
  if (o.segments < 3 || o.rings < 2 || o.plane_tiles < 1 || !(o.plane_size > 0.0)) {
    throw Error("buildShapeMesh: need segments >= 3, rings >= 2, plane_tiles >= 1, plane_size > 0");
  }
  const double scale = detail::textureScale(shape);
  ShapeMesh mesh;
  MeshBuilder out(mesh, scale);
  switch (shape.type) {
    case ShapeType::Box:
      buildBox(shape, out);
      break;
    case ShapeType::Sphere:
      buildSphereBand(shape.radius, 0.0, -kPi / 2, kPi / 2, o.rings, o.segments, 0.0, out, -1);
      break;
    case ShapeType::Cylinder:
      buildSide(shape.radius, shape.half_height, o.segments, out);
      buildCap(shape.radius, shape.half_height, true, o.segments, out);
      buildCap(shape.radius, shape.half_height, false, o.segments, out);
      break;
    case ShapeType::Capsule: {
      const int rows = std::max(1, o.rings / 2);
      buildSide(shape.radius, shape.half_height, o.segments, out);
      buildSphereBand(shape.radius, shape.half_height, 0.0, kPi / 2, rows, o.segments,
                      shape.half_height, out, -1);
      buildSphereBand(shape.radius, -shape.half_height, -kPi / 2, 0.0, rows, o.segments,
                      -shape.half_height, out, -1);
      break;
    }
    case ShapeType::Plane:
      buildPlane(shape, o, out);
      break;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      if (!shape.mesh) throw Error("buildShapeMesh: mesh shape without mesh data");
      if (shape.type == ShapeType::ConvexHull)
        buildHull(*shape.mesh, out);
      else
        buildTriangleMesh(*shape.mesh, mesh, scale);
      break;
  }
  rotateAll(mesh, shape.surface.texture_rotation);
  return mesh;
}

}  // namespace asperity
