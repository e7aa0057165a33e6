// Draws a DebugDrawList: filled polygons (translucent), lines, then round points.
#pragma once

#include "asperity/render/camera.hpp"
#include "asperity/world/debug_draw.hpp"
#include "gl/objects.hpp"
#include "gl/shader.hpp"

namespace asperity::render {

class DebugPass {
 public:
  DebugPass();
  // Draws into the bound framebuffer; depth is tested unless `on_top`.
  void draw(const DebugDrawList& list, const Mat4f& view_proj, bool on_top);

 private:
  gl::Program program_;
  gl::VertexArray vao_;
  gl::Buffer buffer_;
};

}  // namespace asperity::render
