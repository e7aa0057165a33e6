// Contact-frame triangles of a contact's surfaces (patch_triangles.hpp).
#include "sampler/patch_triangles.hpp"

#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "geometry/shape_mesh_internal.hpp"

namespace asperity::patch {

namespace {

struct Corner {
  Vec3 p;  // contact frame
  double u = 0.0, v = 0.0;
  Vec3 t, b, n;  // contact frame
};

PatchVertex toVertex(const Corner& c, double du, double dv) {
  PatchVertex v{};
  for (int k = 0; k < 3; ++k) {
    v.p[k] = static_cast<float>(c.p[k]);
    v.t[k] = static_cast<float>(c.t[k]);
    v.b[k] = static_cast<float>(c.b[k]);
    v.n[k] = static_cast<float>(c.n[k]);
  }
  v.uv[0] = static_cast<float>(c.u - du);
  v.uv[1] = static_cast<float>(c.v - dv);
  return v;
}

Corner lerp(const Corner& a, const Corner& b, double s) {
  return {a.p + s * (b.p - a.p), a.u + s * (b.u - a.u), a.v + s * (b.v - a.v),
          a.t + s * (b.t - a.t), a.b + s * (b.b - a.b), a.n + s * (b.n - a.n)};
}

// Sutherland-Hodgman against sign * p[axis] <= limit; attributes interpolate linearly, as the
// rasteriser would across the triangle.
int clipPolygon(const Corner* in, int count, int axis, double sign, double limit, Corner* out) {
  int n = 0;
  for (int k = 0; k < count; ++k) {
    const Corner& a = in[k];
    const Corner& b = in[(k + 1) % count];
    const double da = sign * a.p[axis] - limit, db = sign * b.p[axis] - limit;
    if (da <= 0.0) out[n++] = a;
    if ((da <= 0.0) != (db <= 0.0)) out[n++] = lerp(a, b, da / (da - db));
  }
  return n;
}

// Exact edge tests of triangle (a, b, c) as the CPU sampler's makePlanar sets them up: made
// counter-clockwise in the contact plane, then inside when e > 0, or e == 0 on a top or left
// edge. Bit k of `edge_mask` keeps edge k (from corner k to corner k + 1); the others pass.
struct EdgeTests {
  float e[3][4] = {{0, 0, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}};
};

EdgeTests edgeTests(const Corner& a, const Corner& b, const Corner& c, unsigned edge_mask) {
  EdgeTests tests;
  const Vec3* p[3] = {&a.p, &b.p, &c.p};
  const double area =
      (b.p.x() - a.p.x()) * (c.p.y() - a.p.y()) - (b.p.y() - a.p.y()) * (c.p.x() - a.p.x());
  for (int k = 0; k < 3; ++k) {
    if ((edge_mask & (1u << k)) == 0) continue;
    // Clockwise triangles (side A seen from +n) run their edges backwards.
    const Vec3& from = area >= 0.0 ? *p[k] : *p[(k + 1) % 3];
    const Vec3& to = area >= 0.0 ? *p[(k + 1) % 3] : *p[k];
    const double ea = -(to.y() - from.y()), eb = to.x() - from.x();
    const double len = std::hypot(ea, eb);
    if (!(len > 0.0)) continue;
    const double ec = -(ea * from.x() + eb * from.y());
    const bool inclusive = to.y() < from.y() || (to.y() == from.y() && to.x() < from.x());
    float* e = tests.e[static_cast<size_t>(k)];
    e[0] = static_cast<float>(ea / len);
    e[1] = static_cast<float>(eb / len);
    e[2] = static_cast<float>(ec / len);
    e[3] = inclusive ? 1.0f : 0.0f;
  }
  return tests;
}

// Moves every edge of the triangle's projection outward by 1/64 pixel (scaling about its
// incentre, attributes extrapolated alike), so that the rasteriser's snapped edges still
// produce every fragment the exact edge tests keep; the tests discard the rest. Triangles
// narrower than a pixel (near edge-on faces) are left to the rasteriser as they are: their
// depth varies too fast across them for a pixel centre on their edge to be decided alike.
void grow(Corner* tri, double pixel) {
  const double la = (tri[2].p - tri[1].p).head<2>().norm();
  const double lb = (tri[0].p - tri[2].p).head<2>().norm();
  const double lc = (tri[1].p - tri[0].p).head<2>().norm();
  const double perimeter = la + lb + lc;
  const Vec3 e1 = tri[1].p - tri[0].p, e2 = tri[2].p - tri[0].p;
  const double inradius = std::abs(e1.x() * e2.y() - e1.y() * e2.x()) / perimeter;
  if (!(inradius >= pixel)) return;
  // The incentre as a corner: weights la, lb, lc (as two lerps).
  const Corner ab = lerp(tri[0], tri[1], lb / (la + lb));
  const Corner centre = lerp(ab, tri[2], lc / perimeter);
  const double scale = 1.0 + pixel / 64.0 / inradius;
  for (int k = 0; k < 3; ++k) tri[k] = lerp(centre, tri[k], scale);
}

// A triangle clipped to the footprint (one pixel wider on each side, so the vertices the GPU
// sees stay near the tile whatever the shape's size) and kept when its depth range meets the
// volume's; whole repeats of the first uv removed; fan-triangulated. Box faces carry their sides'
// exact tests (edge_mask, see edgeTests) and are grown to let the tests decide.
void emit(const Volume& volume, const Corner& a, const Corner& b, const Corner& c,
          unsigned edge_mask, std::vector<PatchVertex>& out) {
  const double zmin = std::min({a.p.z(), b.p.z(), c.p.z()});
  const double zmax = std::max({a.p.z(), b.p.z(), c.p.z()});
  if (zmin > volume.half_depth || zmax < -volume.half_depth) return;
  Corner poly[2][8] = {{a, b, c}, {}};
  int count = 3, cur = 0;
  const double limit = 0.5 * volume.width + volume.pixel;
  for (int axis = 0; axis < 2 && count > 0; ++axis) {
    for (double sign : {1.0, -1.0}) {
      count = clipPolygon(poly[cur], count, axis, sign, limit, poly[1 - cur]);
      cur = 1 - cur;
      if (count == 0) return;
    }
  }
  const double du = std::floor(poly[cur][0].u), dv = std::floor(poly[cur][0].v);
  const EdgeTests tests = edgeTests(a, b, c, edge_mask);
  for (int k = 1; k + 1 < count; ++k) {
    Corner tri[3] = {poly[cur][0], poly[cur][k], poly[cur][k + 1]};
    if (edge_mask != 0) grow(tri, volume.pixel);
    for (const Corner& corner : tri) {
      PatchVertex v = toVertex(corner, du, dv);
      std::copy(&tests.e[0][0], &tests.e[0][0] + 12, &v.edges[0][0]);
      out.push_back(v);
    }
  }
}

bool facesOther(Side side, double normal_z) {
  return side == Side::B ? normal_z > 0.0 : normal_z < 0.0;
}

void boxTriangles(const Volume& volume, const Shape& shape, const Mat3& m, const Vec3& o, Side side,
                  std::vector<PatchVertex>& out) {
  const double scale = detail::textureScale(shape);
  const Vec3 h = shape.half_extents;
  // Each front-facing face as two triangles (corners counter-clockwise seen from outside).
  for (int face = 0; face < 6; ++face) {
    const SurfaceFrame f = boxFaceFrame(face);
    const Vec3 nc = m * f.n;
    if (!facesOther(side, nc.z())) continue;
    const SurfaceFrame tex = rotateTexture(f, shape.surface.texture_rotation);
    const Vec3 centre = f.n.cwiseProduct(h), et = f.t.cwiseProduct(h), eb = f.b.cwiseProduct(h);
    static constexpr double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    Corner q[4];
    for (int k = 0; k < 4; ++k) {
      const Vec3 p = centre + su[k] * et + sv[k] * eb;
      q[k] = {m * p + o, scale * p.dot(tex.t), scale * p.dot(tex.b), m * tex.t, m * tex.b, nc};
    }
    // The quad's four sides are tested exactly; its diagonal is left to the rasteriser.
    emit(volume, q[0], q[1], q[2], 0b011u, out);
    emit(volume, q[0], q[2], q[3], 0b110u, out);
  }
}

void planeTriangles(const Volume& volume, const Shape& shape, const Mat3& m, const Vec3& o,
                    Side side, std::vector<PatchVertex>& out) {
  const double len = shape.plane_normal.norm();
  if (!(len > 0.0)) throw Error("plane shape: plane_normal is zero");
  const Vec3 nl = shape.plane_normal / len;
  const Vec3 nc = m * nl;
  if (!facesOther(side, nc.z()) || std::abs(nc.z()) < 1e-9) return;
  // The plane over the footprint (one pixel wider on each side), uv through the shape frame.
  const SurfaceFrame tex = rotateTexture(detail::planeFrame(nl), shape.surface.texture_rotation);
  const double scale = detail::textureScale(shape);
  const Vec3 p0 = m * (shape.plane_offset / len * nl) + o;
  const Mat3 to_local = m.transpose();
  const double half = 0.5 * volume.width + volume.pixel;
  Corner q[4];
  static constexpr double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int k = 0; k < 4; ++k) {
    const double x = sx[k] * half, y = sy[k] * half;
    const double z = p0.z() - (nc.x() * (x - p0.x()) + nc.y() * (y - p0.y())) / nc.z();
    const Vec3 pc(x, y, z);
    const Vec3 pl = to_local * (pc - o);
    q[k] = {pc, scale * pl.dot(tex.t), scale * pl.dot(tex.b), m * tex.t, m * tex.b, nc};
  }
  // Counter-clockwise seen from +n; reversed for A (which faces -n).
  // The plane covers the whole footprint: no edge to test.
  if (side == Side::B) {
    emit(volume, q[0], q[1], q[2], 0u, out);
    emit(volume, q[0], q[2], q[3], 0u, out);
  } else {
    emit(volume, q[0], q[2], q[1], 0u, out);
    emit(volume, q[0], q[3], q[2], 0u, out);
  }
}

void meshTriangles(const Volume& volume, const Shape& shape, const Mat3& m, const Vec3& o,
                   Side side, MeshCache& meshes, GeometryScratch& scratch,
                   std::vector<PatchVertex>& out) {
  const CachedMesh& cached = meshes.get(shape);
  const ShapeMesh& mesh = cached.mesh;
  // The volume's box in the shape frame selects candidate triangles.
  const Mat3 to_local = m.transpose();
  Aabb box;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner(c & 1 ? 0.5 * volume.width : -0.5 * volume.width,
                      c & 2 ? 0.5 * volume.width : -0.5 * volume.width,
                      c & 4 ? volume.half_depth : -volume.half_depth);
    box.grow(Vec3f((to_local * (corner - o)).cast<float>()));
  }
  scratch.triangles.clear();
  cached.bvh.query(box, scratch.triangles);
  for (int index : scratch.triangles) {
    const auto& tri = mesh.triangles[static_cast<size_t>(index)];
    Corner c[3];
    for (int k = 0; k < 3; ++k) {
      const auto vi = static_cast<size_t>(tri[static_cast<size_t>(k)]);
      c[k] = {m * mesh.positions[vi].cast<double>() + o,
              mesh.uvs[vi].x(),
              mesh.uvs[vi].y(),
              m * mesh.tangents[vi].cast<double>(),
              m * mesh.bitangents[vi].cast<double>(),
              m * mesh.normals[vi].cast<double>()};
    }
    const Vec3 e1 = c[1].p - c[0].p, e2 = c[2].p - c[0].p;
    if (!facesOther(side, e1.x() * e2.y() - e1.y() * e2.x())) continue;
    // Left to the rasteriser: mesh triangles (tessellations included) are mostly narrower
    // than a pixel.
    emit(volume, c[0], c[1], c[2], 0u, out);
  }
}

}  // namespace

void collectTriangles(const Volume& volume, const Shape& shape, const Transform& pose, Side side,
                      MeshCache& meshes, GeometryScratch& scratch, std::vector<PatchVertex>& out) {
  const Mat3 at = volume.axes.transpose();
  const Mat3 m = at * pose.rotation.toRotationMatrix();
  const Vec3 o = at * (pose.position - volume.origin);
  switch (shape.type) {
    case ShapeType::Box:
      boxTriangles(volume, shape, m, o, side, out);
      break;
    case ShapeType::Plane:
      planeTriangles(volume, shape, m, o, side, out);
      break;
    case ShapeType::Sphere:
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      meshTriangles(volume, shape, m, o, side, meshes, scratch, out);
      break;
  }
}

}  // namespace asperity::patch
