// Contact-frame triangles of a contact's surfaces (patch_triangles.hpp).
#include "sampler/patch_triangles.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "asperity/error.hpp"
#include "geometry/shape_mesh_internal.hpp"
#include "sampler/patch_faces.hpp"

namespace asperity::patch {

namespace {

// A corner of a face (patch_faces.hpp): position, uv and frame in the contact frame.
using Corner = FaceCorner;

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

void boxTriangles(const Volume& volume, const Shape& shape, const Placement& pl, Side side,
                  std::vector<PatchVertex>& out) {
  const double scale = detail::textureScale(shape);
  // Each front-facing face as two triangles (corners counter-clockwise seen from outside).
  std::array<BoxFace, 6> faces;
  const int count = facingBoxFaces(shape, pl, side, faces);
  for (int f = 0; f < count; ++f) {
    const BoxFace& face = faces[static_cast<size_t>(f)];
    const std::array<Corner, 4> q =
        boxFaceCorners(shape, pl, face, scale, boxFacePositions(pl, face));
    // The quad's four sides are tested exactly; its diagonal is left to the rasteriser.
    emit(volume, q[0], q[1], q[2], 0b011u, out);
    emit(volume, q[0], q[2], q[3], 0b110u, out);
  }
}

void planeTriangles(const Volume& volume, const Shape& shape, const Placement& pl, Side side,
                    std::vector<PatchVertex>& out) {
  FacingPlane plane;
  if (!facingPlane(shape, pl, side, plane)) return;
  // The plane over the footprint (one pixel wider on each side), uv through the shape frame.
  const Vec3& nc = plane.normal;
  const Vec3& p0 = plane.point;
  const Mat3 to_local = pl.m.transpose();
  const double half = 0.5 * volume.width + volume.pixel;
  Corner q[4];
  static constexpr double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int k = 0; k < 4; ++k) {
    const double x = sx[k] * half, y = sy[k] * half;
    const double z = p0.z() - (nc.x() * (x - p0.x()) + nc.y() * (y - p0.y())) / nc.z();
    const Vec3 pc(x, y, z);
    const Vec3 local = to_local * (pc - pl.o);
    q[k] = {pc,
            plane.scale * local.dot(plane.texture.t),
            plane.scale * local.dot(plane.texture.b),
            plane.t,
            plane.b,
            nc};
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

void meshTriangles(const Volume& volume, const Shape& shape, const Placement& pl, Side side,
                   MeshCache& meshes, GeometryScratch& scratch, std::vector<PatchVertex>& out) {
  const CachedMesh& cached = meshes.get(shape);
  // The volume's box in the shape frame selects candidate triangles.
  scratch.triangles.clear();
  cached.bvh.query(volumeBoxInShape(volume, pl), scratch.triangles);
  for (int index : scratch.triangles) {
    const std::array<Corner, 3> c = meshTriangleCorners(cached.mesh, index, pl);
    if (!triangleFacesOther(side, c)) continue;
    // Left to the rasteriser: mesh triangles (tessellations included) are mostly narrower
    // than a pixel.
    emit(volume, c[0], c[1], c[2], 0u, out);
  }
}

}  // namespace

void collectTriangles(const Volume& volume, const Shape& shape, const Transform& pose, Side side,
                      MeshCache& meshes, GeometryScratch& scratch, std::vector<PatchVertex>& out) {
  const Placement pl = place(volume, pose);
  switch (shape.type) {
    case ShapeType::Box:
      boxTriangles(volume, shape, pl, side, out);
      break;
    case ShapeType::Plane:
      planeTriangles(volume, shape, pl, side, out);
      break;
    case ShapeType::Sphere:
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      meshTriangles(volume, shape, pl, side, meshes, scratch, out);
      break;
  }
}

}  // namespace asperity::patch
