// Window, main loop, simulation clock, camera and mouse-spring input, screenshots.
#include "viewer.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "asperity/error.hpp"
#include "asperity/gl/context.hpp"
#include "asperity/sampler/gl_patch_sampler.hpp"
#include "asperity/scene/gl_sampler_provider.hpp"

namespace asperity::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options) : options_(options), playing_(options.play) {
  // A 4.3 core window (the renderer's minimum), vsync off so frame rates are measurable.
  if (glfwInit() != GLFW_TRUE)
    throw Error("viewer: cannot initialise GLFW (no display? set DISPLAY or run under xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(options.width, options.height, "asperity-viewer", nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    throw Error("viewer: cannot open a window with an OpenGL 4.3 core context");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(options.frames > 0 ? 0 : 1);
  glfwSetWindowUserPointer(window_, this);
  gl::installDebugHook(nullptr);
  // Dear ImGui on the same context; our callbacks chain to its own.
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 430 core");
  glfwSetScrollCallback(window_, scrollCallback);
  glfwSetKeyCallback(window_, keyCallback);

  render::RendererOptions ro;
  ro.width = options.width;
  ro.height = options.height;
  // Software rasterisers (llvmpipe) pay for every sample on the CPU: no MSAA unless asked.
  const char* gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software =
      gl_renderer != nullptr && (std::strstr(gl_renderer, "llvmpipe") != nullptr ||
                                 std::strstr(gl_renderer, "softpipe") != nullptr);
  ro.samples = options.samples > 0 ? options.samples : (software ? 1 : 4);
  ro.shadow_map_size = options.shadow_map;
  // One bilinear compare tap per pixel on software rasterisers (soft over a texel of the map).
  ro.shadow_taps = options.shadow_taps > 0 ? options.shadow_taps : (software ? 1 : 4);
  renderer_ = std::make_unique<render::Renderer>(ro);
  // The "gl" patch sampler draws with the window's context (it restores the state it changes).
  providers_ = FrictionProviders::builtIn();
  GlSamplerOptions gl_options;
  gl_options.use_current_context = true;
  addGlPatchSampler(providers_, gl_options);
  preview_ = std::make_unique<SurfacePreview>();
  view_options_.debug.layers = kLayerContacts;
  loadScene(options.scene);
  if (world_ == nullptr) throw Error(message_);
}

Viewer::~Viewer() {
  // GL objects go before the context does.
  preview_.reset();
  renderer_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void Viewer::loadScene(const std::string& path) {
  // Keep the current scene when the new one fails; say why.
  try {
    SceneDesc scene = asperity::loadScene(path);
    if (!options_.sampler.empty()) scene.friction_provider = options_.sampler;
    if (options_.threads >= 0) scene.settings.threads = options_.threads;
    std::unique_ptr<World> world = instantiate(scene, {providers_});
    scene_ = std::move(scene);
    world_ = std::move(world);
    scene_path_ = open_path_ = path;
    // The scene's warnings (deprecated keys, maps that are not all normals) shown in the panel.
    message_.clear();
    for (const std::string& warning : world_->diagnostics().warnings())
      message_ += (message_.empty() ? "warning: " : "\nwarning: ") + warning;
  } catch (const Error& e) {
    message_ = e.what();
    return;
  }
  view_ = render::WorldView();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  // The scene's own view when it has one, else one framing the bodies.
  const std::optional<SceneCamera>& scene_camera = scene_.camera;
  camera_ = scene_camera
                ? render::lookAt(scene_camera->eye, scene_camera->target, scene_camera->fov_y)
                : view_.defaultCamera(*world_, h > 0 ? double(w) / h : 16.0 / 9.0);
  spring_ = kNoSpring;
  dragged_ = kNoBody;
  accumulator_ = 0.0;
  glfwSetWindowTitle(window_, ("asperity-viewer: " + path).c_str());
}

void Viewer::reset() {
  // Re-instantiate from the loaded description, keeping the camera and live settings.
  const WorldSettings settings = world_->settings();
  const std::string sampler = world_->frictionProvider().name();
  world_ = instantiate(scene_, {providers_});
  world_->settings() = settings;
  if (providers_.has(sampler)) world_->setFrictionProvider(providers_.make(sampler));
  view_ = render::WorldView();
  spring_ = kNoSpring;
  dragged_ = kNoBody;
  drag_ = Drag::None;
  accumulator_ = 0.0;
}

void Viewer::advance(double wall_seconds) {
  // Fixed steps of the scene's dt at time_scale x real time; at most 8 steps per frame.
  const Clock::time_point start = Clock::now();
  const double dt = world_->settings().dt;
  if (playing_) accumulator_ += std::min(wall_seconds, 0.1) * time_scale_;
  int steps = 0;
  if (step_once_) {
    world_->step();
    step_once_ = false;
    ++steps;
  }
  while (playing_ && accumulator_ >= dt && steps < 8) {
    world_->step();
    accumulator_ -= dt;
    ++steps;
  }
  if (steps == 8) accumulator_ = 0.0;  // too slow for real time: drop the backlog
  if (steps > 0) step_ms_ = msSince(start) / steps;
}

void Viewer::run() {
  Clock::time_point last = Clock::now();
  const Clock::time_point start = last;
  int frames = 0;
  while (!glfwWindowShouldClose(window_)) {
    glfwPollEvents();
    const Clock::time_point now = Clock::now();
    const double wall = std::chrono::duration<double>(now - last).count();
    last = now;
    // Frame rate from a running mean of frame times.
    frame_seconds_ = frame_seconds_ == 0.0 ? wall : 0.9 * frame_seconds_ + 0.1 * wall;
    fps_ = 1.0 / std::max(frame_seconds_, 1e-6);
    if (frames > 0) advance(wall);
    // UI first (it may change settings), then the scene, then the UI on top.
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    handleMouse();
    drawPanels();
    ImGui::Render();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    const Clock::time_point render_start = Clock::now();
    if (w > 0 && h > 0) {
      if (w != renderer_->options().width || h != renderer_->options().height)
        renderer_->resize(w, h);
      view_options_.highlight = dragged_;
      view_.update(*world_, view_options_, render_scene_);
      renderer_->render(render_scene_, camera_);
      renderer_->blitTo(0, w, h);
    }
    glViewport(0, 0, w, h);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    render_ms_ = msSince(render_start);
    ++frames;
    if (!pending_screenshot_.empty()) {
      try {
        screenshot(pending_screenshot_);
      } catch (const Error& e) {
        message_ = e.what();
      }
      pending_screenshot_.clear();
    }
    // Fixed frame count (tests, measurements): screenshot, report, quit.
    if (options_.frames > 0 && frames >= options_.frames) {
      if (!options_.screenshot.empty()) screenshot(options_.screenshot);
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      std::fprintf(stderr, "asperity-viewer: %d frames in %.2f s (%.1f fps)\n", frames, seconds,
                   frames / seconds);
      break;
    }
    glfwSwapBuffers(window_);
  }
}

void Viewer::screenshot(const std::string& path) {
  // The window's back buffer as drawn (scene and panels), before the swap.
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  render::Image image;
  image.width = w;
  image.height = h;
  std::vector<uint8_t> rows(static_cast<size_t>(w) * h * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  image.rgb.resize(rows.size());
  const size_t stride = static_cast<size_t>(w) * 3;
  for (int y = 0; y < h; ++y)
    std::copy_n(&rows[static_cast<size_t>(h - 1 - y) * stride], stride,
                &image.rgb[static_cast<size_t>(y) * stride]);
  render::savePng(image, path);
  message_ = "saved " + path;
}

}  // namespace asperity::viewer
