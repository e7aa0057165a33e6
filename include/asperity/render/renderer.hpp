// The OpenGL 4.3 core renderer: normal-mapped shape meshes (the same maps and UVs friction
// reads), Blinn-Phong shading with one directional light and a PCF shadow map, a ground grid,
// MSAA resolved into a single-sample framebuffer for read-back, and the debug layers drawn on
// top. Needs a current OpenGL 4.3+ context (gl::GlContext headless, or a window's).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "asperity/render/camera.hpp"
#include "asperity/render/render_scene.hpp"

namespace asperity::render {

struct RendererOptions {
  int width = 1280;
  int height = 720;
  int samples = 4;             // MSAA samples (clamped to GL_MAX_SAMPLES; 1 = off)
  int shadow_map_size = 2048;  // texels per side; 0 = no shadows
  int shadow_taps = 4;         // PCF: 4 bilinear compare taps (3x3 texels) or 1 (2x2, cheaper)
  bool normal_maps = true;     // false: flat shading (the macro normal only)
  bool debug_on_top = true;    // debug layers ignore depth (contacts hide under bodies)
  double grid_step = 0.1;      // m between ground grid lines (every 10th darker)
  Vec3 light_direction = Vec3(-0.45, -0.75, 0.85);  // towards the light (normalised)
};

// An 8-bit RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;

  const uint8_t* pixel(int x, int y) const {
    return &rgb[(static_cast<size_t>(y) * width + x) * 3];
  }
};

// Writes an image as PNG; throws asperity::Error naming the file when it cannot.
void savePng(const Image& image, const std::string& path);

class Renderer {
 public:
  // Compiles the shaders and makes the framebuffers. Throws asperity::Error for a size outside
  // 1..16384, or when a shader or framebuffer fails (the message names it).
  explicit Renderer(const RendererOptions& options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RendererOptions& options() const { return options_; }
  // Changes what the next frame uses; size and sample changes rebuild the framebuffers.
  void setOptions(const RendererOptions& options);
  void resize(int width, int height);

  // Draws one frame into the internal framebuffers (MSAA, then resolved).
  void render(const RenderScene& scene, const Camera& camera);
  // The resolved frame, rows top to bottom.
  Image readPixels() const;
  // Copies the resolved frame into framebuffer `target` (0 = the window) of that size.
  void blitTo(unsigned target, int width, int height) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  RendererOptions options_;
};

}  // namespace asperity::render
