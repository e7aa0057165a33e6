// The analytic texture mapping of every shape (shape_mesh.hpp): uv and tangent frame at a point.
#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "geometry/shape_mesh_internal.hpp"

namespace asperity {

namespace {

// Planar frame: uv from projecting the point on T and B (metres).
SurfaceFrame planarFrame(const SurfaceFrame& f, const Vec3& p) {
  return {Vec2(p.dot(f.t), p.dot(f.b)), f.t, f.b, f.n};
}

// Frame of a cylinder's or capsule's side at a point (metres; v = z).
SurfaceFrame sideFrame(double radius, const Vec3& p) {
  const double lon = std::atan2(p.y(), p.x());
  return detail::sphereFrame(radius, lon, 0.0, p.z());
}

// Frame of a (cap) sphere centred at `centre` on the axis, continuing v from `v_offset`.
SurfaceFrame capFrame(double radius, const Vec3& centre, double v_offset, const Vec3& p) {
  const Vec3 q = p - centre;
  const double len = q.norm();
  const double lon = std::atan2(q.y(), q.x());
  const double lat = len > 0.0 ? std::asin(std::clamp(q.z() / len, -1.0, 1.0)) : 0.0;
  return detail::sphereFrame(radius, lon, lat, v_offset);
}

SurfaceFrame cylinderFrame(const Shape& s, const Vec3& p) {
  // Nearest of side and caps decides which mapping applies.
  const double radial = std::hypot(p.x(), p.y());
  const double to_side = std::abs(s.radius - radial);
  const double to_cap = std::abs(s.half_height - std::abs(p.z()));
  if (to_cap < to_side) return planarFrame(boxFaceFrame(p.z() >= 0.0 ? 4 : 5), p);
  return sideFrame(s.radius, p);
}

SurfaceFrame capsuleFrame(const Shape& s, const Vec3& p) {
  // Side between the cap centres, spheres beyond them.
  if (std::abs(p.z()) <= s.half_height) return sideFrame(s.radius, p);
  const double sign = p.z() > 0.0 ? 1.0 : -1.0;
  return capFrame(s.radius, Vec3(0, 0, sign * s.half_height), sign * s.half_height, p);
}

// Triangle `index` of a mesh shape: per-triangle planar or UV-gradient frame at the point.
SurfaceFrame meshFrame(const Shape& s, int index, const Vec3& p) {
  const TriangleMeshData& data = *s.mesh;
  if (index < 0 || static_cast<size_t>(index) >= data.triangles.size()) {
    throw Error("surfaceFrameAt: triangle " + std::to_string(index) + " out of range (mesh has " +
                std::to_string(data.triangles.size()) + ")");
  }
  const auto& tri = data.triangles[static_cast<size_t>(index)];
  std::array<Vec3, 3> v;
  for (int k = 0; k < 3; ++k) v[k] = data.vertices.at(static_cast<size_t>(tri[k]));
  const Vec3 n = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
  // Without UVs: planar projection along the dominant axis, in texture_size units later.
  if (data.uvs.empty()) {
    const SurfaceFrame f = detail::dominantAxisFrame(n);
    return planarFrame(f, p);
  }
  // With UVs: barycentric uv, tangent frame from the UV gradients (already in repeats).
  std::array<Vec2, 3> uv;
  for (int k = 0; k < 3; ++k) uv[k] = data.uvs.at(static_cast<size_t>(tri[k]));
  const Vec3 l = detail::barycentric(v, p);
  SurfaceFrame f;
  if (data.tangents.size() == data.vertices.size()) {
    // The file's tangents, interpolated; the first corner's bitangent sign.
    Vec3 t = Vec3::Zero();
    for (int k = 0; k < 3; ++k) t += l[k] * data.tangents[static_cast<size_t>(tri[k])].head<3>();
    f = detail::orthogonalFrame(t, data.tangents[static_cast<size_t>(tri[0])].w() * n.cross(t), n);
  } else {
    f = detail::gradientFrame(v, uv, n);
  }
  f.uv = l[0] * uv[0] + l[1] * uv[1] + l[2] * uv[2];
  return f;
}

}  // namespace

namespace detail {

SurfaceFrame sphereFrame(double radius, double lon, double lat, double v_offset) {
  // T east, B north, N radial (T x B = N); arc lengths in metres.
  const double cl = std::cos(lon), sl = std::sin(lon);
  const double ca = std::cos(lat), sa = std::sin(lat);
  SurfaceFrame f;
  f.uv = Vec2(radius * lon, v_offset + radius * lat);
  f.t = Vec3(-sl, cl, 0.0);
  f.b = Vec3(-sa * cl, -sa * sl, ca);
  f.n = Vec3(ca * cl, ca * sl, sa);
  return f;
}

SurfaceFrame dominantAxisFrame(const Vec3& n) {
  // The box face of the dominant axis gives T, projected onto the triangle's plane.
  int axis = 0;
  n.cwiseAbs().maxCoeff(&axis);
  const SurfaceFrame box = boxFaceFrame(2 * axis + (n[axis] < 0.0 ? 1 : 0));
  SurfaceFrame f;
  f.n = n;
  f.t = (box.t - box.t.dot(n) * n).normalized();
  f.b = n.cross(f.t);
  return f;
}

SurfaceFrame gradientFrame(const std::array<Vec3, 3>& v, const std::array<Vec2, 3>& uv,
                           const Vec3& n) {
  // dP = T du + B dv over two edges, solved for T and B (the UV gradients).
  const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0];
  const Vec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
  const double det = d1.x() * d2.y() - d2.x() * d1.y();
  if (std::abs(det) < 1e-20) return dominantAxisFrame(n);  // degenerate UVs
  const Vec3 t = (e1 * d2.y() - e2 * d1.y()) / det;
  const Vec3 b = (e2 * d1.x() - e1 * d2.x()) / det;
  return orthogonalFrame(t, b, n);
}

SurfaceFrame orthogonalFrame(const Vec3& t, const Vec3& b, const Vec3& n) {
  // Gram-Schmidt T against N; B = sign N x T keeps mirrored UVs mirrored.
  SurfaceFrame f;
  f.n = n;
  Vec3 tt = t - t.dot(n) * n;
  if (tt.squaredNorm() < 1e-24) return dominantAxisFrame(n);
  f.t = tt.normalized();
  const double sign = n.cross(f.t).dot(b) < 0.0 ? -1.0 : 1.0;
  f.b = sign * n.cross(f.t);
  return f;
}

Vec3 barycentric(const std::array<Vec3, 3>& v, const Vec3& p) {
  // Least-squares barycentrics of p projected onto the triangle's plane.
  const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], d = p - v[0];
  const double a = e1.dot(e1), b = e1.dot(e2), c = e2.dot(e2);
  const double det = a * c - b * b;
  if (!(std::abs(det) > 0.0)) return Vec3(1.0, 0.0, 0.0);
  const double l1 = (c * d.dot(e1) - b * d.dot(e2)) / det;
  const double l2 = (a * d.dot(e2) - b * d.dot(e1)) / det;
  return Vec3(1.0 - l1 - l2, l1, l2);
}

