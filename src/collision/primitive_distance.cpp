// Exact primitive signed distances (see primitive_distance.hpp).
#include "collision/primitive_distance.hpp"

#include <algorithm>
#include <cmath>

namespace asperity::collision_detail {

namespace {

Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
  const double n = v.norm();
  return n > 0 ? Vec3(v / n) : fallback;
}

// Box of half extents h: outside, the distance to the clamped point; inside, to the nearest face.
void boxSample(const Vec3& h, const Vec3& p, SignedDistanceField::Sample& s) {
  const Vec3 q = p.cwiseAbs() - h;
  const Vec3 sign(p.x() < 0 ? -1.0 : 1.0, p.y() < 0 ? -1.0 : 1.0, p.z() < 0 ? -1.0 : 1.0);
  if (q.maxCoeff() > 0) {
    const Vec3 out = q.cwiseMax(0.0);
    s.distance = out.norm();
    s.gradient = unitOr(out.cwiseProduct(sign), Vec3::UnitZ());
    return;
  }
  int axis = 0;
  s.distance = q.maxCoeff(&axis);
  s.gradient = Vec3::Zero();
  s.gradient[axis] = sign[axis];
}

// Cylinder along z: a rectangle in (radial, z).
void cylinderSample(double r, double hh, const Vec3& p, SignedDistanceField::Sample& s) {
  const double rho = std::hypot(p.x(), p.y());
  const Vec3 radial = rho > 0 ? Vec3(p.x() / rho, p.y() / rho, 0) : Vec3(Vec3::UnitX());
  const Vec3 axial(0, 0, p.z() < 0 ? -1.0 : 1.0);
  const double dr = rho - r, dz = std::abs(p.z()) - hh;
  if (dr > 0 || dz > 0) {
    const double a = std::max(dr, 0.0), b = std::max(dz, 0.0);
    s.distance = std::hypot(a, b);
    s.gradient = unitOr(a * radial + b * axial, axial);
    return;
  }
  s.distance = std::max(dr, dz);
  s.gradient = dr > dz ? radial : axial;
}

}  // namespace

bool hasPrimitiveDistance(ShapeType type) {
  return type == ShapeType::Box || type == ShapeType::Sphere || type == ShapeType::Capsule ||
         type == ShapeType::Cylinder;
}

SignedDistanceField::Sample primitiveSample(const Shape& shape, const Vec3& p) {
  SignedDistanceField::Sample s;
  s.inside_grid = true;
  switch (shape.type) {
    case ShapeType::Box:
      boxSample(shape.half_extents, p, s);
      break;
    case ShapeType::Sphere:
      s.distance = p.norm() - shape.radius;
      s.gradient = unitOr(p, Vec3::UnitZ());
      break;
    case ShapeType::Capsule: {
      // Distance to the core segment, less the radius.
      const Vec3 v = p - Vec3(0, 0, std::clamp(p.z(), -shape.half_height, shape.half_height));
      s.distance = v.norm() - shape.radius;
      s.gradient = unitOr(v, Vec3::UnitX());
      break;
    }
    case ShapeType::Cylinder:
      cylinderSample(shape.radius, shape.half_height, p, s);
      break;
    default:
      s.inside_grid = false;
      break;
  }
  return s;
}

namespace {
// The bounds' margin: far above the rounding of the exact distances, so that a point called
// beyond would be rejected by primitiveSample too.
constexpr double kGrow = 1.0 + 1e-9;
}  // namespace

PrimitiveReach::PrimitiveReach(const Shape& shape, double reach) {
  // Squared distances against (radius + reach)^2, grown; an invalid reach leaves every point
  // to the exact distance.
  if (!(reach >= 0)) return;
  type_ = shape.type;
  radius2_ = lanes::splat(kGrow * (shape.radius + reach) * (shape.radius + reach));
  z_limit_ = lanes::splat(kGrow * (shape.half_height + reach));
  half_height_ = shape.half_height;
}

}  // namespace asperity::collision_detail
