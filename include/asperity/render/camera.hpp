// A perspective camera looking from `eye` at `target` with z up (Asperity's up axis), and the
// orbit / pan / zoom moves the viewer makes with it.
#pragma once

#include <Eigen/Geometry>

#include "asperity/math/types.hpp"

namespace asperity::render {

using Mat4f = Eigen::Matrix4f;
using Box3 = Eigen::AlignedBox3d;

struct Camera {
  Vec3 eye = Vec3(1.2, -1.8, 1.0);
  Vec3 target = Vec3::Zero();
  Vec3 up = Vec3::UnitZ();
  double fov_y = 35.0 * kPi / 180.0;  // vertical field of view (rad)
  double near_plane = 0.01;           // m
  double far_plane = 100.0;           // m

  Mat4f view() const;
  Mat4f projection(double aspect) const;
  // Window pixel (x right, y DOWN from the top-left corner) of a world point, and its
  // normalised depth in [0, 1]; depth outside [0, 1] means behind or beyond the clip planes.
  Eigen::Vector3d project(const Vec3& world, int width, int height) const;
  // World-space ray through a window pixel (y down): origin at the eye, unit direction.
  void ray(double px, double py, int width, int height, Vec3& origin, Vec3& direction) const;

  // Turns about the target: yaw about z, pitch about the camera's right axis (rad); the pitch
  // stops short of straight up and down.
  void orbit(double yaw, double pitch);
  // Moves eye and target together by fractions of the view's height at the target distance.
  void pan(double dx, double dy);
  // Multiplies the eye-target distance by `factor` (> 0).
  void zoom(double factor);
};

// A camera that frames `box` (the bounds of the bodies to look at) from the front-right,
// slightly above, with the whole box in view at this aspect ratio. Near and far planes follow
// the scene's size (`scene_radius`: half the size of everything to show, ground included).
Camera frameBox(const Box3& box, double aspect, double scene_radius = 0.0);

// A camera at `eye` looking at `target` (they differ) with this vertical field of view; near
// and far planes follow the distance between them (a scene's "camera", --camera).
Camera lookAt(const Vec3& eye, const Vec3& target, double fov_y = 35.0 * kPi / 180.0);

// Parses "eye_x,eye_y,eye_z,target_x,target_y,target_z"; throws asperity::Error naming the
// option (`what`) when it is not six finite numbers or eye equals target.
Camera parseCamera(const std::string& text, const char* what = "--camera");

}  // namespace asperity::render