SurfaceFrame planeFrame(const Vec3& normal) {
  // x projected on the plane, or y when x is within 25 degrees of the normal.
  const Vec3 n = normal.normalized();
  const Vec3 axis = std::abs(n.x()) > 0.906 ? Vec3::UnitY() : Vec3::UnitX();
  SurfaceFrame f;
  f.n = n;
  f.t = (axis - axis.dot(n) * n).normalized();
  f.b = n.cross(f.t);
  return f;
}

double textureScale(const Shape& shape) {
  const double size = shape.surface.texture_size;
  if (!std::isfinite(size) || !(size > 0.0)) {
    throw Error("surface.texture_size must be a positive finite length (m), got " +
                std::to_string(size));
  }
  return 1.0 / size;
}

}  // namespace detail

int boxFaceAt(const Vec3& half_extents, const Vec3& p) {
  // The face whose plane is nearest to the point.
  int best = 0;
  double best_distance = 1e300;
  for (int axis = 0; axis < 3; ++axis) {
    for (int neg = 0; neg < 2; ++neg) {
      const double coord = neg ? -p[axis] : p[axis];
      const double distance = std::abs(half_extents[axis] - coord);
      if (distance < best_distance) best_distance = distance, best = 2 * axis + neg;
    }
  }
  return best;
}

SurfaceFrame boxFaceFrame(int face) {
  // The table of shape_mesh.hpp: z faces T = +x; side faces wrap around z with B = +z.
  static const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  switch (face) {
    case 0:
      return {Vec2::Zero(), y, z, x};
    case 1:
      return {Vec2::Zero(), -y, z, -x};
    case 2:
      return {Vec2::Zero(), -x, z, y};
    case 3:
      return {Vec2::Zero(), x, z, -y};
    case 4:
      return {Vec2::Zero(), x, y, z};
    case 5:
      return {Vec2::Zero(), x, -y, -z};
    default:
      throw Error("boxFaceFrame: face " + std::to_string(face) + " is not in 0..5");
  }
}

SurfaceFrame rotateTexture(const SurfaceFrame& f, double rotation) {
  if (rotation == 0.0) return f;
  // The texture's +u axis turns by `rotation` from T toward B.
  const double c = std::cos(rotation), s = std::sin(rotation);
  SurfaceFrame out;
  out.uv = Vec2(c * f.uv.x() + s * f.uv.y(), -s * f.uv.x() + c * f.uv.y());
  out.t = c * f.t + s * f.b;
  out.b = -s * f.t + c * f.b;
  out.n = f.n;
  return out;
}

SurfaceFrame surfaceFrameAt(const Shape& shape, int feature, const Vec3& p) {
  const double scale = detail::textureScale(shape);
  SurfaceFrame f;
  bool mesh_uvs = false;
  // The face mapping in metres (mesh UVs are already in repeats).
  switch (shape.type) {
    case ShapeType::Box: {
      const int face = feature >= 0 && feature < 6 ? feature : boxFaceAt(shape.half_extents, p);
      const SurfaceFrame box = boxFaceFrame(face);
      f = planarFrame(box, p);
      break;
    }
    case ShapeType::Sphere:
      f = capFrame(shape.radius, Vec3::Zero(), 0.0, p);
      break;
    case ShapeType::Cylinder:
      f = cylinderFrame(shape, p);
      break;
    case ShapeType::Capsule:
      f = capsuleFrame(shape, p);
      break;
    case ShapeType::Plane: {
      const SurfaceFrame plane = detail::planeFrame(shape.plane_normal);
      f = planarFrame(plane, p);
      break;
    }
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh: {
      if (!shape.mesh) throw Error("surfaceFrameAt: mesh shape without mesh data");
      if (feature >= 0 && !shape.mesh->triangles.empty()) {
        f = meshFrame(shape, feature, p);
        mesh_uvs = !shape.mesh->uvs.empty();
      } else {
        const SurfaceFrame d =
            detail::dominantAxisFrame(p.norm() > 0.0 ? p.normalized() : Vec3::UnitZ());
        f = planarFrame(d, p);
      }
      break;
    }
  }
  // Metres to repeats, then the texture's own rotation.
  if (!mesh_uvs) f.uv *= scale;
  return rotateTexture(f, shape.surface.texture_rotation);
}

}  // namespace asperity
