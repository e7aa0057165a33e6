// Double-precision contact geometry (see contact_geometry.hpp).
#include "collision/contact_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace asperity::collision_detail {

namespace {

// Closest point on the surface of a box (local frame), from inside or outside.
Vec3 boxSurfacePoint(const Vec3& p, const Vec3& h) {
  const Vec3 clamped = p.cwiseMax(-h).cwiseMin(h);
  if (clamped != p) return clamped;
  // Inside: move to the nearest face.
  int axis = 0;
  double best = h[0] - std::abs(p[0]);
  for (int a = 1; a < 3; ++a) {
    if (h[a] - std::abs(p[a]) < best) best = h[a] - std::abs(p[a]), axis = a;
  }
  Vec3 out = p;
  out[axis] = p[axis] < 0 ? -h[axis] : h[axis];
  return out;
}

// Closest point on the surface of a z-axis cylinder (local frame).
Vec3 cylinderSurfacePoint(const Vec3& p, double r, double hh) {
  const Vec2 xy(p.x(), p.y());
  const double radial = xy.norm();
  const Vec2 dir = radial > 0 ? Vec2(xy / radial) : Vec2(1, 0);
  const bool inside = radial <= r && std::abs(p.z()) <= hh;
  if (!inside) {
    const Vec2 q = radial > r ? Vec2(dir * r) : xy;
    return {q.x(), q.y(), std::clamp(p.z(), -hh, hh)};
  }
  // Inside: the side or the nearer cap, whichever is closer.
  if (r - radial < hh - std::abs(p.z())) return {dir.x() * r, dir.y() * r, p.z()};
  return {p.x(), p.y(), p.z() < 0 ? -hh : hh};
}

}  // namespace

Vec3 snapToSurface(const Shape& shape, const Transform& shape_world, const Vec3& witness,
                   const Vec3& outward) {
  switch (shape.type) {
    case ShapeType::Sphere:
      return shape_world.position + shape.radius * outward;
    case ShapeType::Capsule: {
      // The core segment's closest point pushed out by the radius along the normal.
      const Vec3 local = shape_world.applyInverse(witness);
      const Vec3 core(0, 0, std::clamp(local.z(), -shape.half_height, shape.half_height));
      return shape_world.apply(core) + shape.radius * outward;
    }
    case ShapeType::Box:
      return shape_world.apply(
          boxSurfacePoint(shape_world.applyInverse(witness), shape.half_extents));
    case ShapeType::Cylinder:
      return shape_world.apply(
          cylinderSurfacePoint(shape_world.applyInverse(witness), shape.radius, shape.half_height));
    case ShapeType::Plane: {
      const Vec3 n = shape_world.rotation * shape.plane_normal.normalized();
      const Vec3 p0 = shape_world.apply(shape.plane_normal.normalized() * shape.plane_offset);
      return witness - (witness - p0).dot(n) * n;
    }
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      return witness;
  }
  return witness;
}

int boxFace(const Transform& shape_world, const Vec3& outward) {
  const Vec3 local = shape_world.rotation.conjugate() * outward;
  int axis = 0;
  local.cwiseAbs().maxCoeff(&axis);
  return 2 * axis + (local[axis] < 0 ? 1 : 0);
}

void finishContact(Contact& c, const Shape& shape_a, const Transform& world_a, const Shape& shape_b,
                   const Transform& world_b) {
  // A plane (always B, static) gives the exact normal.
  if (shape_b.type == ShapeType::Plane) {
    c.normal = (world_b.rotation * shape_b.plane_normal).normalized();
  }
  // A's outward normal is -n, B's is +n (n points from B toward A).
  c.witness_a = snapToSurface(shape_a, world_a, c.witness_a, -c.normal);
  c.witness_b = snapToSurface(shape_b, world_b, c.witness_b, c.normal);
  // SPEC 1: phi > 0 when A's witness lies behind B's along n.
  c.phi = (c.witness_b - c.witness_a).dot(c.normal);
  c.point = 0.5 * (c.witness_a + c.witness_b);
  if (shape_a.type == ShapeType::Box) c.feature_a = boxFace(world_a, -c.normal);
  if (shape_b.type == ShapeType::Box) c.feature_b = boxFace(world_b, c.normal);
}

bool boxesApart(const Vec3& half_a, const Mat3& axes_a, const Vec3& centre_a, const Vec3& half_b,
                const Mat3& axes_b, const Vec3& centre_b, double gap) {
  // Centre distance along a face normal against the two boxes' extents along it, one axis at
  // a time: neighbours in a pile part along the first or second.
  const Vec3 d = centre_b - centre_a;
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = axes_a.col(i), b = axes_b.col(i);
    const Vec3 a_on_b = (axes_b.transpose() * a).cwiseAbs();  // |a_i . b_j|
    if (std::abs(a.dot(d)) - half_a[i] - a_on_b.dot(half_b) > gap) return true;
    const Vec3 b_on_a = (axes_a.transpose() * b).cwiseAbs();  // |b_i . a_j|
    if (std::abs(b.dot(d)) - half_b[i] - b_on_a.dot(half_a) > gap) return true;
  }
  return false;
}

}  // namespace asperity::collision_detail
