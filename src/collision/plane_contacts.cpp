// Convex shapes against planes (see plane_contacts.hpp).
#include "collision/plane_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

namespace asperity::collision_detail {

namespace {

// The exact candidate points of a shape's surface that can be lowest against `n`, into `out`.
void candidates(const Shape& shape, const Transform& world, const Vec3& n, std::vector<Vec3>& out) {
  out.clear();
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
}

// Index of the point maximising score(i) among those not yet chosen.
template <typename Score>
int best(const std::vector<PlanePoint>& pts, std::span<const int> chosen, Score score) {
  int arg = -1;
  double top = -1.0;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    if (std::find(chosen.begin(), chosen.end(), i) != chosen.end()) continue;
    const double s = score(pts[static_cast<size_t>(i)]);
    if (s > top) top = s, arg = i;
  }
  return arg;
}

// Four spread points of `pts` into `out`: the deepest, the farthest from it, the largest
// triangle, then the point farthest from the three chosen.
void reduceToFour(const std::vector<PlanePoint>& pts, const Vec3& n, std::vector<PlanePoint>& out) {
  std::array<int, 4> chosen{0, -1, -1, -1};
  for (size_t i = 1; i < pts.size(); ++i) {
    if (pts[i].distance < pts[static_cast<size_t>(chosen[0])].distance)
      chosen[0] = static_cast<int>(i);
  }
  const Vec3 p0 = pts[static_cast<size_t>(chosen[0])].point;
  chosen[1] = best(pts, std::span(chosen.data(), 1),
                   [&](const PlanePoint& p) { return (p.point - p0).squaredNorm(); });
  const Vec3 p1 = pts[static_cast<size_t>(chosen[1])].point;
  chosen[2] = best(pts, std::span(chosen.data(), 2), [&](const PlanePoint& p) {
    return std::abs((p1 - p0).cross(p.point - p0).dot(n));
  });
  const Vec3 p2 = pts[static_cast<size_t>(chosen[2])].point;
  chosen[3] = best(pts, std::span(chosen.data(), 3), [&](const PlanePoint& p) {
    return std::min(
        {(p.point - p0).squaredNorm(), (p.point - p1).squaredNorm(), (p.point - p2).squaredNorm()});
  });
  out.clear();
  for (int c : chosen) out.push_back(pts[static_cast<size_t>(c)]);
}

}  // namespace

WorldPlane worldPlane(const Shape& plane, const Transform& plane_world) {
  const Vec3 n_local = plane.plane_normal.normalized();
  WorldPlane out;
  out.normal = plane_world.rotation * n_local;
  out.offset = out.normal.dot(plane_world.apply(n_local * plane.plane_offset));
  return out;
}

const std::vector<PlanePoint>& planePoints(const Shape& shape, const Transform& world,
                                           const WorldPlane& plane, double max_distance,
                                           PlaneScratch& scratch) {
  // Signed distances of all candidates; keep those within reach.
  candidates(shape, world, plane.normal, scratch.candidates);
  std::vector<PlanePoint>& near = scratch.near;
  near.clear();
  for (size_t i = 0; i < scratch.candidates.size(); ++i) {
    const Vec3& p = scratch.candidates[i];
    const double d = plane.normal.dot(p) - plane.offset;
    if (d < max_distance) near.push_back({static_cast<int>(i), p, d});
  }
  if (near.size() <= 4) return near;
  reduceToFour(near, plane.normal, scratch.points);
  return scratch.points;
}

}  // namespace asperity::collision_detail
