// `asperity render`: steps a scene headless and renders it through EGL, to an MP4 (ffmpeg), a
// folder of PNG frames, or one PNG at a given time (--frame-at).
#include "cli_common.hpp"

#if ASPERITY_HAVE_RENDER
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "asperity/error.hpp"
#include "asperity/gl/context.hpp"
#include "asperity/render/renderer.hpp"
#include "asperity/render/video_writer.hpp"
#include "asperity/render/world_view.hpp"
#include "asperity/sampler/gl_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
namespace asperity::cli {
namespace {

namespace fs = std::filesystem;

struct RenderCommandOptions {
  std::string scene;
  double seconds = 5.0;
  double fps = 30.0;
  std::string size = "1280x720";
  std::string camera;
  std::string layers = "none";
  std::string sampler;
  std::string out;
  double frame_at = -1.0;
  int samples = 4;
};

enum class OutputKind { Video, Frames, Png };

// "WxH" with both in 1..8192.
void parseSize(const std::string& text, int& width, int& height) {
  const size_t x = text.find('x');
  try {
    size_t used_w = 0, used_h = 0;
    if (x == std::string::npos) throw std::invalid_argument(text);
    width = std::stoi(text.substr(0, x), &used_w);
    height = std::stoi(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw Error("render: --size '" + text + "' is not WIDTHxHEIGHT (e.g. 1280x720)");
  }
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw Error("render: --size " + text + ": width and height must be in 16..8192");
}

// What --out names, checked for writability before any rendering.
OutputKind prepareOutput(const RenderCommandOptions& o) {
  const std::string& out = o.out;
  const fs::path path(out);
  const bool dir = out.back() == '/' || (fs::exists(path) && fs::is_directory(path));
  if (o.frame_at >= 0.0) {
    if (dir || path.extension() != ".png")
      throw Error("render: --frame-at writes one PNG: --out must end in .png, got '" + out + "'");
  } else if (!dir && path.extension() != ".mp4") {
    throw Error("render: --out must be FILE.mp4 or a folder DIR/ for PNG frames, got '" + out +
                "'");
  }
  // Create the folder, then prove a file can be written where the output goes.
  std::error_code ec;
  if (dir) fs::create_directories(path, ec);
  const fs::path probe = dir ? path / ".asperity_write_test" : path;
  const bool existed = fs::exists(probe);
  std::ofstream test(probe, std::ios::app);
  if (!test) throw Error("render: cannot write '" + out + "' (missing folder or no permission)");
  test.close();
  if (dir || !existed) fs::remove(probe, ec);
  if (dir) return OutputKind::Frames;
  return o.frame_at >= 0.0 ? OutputKind::Png : OutputKind::Video;
}

// "[#####.....]  42%  frame 63/150" on one line of a terminal's stderr.
void showProgress(int done, int total) {
  const int width = 40;
  const int filled = total > 0 ? done * width / total : width;
  std::fprintf(stderr, "\r[%s%s] %3d%%  frame %d/%d",
               std::string(static_cast<size_t>(filled), '#').c_str(),
               std::string(static_cast<size_t>(width - filled), '.').c_str(),
               total > 0 ? done * 100 / total : 100, done, total);
  if (done == total) std::fputc('\n', stderr);
  std::fflush(stderr);
}

// Steps until the world's time reaches t (to the nearest step).
void advanceTo(World& world, double t) {
  const double dt = world.settings().dt;
  while (world.time() + 0.5 * dt < t) world.step();
}

// The options checked and parsed, before anything is loaded or rendered.
struct RenderPlan {
  int width = 0, height = 0;
  OutputKind kind = OutputKind::Video;
  render::WorldViewOptions view;
  render::Camera user_camera;  // --camera when given
};

RenderPlan planRender(const RenderCommandOptions& o) {
  RenderPlan plan;
  parseSize(o.size, plan.width, plan.height);
  if (!std::isfinite(o.fps) || o.fps <= 0.0 || o.fps > 1000.0)
    throw Error("render: --fps must be in (0, 1000]");
  if (!std::isfinite(o.seconds) || o.seconds < 0.0) throw Error("render: --seconds must be >= 0");
  plan.view.debug.layers = parseDebugLayers(o.layers);
  // The camera is checked now and placed once the world exists.
  if (!o.camera.empty()) plan.user_camera = render::parseCamera(o.camera, "render: --camera");
  if (o.out.empty()) throw Error("render: --out FILE.mp4, DIR/ or FILE.png is required");
  plan.kind = prepareOutput(o);
  if (plan.kind == OutputKind::Video && render::findExecutable("ffmpeg").empty())
    throw Error("render: " + o.out +
                ": ffmpeg is not on PATH (install Debian's ffmpeg package, or write PNG frames: "
                "--out DIR/)");
  return plan;
}

// The world, with the chosen friction sampler ("gl" included).
std::unique_ptr<World> makeWorld(const RenderCommandOptions& o, SceneDesc& scene) {
  const FrictionProviders providers = frictionProviders();
  scene = loadScene(o.scene);
  if (!o.sampler.empty()) {
    checkSampler(providers, o.sampler);  // names the known ones
    scene.friction_provider = o.sampler;
  }
  std::unique_ptr<World> world = instantiate(scene, {providers});
  printWarnings(*world);
  return world;
}

// A headless context and renderer that step the world to a time and render it from one
// camera: --camera, else the scene's camera, else one framing the bodies.
class FrameRenderer {
 public:
  FrameRenderer(World& world, const SceneDesc& scene, const RenderPlan& plan,
                const RenderCommandOptions& o)
      : world_(world), renderer_(rendererOptions(plan, o)), view_options_(plan.view) {
    camera_ = !o.camera.empty() ? plan.user_camera
              : scene.camera
                  ? render::lookAt(scene.camera->eye, scene.camera->target, scene.camera->fov_y)
                  : view_.defaultCamera(world, double(plan.width) / plan.height);
  }

  render::Image at(double t) {
    advanceTo(world_, t);
    context_.makeCurrent();  // the "gl" sampler may have made its own context current
    view_.update(world_, view_options_, frame_scene_);
    renderer_.render(frame_scene_, camera_);
    return renderer_.readPixels();
  }

 private:
  static render::RendererOptions rendererOptions(const RenderPlan& plan,
                                                 const RenderCommandOptions& o) {
    render::RendererOptions ro;
    ro.width = plan.width;
    ro.height = plan.height;
    ro.samples = o.samples;
    return ro;
  }

  World& world_;
  gl::GlContext context_;  // made before the renderer, which needs it current
  render::Renderer renderer_;
  render::WorldView view_;
  render::WorldViewOptions view_options_;
  render::Camera camera_;
  render::RenderScene frame_scene_;
};

// A frame every 1/fps seconds, t = 0 included, into the video or the folder of PNGs.
void renderFrames(const RenderCommandOptions& o, const RenderPlan& plan, FrameRenderer& frames) {
  const int count = static_cast<int>(std::floor(o.seconds * o.fps + 1e-9)) + 1;
  const bool tty = isatty(STDERR_FILENO) != 0;
  std::unique_ptr<render::VideoWriter> video;
  if (plan.kind == OutputKind::Video)
    video = std::make_unique<render::VideoWriter>(o.out, plan.width, plan.height, o.fps);
  for (int i = 0; i < count; ++i) {
    const render::Image image = frames.at(i / o.fps);
    if (video) {
      video->write(image);
    } else {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%05d.png", i);
      render::savePng(image, (fs::path(o.out) / name).string());
    }
    if (tty) showProgress(i + 1, count);
  }
  if (video) video->finish();
}

void runRender(const RenderCommandOptions& o) {
  // Validate everything before loading or rendering anything.
  const RenderPlan plan = planRender(o);
  SceneDesc scene;
  std::unique_ptr<World> world = makeWorld(o, scene);
  FrameRenderer frames(*world, scene, plan, o);
  // One PNG at --frame-at, else the whole run.
  if (plan.kind == OutputKind::Png) {
    render::savePng(frames.at(o.frame_at), o.out);
    return;
  }
  renderFrames(o, plan, frames);
}

}  // namespace

void registerRenderCommand(CLI::App& app) {
  auto opt = std::make_shared<RenderCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "render",
      "Simulate a scene and render it headless (EGL): --out FILE.mp4 (ffmpeg) or DIR/ (PNG "
      "frames), or one frame with --frame-at T --out FILE.png");
  sub->add_option("scene", opt->scene, "Scene file (JSON)")->required();
  sub->add_option("--seconds", opt->seconds, "Simulated time to render (s)")->capture_default_str();
  sub->add_option("--fps", opt->fps, "Frames per second of simulated time")->capture_default_str();
  sub->add_option("--size", opt->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  sub->add_option("--camera", opt->camera,
                  "eye_x,eye_y,eye_z,target_x,target_y,target_z (m); default: the scene's "
                  "camera, else one framing the bodies");
  sub->add_option("--layers", opt->layers,
                  "Debug layers: contacts,frames,cones,patches (or all, none)")
      ->capture_default_str();
  sub->add_option("--sampler", opt->sampler,
                  "Friction provider replacing the scene's friction_provider");
  sub->add_option("--samples", opt->samples, "MSAA samples per pixel")
      ->check(CLI::Range(1, 16))
      ->capture_default_str();
  sub->add_option("--frame-at", opt->frame_at,
                  "Render only the frame at this time (s) into --out FILE.png")
      ->check(finiteNumber())
      ->check(CLI::Range(0.0, 1e6));
  sub->add_option("--out", opt->out, "Output: FILE.mp4, DIR/ or (with --frame-at) FILE.png");
  sub->callback([opt]() { runRender(*opt); });
}

}  // namespace asperity::cli
#else
#include "asperity/error.hpp"

namespace asperity::cli {

// Built without OpenGL (ASPERITY_WITH_GL=OFF): the subcommand exists and says so.
void registerRenderCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("render", "Render a scene (needs a build with OpenGL)");
  sub->allow_extras();
  sub->callback([]() {
    throw Error("render: this asperity was built without OpenGL (ASPERITY_WITH_GL=OFF)");
  });
}

}  // namespace asperity::cli
#endif
