// Basic math types shared by every stage. Physics runs in double precision; per-fragment
// texture kernels use float (see friction/).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace asperity {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Vec2f = Eigen::Vector2f;
using Vec3f = Eigen::Vector3f;

inline constexpr double kPi = 3.14159265358979323846;

// The cross-product matrix: skew(r) * x == r.cross(x).
inline Mat3 skew(const Vec3& r) {
  Mat3 m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// A unit vector perpendicular to the unit vector n: n x (x or y axis, whichever is further from
// n), so the same n always gives the same vector.
inline Vec3 anyPerpendicular(const Vec3& n) {
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  return n.cross(helper).normalized();
}

// A rigid transform: x_world = rotation * x_local + position.
struct Transform {
  Vec3 position = Vec3::Zero();
  Quat rotation = Quat::Identity();

  Vec3 apply(const Vec3& local) const { return rotation * local + position; }
  Vec3 applyInverse(const Vec3& world) const { return rotation.conjugate() * (world - position); }
  Transform operator*(const Transform& other) const {
    return {apply(other.position), (rotation * other.rotation).normalized()};
  }
  Transform inverse() const {
    const Quat inv = rotation.conjugate();
    return {-(inv * position), inv};
  }
};

}  // namespace asperity
