// Convex shapes against planes (see plane_contacts.hpp).
#include "collision/plane_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace asperity::collision_detail {

namespace {

// The exact candidate points of a shape's surface that can be lowest against `n`.
std::vector<Vec3> candidates(const Shape& shape, const Transform& world, const Vec3& n) {
  std::vector<Vec3> out;
  switch (shape.type) {
    case ShapeType::Sphere:
      out.push_back(world.position - shape.radius * n);
      break;
    case ShapeType::Capsule:
      for (double s : {-1.0, 1.0}) {
        out.push_back(world.apply(Vec3(0, 0, s * shape.half_height)) - shape.radius * n);
      }
      break;
    case ShapeType::Box:
      for (int i = 0; i < 8; ++i) {
        const Vec3& h = shape.half_extents;
        out.push_back(world.apply(
            Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z())));
      }
      break;
    case ShapeType::Cylinder: {
      // Per cap: four rim points along the local axes and the rim's lowest point.
      const Vec3 axis = world.rotation * Vec3::UnitZ();
      const Vec3 across = n - n.dot(axis) * axis;
      for (double s : {-1.0, 1.0}) {
        const double r = shape.radius;
        const size_t first = out.size();
        for (const Vec2& d : {Vec2(r, 0), Vec2(0, r), Vec2(-r, 0), Vec2(0, -r)}) {
          out.push_back(world.apply(Vec3(d.x(), d.y(), s * shape.half_height)));
        }
        // (Standing upright the rim is level and the four points suffice; a lowest point
        // that is one of the four is not repeated.)
        if (across.norm() < 1e-9) continue;
        const Vec3 lowest =
            world.apply(Vec3(0, 0, s * shape.half_height)) - r * across.normalized();
        const bool repeated =
            std::any_of(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                        [&](const Vec3& p) { return (p - lowest).norm() < 1e-9 * r; });
        if (!repeated) out.push_back(lowest);
      }
      break;
    }
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      if (shape.mesh) {
        for (const Vec3& v : shape.mesh->vertices) out.push_back(world.apply(v));
      }
      break;
    case ShapeType::Plane:
      break;
  }
  return out;
}

// Index of the point maximising score(i) among those not yet chosen.
template <typename Score>
int best(const std::vector<PlanePoint>& pts, const std::vector<int>& chosen, Score score) {
  int arg = -1;
  double top = -1.0;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    if (std::find(chosen.begin(), chosen.end(), i) != chosen.end()) continue;
    const double s = score(pts[static_cast<size_t>(i)]);
    if (s > top) top = s, arg = i;
  }
  return arg;
}

// Four spread points: the deepest, the farthest from it, the largest triangle, then the
// point farthest from the three chosen.
std::vector<PlanePoint> reduceToFour(const std::vector<PlanePoint>& pts, const Vec3& n) {
  std::vector<int> chosen{0};
  for (size_t i = 1; i < pts.size(); ++i) {
    if (pts[i].distance < pts[static_cast<size_t>(chosen[0])].distance)
      chosen[0] = static_cast<int>(i);
  }
  const Vec3 p0 = pts[static_cast<size_t>(chosen[0])].point;
  chosen.push_back(
      best(pts, chosen, [&](const PlanePoint& p) { return (p.point - p0).squaredNorm(); }));
  const Vec3 p1 = pts[static_cast<size_t>(chosen[1])].point;
  chosen.push_back(best(pts, chosen, [&](const PlanePoint& p) {
    return std::abs((p1 - p0).cross(p.point - p0).dot(n));
  }));
  const Vec3 p2 = pts[static_cast<size_t>(chosen[2])].point;
  chosen.push_back(best(pts, chosen, [&](const PlanePoint& p) {
    return std::min(
        {(p.point - p0).squaredNorm(), (p.point - p1).squaredNorm(), (p.point - p2).squaredNorm()});
  }));
  std::vector<PlanePoint> out;
  for (int c : chosen) out.push_back(pts[static_cast<size_t>(c)]);
  return out;
}

}  // namespace

WorldPlane worldPlane(const Shape& plane, const Transform& plane_world) {
  const Vec3 n_local = plane.plane_normal.normalized();
  WorldPlane out;
  out.normal = plane_world.rotation * n_local;
  out.offset = out.normal.dot(plane_world.apply(n_local * plane.plane_offset));
  return out;
}

std::vector<PlanePoint> planePoints(const Shape& shape, const Transform& world,
                                    const WorldPlane& plane, double max_distance) {
  // Signed distances of all candidates; keep those within reach.
  std::vector<PlanePoint> pts;
  const std::vector<Vec3> cand = candidates(shape, world, plane.normal);
  for (size_t i = 0; i < cand.size(); ++i) {
    const double d = plane.normal.dot(cand[i]) - plane.offset;
    if (d < max_distance) pts.push_back({static_cast<int>(i), cand[i], d});
  }
  if (pts.size() <= 4) return pts;
  return reduceToFour(pts, plane.normal);
}

}  // namespace asperity::collision_detail
