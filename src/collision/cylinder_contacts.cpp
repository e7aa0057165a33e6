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

// The two ends of the line along which a shape lies on the side, as points of the shape
// (world); `found` false where it touches at one point.
struct Line {
  bool found = false;
  Vec3 ends[2];
};

// Within about 25 degrees: a face turned toward the axis, an edge or capsule along it.
constexpr double kAligned = 0.9;

// The t interval of the axis line p(t) = p0 + t d (d unit) on which the 1D coordinate
// x0 + t dx stays within [-half, half]; intersected with [lo, hi].
void clip(double x0, double dx, double half, double& lo, double& hi) {
  if (std::abs(dx) < 1e-12) {
    if (std::abs(x0) > half) lo = hi + 1.0;  // outside for every t: empty
    return;
  }
  double a = (-half - x0) / dx, b = (half - x0) / dx;
  if (a > b) std::swap(a, b);
  lo = std::max(lo, a), hi = std::min(hi, b);
}

// A box face turned toward the axis (outward normal within 25 degrees of -n) touches the side
// where the face's plane is nearest the axis: the axis projected onto the face, a line (the
// face's plane is parallel to the axis within 25 degrees). Its ends are the projected axis
// clipped to the face rectangle and to the rod's length. Where that line misses the face, the
// box rests on an edge: one lying along the axis touches along it, from end to end.
Line boxLine(const Shape& box, const Transform& world, const Axis& axis, const Vec3& n,
             const Vec3& deepest) {
  Line line;
  const Mat3 r = world.rotation.toRotationMatrix();
  const Vec3& h = box.half_extents;
  int k = 0;
  (r.transpose() * -n).cwiseAbs().maxCoeff(&k);
  const double sign = (r.col(k).dot(-n) >= 0) ? 1.0 : -1.0;
  if (sign * r.col(k).dot(-n) >= kAligned) {
    const Vec3 face_centre = world.position + sign * h[k] * r.col(k);
    double lo = -axis.half, hi = axis.half;
    const Vec3 p0 = axis.centre - face_centre;
    for (int e = 0; e < 3; ++e) {
      if (e != k) clip(p0.dot(r.col(e)), axis.u.dot(r.col(e)), h[e], lo, hi);
    }
    if (lo < hi) {
      const Mat3 in_plane = Mat3::Identity() - r.col(k) * r.col(k).transpose();
      for (const auto& [t, i] : {std::pair{lo, 0}, std::pair{hi, 1}}) {
        line.ends[i] = face_centre + in_plane * (axis.at(t) - face_centre);
      }
      line.found = true;
      return line;
    }
  }
  // An edge along the axis: the deepest point lies on the box's boundary in both coordinates
  // across that edge.
  const Vec3 local = r.transpose() * (deepest - world.position);
  const double tol = 1e-6 * h.maxCoeff();
  for (int e = 0; e < 3; ++e) {
    if (std::abs(r.col(e).dot(axis.u)) < kAligned) continue;
    const int a = (e + 1) % 3, b = (e + 2) % 3;
    if (std::abs(local[a]) < h[a] - tol || std::abs(local[b]) < h[b] - tol) continue;
    // The edge's extent, cut where its points' feet leave the rod's length.
    double lo = -h[e], hi = h[e];
    const double along = r.col(e).dot(axis.u);
    const double mid = (deepest - r.col(e) * local[e] - axis.centre).dot(axis.u);
    clip(mid, along, axis.half, lo, hi);
    if (lo >= hi) return line;
    const Vec3 base = deepest - local[e] * r.col(e);
    line.ends[0] = base + lo * r.col(e), line.ends[1] = base + hi * r.col(e);
    line.found = true;
    return line;
  }
  return line;
}

// A capsule lying along the side (its axis within 25 degrees of the cylinder's) touches along
// its core: its points nearest the axis at its two ends' axis parameters.
Line capsuleLine(const Shape& capsule, const Transform& world, const Axis& axis) {
  Line line;
  const Vec3 w = world.rotation * Vec3::UnitZ();
  if (std::abs(w.dot(axis.u)) < kAligned) return line;
  const double mid = (world.position - axis.centre).dot(axis.u);
  const double half = capsule.half_height * std::abs(w.dot(axis.u));
  const double lo = std::max(mid - half, -axis.half), hi = std::min(mid + half, axis.half);
  if (lo >= hi) return line;
  line.ends[0] = closestOnShape(capsule, world, axis.at(lo));
  line.ends[1] = closestOnShape(capsule, world, axis.at(hi));
  line.found = true;
  return line;
}

// The contact at the shape's point q: its foot on the axis, the normal from there to q.
bool sidePoint(const Axis& axis, double radius, const Vec3& q, int id, CylinderSidePoint& out) {
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
  // A face, edge or capsule lying along the side: a point at each end of the line it touches
  // along, as a manifold has;
  // one not quite flat on the side gets its lifted end as a speculative point (depth < 0),
  // which the solver lets close but not pass.
  const Vec3 q = closestOnShape(shape, shape_world, axis.at(t_min));
  const Vec3 n = (q - axis.at(t_min)).normalized();
  const Line line = shape.type == ShapeType::Box       ? boxLine(shape, shape_world, axis, n, q)
                    : shape.type == ShapeType::Capsule ? capsuleLine(shape, shape_world, axis)
                                                       : Line{};
  const double speculative = std::max(reach, 0.25 * shapeSize(shape));
  CylinderSidePoint p;
  if (line.found && (line.ends[1] - line.ends[0]).norm() > 0.05 * shapeSize(shape)) {
    // A face tilted along the axis sinks deepest at a corner off the line: that corner
    // stands for the line's deeper end.
    Vec3 ends[2] = {line.ends[0], line.ends[1]};
    auto fromAxis = [&](const Vec3& x) { return (x - axis.at(axis.param(x))).norm(); };
    const int deeper = fromAxis(ends[0]) <= fromAxis(ends[1]) ? 0 : 1;
    if (fromAxis(ends[deeper]) > nearest + tiny) ends[deeper] = q;
    for (int id : {0, 1}) {
      if (sidePoint(axis, cylinder.radius, ends[id], id, p) && p.depth > -speculative) {
        out.push_back(p);
      }
    }
  }
  if (out.empty() && sidePoint(axis, cylinder.radius, q, 2, p)) out.push_back(p);
  return !out.empty() || nearest > cylinder.radius;
}

}  // namespace asperity::collision_detail
