// Mouse and keyboard: left-drag a body with a spring (or orbit on empty space), right or
// middle drag pans, the wheel zooms; Space plays/pauses, S steps, R resets, F12 screenshots.
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "viewer.hpp"

namespace asperity::viewer {

void Viewer::scrollCallback(GLFWwindow* window, double dx, double dy) {
  (void)dx;
  auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
  if (!ImGui::GetIO().WantCaptureMouse) viewer->onScroll(dy);
}

void Viewer::keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  (void)scancode;
  auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
  if (!ImGui::GetIO().WantCaptureKeyboard) viewer->onKey(key, action, mods);
}

void Viewer::onScroll(double dy) {
  camera_.zoom(std::pow(0.9, dy));
}

void Viewer::onKey(int key, int action, int mods) {
  (void)mods;
  if (action != GLFW_PRESS) return;
  switch (key) {
    case GLFW_KEY_SPACE:
      playing_ = !playing_;
      break;
    case GLFW_KEY_S:
      step_once_ = true;
      break;
    case GLFW_KEY_R:
      reset();
      break;
    case GLFW_KEY_F12: {
      char name[64];
      std::snprintf(name, sizeof name, "asperity-screenshot-%03d.png", screenshot_count_++);
      pending_screenshot_ = name;
      break;
    }
    case GLFW_KEY_ESCAPE:
      glfwSetWindowShouldClose(window_, GLFW_TRUE);
      break;
    default:
      break;
  }
}

void Viewer::handleMouse() {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  const bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                     glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  // A press starts a drag unless the panels want the mouse.
  if (drag_ == Drag::None && (left || right) && !ImGui::GetIO().WantCaptureMouse) {
    if (left) {
      beginDrag(x, y);
    } else {
      drag_ = Drag::Pan;
    }
  } else if (drag_ != Drag::None && !left && !right) {
    endDrag();
  }
  // Moves in window-height units.
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  const double dx = (x - last_x_) / std::max(h, 1), dy = (y - last_y_) / std::max(h, 1);
  if (drag_ == Drag::Orbit) camera_.orbit(-3.0 * dx, 3.0 * dy);
  if (drag_ == Drag::Pan) camera_.pan(dx, dy);
  if (drag_ == Drag::Body) updateDrag(x, y);
  last_x_ = x;
  last_y_ = y;
}

void Viewer::beginDrag(double x, double y) {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  Vec3 origin, direction;
  camera_.ray(x, y, w, h, origin, direction);
  const std::optional<render::PickHit> hit = view_.pick(*world_, origin, direction);
  if (!hit) {
    drag_ = Drag::Orbit;
    return;
  }
  // Attach the mouse spring at the picked point; stiffness and damping scale with the mass.
  const Body& body = world_->body(hit->body);
  const double mass = body.inverse_mass > 0.0 ? 1.0 / body.inverse_mass : 1.0;
  SpringDesc spring;
  spring.name = "mouse";
  spring.body = hit->body;
  spring.local_point = body.pose.applyInverse(hit->point);
  spring.target = hit->point;
  spring.stiffness = spring_stiffness_ * mass;
  spring.damping = 2.0 * 0.5 * std::sqrt(spring.stiffness * mass);
  if (spring_ == kNoSpring) {
    spring_ = world_->addSpring(spring);
  } else {
    world_->springs()[spring_] = spring;
  }
  dragged_ = hit->body;
  drag_plane_point_ = hit->point;
  drag_ = Drag::Body;
}

void Viewer::updateDrag(double x, double y) {
  // The target follows the mouse in the plane through the grab point facing the camera.
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  Vec3 origin, direction;
  camera_.ray(x, y, w, h, origin, direction);
  const Vec3 normal = (camera_.eye - camera_.target).normalized();
  const double denominator = direction.dot(normal);
  if (std::abs(denominator) < 1e-9 || spring_ == kNoSpring) return;
  const double s = (drag_plane_point_ - origin).dot(normal) / denominator;
  if (s <= 0.0) return;
  SpringDesc& spring = world_->springs()[spring_];
  spring.target = origin + s * direction;
  spring.target_velocity = Vec3::Zero();
}

void Viewer::endDrag() {
  // Springs cannot be removed: the idle one has no stiffness.
  if (drag_ == Drag::Body && spring_ != kNoSpring) {
    SpringDesc& spring = world_->springs()[spring_];
    spring.stiffness = 0.0;
    spring.damping = 0.0;
  }
  dragged_ = kNoBody;
  drag_ = Drag::None;
}

}  // namespace asperity::viewer
