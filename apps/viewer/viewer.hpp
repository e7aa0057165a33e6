// The interactive viewer: a GLFW window with the renderer, Dear ImGui panels that change the
// world's settings live, camera moves, a mouse spring to drag bodies, and screenshots.
#pragma once

// GLFW declares no GL itself: epoxy loads every GL function.
#include <epoxy/gl.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>

#include "asperity/render/renderer.hpp"
#include "asperity/render/world_view.hpp"
#include "asperity/scene/scene.hpp"
#include "surface_preview.hpp"

namespace asperity::viewer {

struct ViewerOptions {
  std::string scene;
  std::string sampler;  // replaces the scene's friction sampler when set
  int threads = -1;     // worker threads of a step; < 0: the scene's
  int width = 1280;
  int height = 720;
  int samples = 0;         // MSAA; 0 = automatic: 4 on a GPU, 1 on a software rasteriser
  int shadow_map = 1024;   // shadow map texels per side (0 = no shadows)
  int shadow_taps = 0;     // PCF taps, 1 or 4; 0 = automatic: 4 on a GPU, 1 on a software one
  int frames = 0;          // > 0: quit after this many frames (tests, measurements)
  std::string screenshot;  // with frames: PNG of the last frame
  bool play = true;        // start playing
};

class Viewer {
 public:
  // Opens the window and loads the scene. Throws asperity::Error (no display, no 4.3 context,
  // bad scene).
  explicit Viewer(const ViewerOptions& options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Runs until the window closes (or options.frames frames were drawn).
  void run();

 private:
  // Scene and simulation.
  void loadScene(const std::string& path);
  void reset();
  void advance(double wall_seconds);
  // Input.
  void handleMouse();
  void beginDrag(double x, double y);
  void updateDrag(double x, double y);
  void endDrag();
  void onScroll(double dy);
  void onKey(int key, int action, int mods);
  // Panels (panels.cpp).
  void drawPanels();
  void simulationPanel();
  void settingsPanel();
  void bodiesPanel();
  void profilePanel();
  // Output.
  void screenshot(const std::string& path);

  static void scrollCallback(GLFWwindow* window, double dx, double dy);
  static void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods);

  ViewerOptions options_;
  GLFWwindow* window_ = nullptr;
  std::unique_ptr<render::Renderer> renderer_;
  render::WorldView view_;
  render::RenderScene render_scene_;
  render::Camera camera_;
  render::WorldViewOptions view_options_;
  std::unique_ptr<SurfacePreview> preview_;

  SceneDesc scene_;
  FrictionProviders providers_;  // the samplers scenes and the panel may pick ("gl" included)
  std::unique_ptr<World> world_;
  std::string scene_path_;
  std::string open_path_;  // the "open scene" text field
  std::string message_;    // last error, shown in the simulation panel
  bool playing_ = true;
  bool step_once_ = false;
  double time_scale_ = 1.0;
  double accumulator_ = 0.0;

  // Mouse: orbit / pan / drag state.
  enum class Drag { None, Orbit, Pan, Body } drag_ = Drag::None;
  double last_x_ = 0.0, last_y_ = 0.0;
  SpringId spring_ = kNoSpring;  // the world's mouse spring (reused; stiffness 0 when idle)
  BodyId dragged_ = kNoBody;
  Vec3 drag_plane_point_ = Vec3::Zero();
  double spring_stiffness_ = 60.0;  // per kg of the dragged body (N/m/kg)

  // Frame statistics.
  double fps_ = 0.0;
  double frame_seconds_ = 0.0;
  double render_ms_ = 0.0;
  double step_ms_ = 0.0;
  int screenshot_count_ = 0;
  std::string pending_screenshot_;  // taken after the next frame is drawn (F12)
};

}  // namespace asperity::viewer
