// Camera matrices, picking rays, orbit/pan/zoom, and automatic framing.
#include "asperity/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/error.hpp"

namespace asperity::render {

Mat4f Camera::view() const {
  // Right-handed look-at: camera looks down its -z.
  const Vec3 f = (target - eye).normalized();
  Vec3 s = f.cross(up);
  if (s.norm() < 1e-9) s = f.cross(Vec3::UnitY());
  s.normalize();
  const Vec3 u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m.cast<float>();
}

Mat4f Camera::projection(double aspect) const {
  // OpenGL perspective, clip z in [-w, w].
  const double f = 1.0 / std::tan(0.5 * fov_y);
  const double n = near_plane, fa = far_plane;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (fa + n) / (n - fa);
  m(2, 3) = 2.0 * fa * n / (n - fa);
  m(3, 2) = -1.0;
  return m.cast<float>();
}

Eigen::Vector3d Camera::project(const Vec3& world, int width, int height) const {
  const Eigen::Matrix4d pv = (projection(double(width) / height) * view()).cast<double>();
  const Eigen::Vector4d clip = pv * Eigen::Vector4d(world.x(), world.y(), world.z(), 1.0);
  if (clip.w() <= 0.0) return {-1.0, -1.0, -1.0};
  const Vec3 ndc = clip.head<3>() / clip.w();
  return {(ndc.x() * 0.5 + 0.5) * width, (0.5 - ndc.y() * 0.5) * height, ndc.z() * 0.5 + 0.5};
}

void Camera::ray(double px, double py, int width, int height, Vec3& origin, Vec3& direction) const {
  // Pixel -> normalised device coordinates -> camera-space direction -> world.
  const double aspect = double(width) / height;
  const double t = std::tan(0.5 * fov_y);
  const double x = (2.0 * px / width - 1.0) * t * aspect;
  const double y = (1.0 - 2.0 * py / height) * t;
  const Vec3 f = (target - eye).normalized();
  const Vec3 s = f.cross(up).normalized();
  const Vec3 u = s.cross(f);
  origin = eye;
  direction = (f + x * s + y * u).normalized();
}

void Camera::orbit(double yaw, double pitch) {
  // Spherical coordinates of the eye about the target, z up.
  const Vec3 d = eye - target;
  const double r = d.norm();
  double azimuth = std::atan2(d.y(), d.x()) + yaw;
  double elevation = std::asin(std::clamp(d.z() / r, -1.0, 1.0)) + pitch;
  elevation = std::clamp(elevation, -1.5, 1.5);
  eye = target + r * Vec3(std::cos(elevation) * std::cos(azimuth),
                          std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
}

void Camera::pan(double dx, double dy) {
  const Vec3 f = (target - eye).normalized();
  const Vec3 s = f.cross(up).normalized();
  const Vec3 u = s.cross(f);
  const double h = 2.0 * (target - eye).norm() * std::tan(0.5 * fov_y);
  const Vec3 shift = (-dx * s + dy * u) * h;
  eye += shift;
  target += shift;
}

void Camera::zoom(double factor) {
  if (factor > 0.0) eye = target + (eye - target) * factor;
}

Camera frameBox(const Box3& box, double aspect, double scene_radius) {
  Camera c;
  const Box3 b = box.isEmpty() ? Box3(Vec3::Constant(-0.5), Vec3::Constant(0.5)) : box;
  const Vec3 centre = b.center();
  const Vec3 direction = Vec3(0.55, -1.0, 0.55).normalized();  // towards the eye
  // Camera basis, then the smallest distance at which every corner is inside both fields of
  // view (with a 10 % margin): d >= depth + |offset| / tan(half angle).
  const Vec3 f = -direction;
  const Vec3 s = f.cross(c.up).normalized();
  const Vec3 u = s.cross(f);
  const double tan_y = std::tan(0.5 * c.fov_y) / 1.1;
  const double tan_x = tan_y * aspect;
  double distance = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 p = b.corner(static_cast<Box3::CornerType>(k)) - centre;
    const double depth = p.dot(direction);
    distance = std::max(
        {distance, depth + std::abs(p.dot(s)) / tan_x, depth + std::abs(p.dot(u)) / tan_y});
  }
  distance = std::max(distance, 0.1);
  c.target = centre;
  c.eye = centre + direction * distance;
  const double extent = std::max(scene_radius, 0.5 * b.diagonal().norm());
  c.near_plane = std::max(1e-3, distance * 0.02);
  c.far_plane = distance + 2.0 * extent;
  return c;
}

Camera parseCamera(const std::string& text, const char* what) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  // Six comma-separated finite numbers.
  while (std::getline(stream, item, ',')) {
    try {
      size_t used = 0;
      const double v = std::stod(item, &used);
      if (used != item.size() || !std::isfinite(v)) throw std::invalid_argument(item);
      values.push_back(v);
    } catch (const std::exception&) {
      throw Error(std::string(what) + ": '" + item + "' is not a finite number");
    }
  }
  if (values.size() != 6)
    throw Error(std::string(what) +
                ": expected eye_x,eye_y,eye_z,target_x,target_y,target_z (6 numbers), got " +
                std::to_string(values.size()));
  const Vec3 eye(values[0], values[1], values[2]);
  const Vec3 target(values[3], values[4], values[5]);
  if ((eye - target).norm() < 1e-9) throw Error(std::string(what) + ": eye and target coincide");
  return lookAt(eye, target);
}

Camera lookAt(const Vec3& eye, const Vec3& target, double fov_y) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.fov_y = fov_y;
  const double distance = (eye - target).norm();
  c.near_plane = std::max(1e-3, distance * 0.02);
  c.far_plane = distance * 20.0 + 50.0;
  return c;
}

}  // namespace asperity::render
