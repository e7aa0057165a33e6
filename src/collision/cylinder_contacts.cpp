// Boxes, capsules and spheres against a cylinder's side (see cylinder_contacts.hpp).
#include "collision/cylinder_contacts.hpp"

#include <algorithm>
#include <cmath>

#include "collision/bullet_shapes.hpp"
#include "collision/primitive_distance.hpp"

namespace asperity::collision_detail {

namespace {

// The point of the solid shape closest to `p` (world); `p` itself when inside.
Vec3 closestOnShape(const Shape& shape, const Transform& world, const Vec3& p) {
  const SignedDistanceField::Sample s = primitiveSample(shape, world.applyInverse(p));
  return s.distance > 0 ? Vec3(p - s.distance * (world.rotation * s.gradient)) : p;
}

// The cylinder's axis as a segment: centre, unit direction, half length.
struct Axis {
  Vec3 centre;
  Vec3 u;
  double half = 0.0;
  Vec3 at(double t) const { return centre + t * u; }
  double param(const Vec3& p) const { return std::clamp((p - centre).dot(u), -half, half); }
};

// Distance from the axis point at t to the shape: convex in t (the distance to a convex set,
// along a line).
struct AxisDistance {
  const Axis& axis;
  const Shape& shape;
  const Transform& world;
  double operator()(double t) const {
    const Vec3 p = axis.at(t);
    return (closestOnShape(shape, world, p) - p).norm();
  }
};

// A minimiser of the convex f on [lo, hi] by golden section.
double argMin(const AxisDistance& f, double lo, double hi) {
  constexpr double kInvPhi = 0.6180339887498949;
  double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 48; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kInvPhi * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kInvPhi * (hi - lo), f2 = f(x2);
    }
  }
  return 0.5 * (lo + hi);
}

// Where a box face or a capsule lies along the side (its normal within about 25 degrees of
// the contact's, a capsule's axis within 25 degrees of the cylinder's), the axis parameters of
// its two ends; else an empty interval.
struct Stretch {
  double lo = 0.0, hi = 0.0;
};
Stretch alongAxis(const Shape& shape, const Transform& world, const Axis& axis, const Vec3& n) {
  constexpr double kAligned = 0.9;
  Stretch s;
  if (shape.type == ShapeType::Box) {
    // The face turned most toward the axis (outward normal closest to -n).
    const Mat3 r = world.rotation.toRotationMatrix();
    int k = 0;
    (r.transpose() * -n).cwiseAbs().maxCoeff(&k);
    const double sign = (r.col(k).dot(-n) >= 0) ? 1.0 : -1.0;
    if (sign * r.col(k).dot(-n) < kAligned) return s;
    const Vec3& h = shape.half_extents;
    const Vec3 face_centre = world.position + sign * h[k] * r.col(k);
    // The face's half extent along the axis: its two in-plane edges projected on u.
    double half = 0.0;
    for (int e = 0; e < 3; ++e) {
      if (e != k) half += h[e] * std::abs(r.col(e).dot(axis.u));
    }
    const double mid = (face_centre - axis.centre).dot(axis.u);
    s.lo = mid - half, s.hi = mid + half;
  } else if (shape.type == ShapeType::Capsule) {
    const Vec3 w = world.rotation * Vec3::UnitZ();
    if (std::abs(w.dot(axis.u)) < kAligned) return s;
    const double mid = (world.position - axis.centre).dot(axis.u);
    const double half = shape.half_height * std::abs(w.dot(axis.u));
    s.lo = mid - half, s.hi = mid + half;
  }
  s.lo = std::max(s.lo, -axis.half), s.hi = std::min(s.hi, axis.half);
  return s;
}

// The contact at axis parameter t: the shape's closest point and its foot on the axis.
bool sidePoint(const Axis& axis, double radius, const Shape& shape, const Transform& world,
               double t, int id, CylinderSidePoint& out) {
  const Vec3 q = closestOnShape(shape, world, axis.at(t));
  const Vec3 foot = axis.at(axis.param(q));
  const Vec3 d = q - foot;
  const double dist = d.norm();
  // Axial remainder: q lies beyond a cap; no side contact there.
  if (dist <= 1e-12 || std::abs(d.dot(axis.u)) > 1e-9 * (1.0 + dist)) return false;
  out.id = id;
  out.normal = d / dist;
  out.on_shape = q;
  out.on_cylinder = foot + radius * out.normal;
  out.depth = radius - dist;
  return true;
}

}  // namespace

bool isCylinderSideShape(ShapeType type) {
  return type == ShapeType::Box || type == ShapeType::Capsule || type == ShapeType::Sphere;
}

bool cylinderSidePoints(const Shape& cylinder, const Transform& cylinder_world, const Shape& shape,
                        const Transform& shape_world, double reach,
                        std::vector<CylinderSidePoint>& out) {
  out.clear();
  const Axis axis{cylinder_world.position, cylinder_world.rotation * Vec3::UnitZ(),
                  cylinder.half_height};
  // Where along the axis the shape can be nearest: within its bounding radius of its centre's
  // projection (the nearest point's foot lies in the shape's bounding sphere).
  const double centre_t = (shape_world.position - axis.centre).dot(axis.u);
  const double bound = boundingRadius(shape);
  const double lo = std::max(-axis.half, centre_t - bound);
  const double hi = std::min(axis.half, centre_t + bound);
  if (lo >= hi) return false;  // beyond a cap
  const AxisDistance f{axis, shape, shape_world};
  const double t_min = argMin(f, lo, hi);
  const double nearest = f(t_min);
  if (nearest > cylinder.radius + reach) return true;  // apart
  // The axis inside the shape, or the nearest cross-section at a cap: the general path.
  const double tiny = 1e-9 * (cylinder.radius + bound);
  if (nearest <= tiny || t_min <= -axis.half + tiny || t_min >= axis.half - tiny) return false;
  // A face or capsule lying along the side: a point at each of its ends, as a manifold has;
  // one not quite flat on the side gets its lifted end as a speculative point (depth < 0),
  // which the solver lets close but not pass.
  const Vec3 q = closestOnShape(shape, shape_world, axis.at(t_min));
  const Stretch stretch = alongAxis(shape, shape_world, axis, (q - axis.at(t_min)).normalized());
  const double speculative = std::max(reach, 0.25 * shapeSize(shape));
  CylinderSidePoint p;
  if (stretch.hi - stretch.lo > 0.05 * shapeSize(shape)) {
    for (const auto& [t, id] : {std::pair{stretch.lo, 0}, std::pair{stretch.hi, 1}}) {
      if (sidePoint(axis, cylinder.radius, shape, shape_world, t, id, p) &&
          p.depth > -speculative) {
        out.push_back(p);
      }
    }
  }
  if (out.empty() && sidePoint(axis, cylinder.radius, shape, shape_world, t_min, 2, p)) {
    out.push_back(p);
  }
  return !out.empty() || nearest > cylinder.radius;
}

}  // namespace asperity::collision_detail
