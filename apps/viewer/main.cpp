// asperity-viewer SCENE.json: interactive viewer (see docs/rendering.md for the controls).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "asperity/error.hpp"
#include "viewer.hpp"

int main(int argc, char** argv) {
  asperity::viewer::ViewerOptions options;
  CLI::App app{"Asperity viewer: simulate a scene interactively.", "asperity-viewer"};
  app.add_option("scene", options.scene, "Scene file (JSON)")->required();
  app.add_option("--sampler", options.sampler,
                 "Friction provider replacing the scene's friction_provider");
  app.add_option("--threads", options.threads, "Worker threads of a step (0 = every core)")
      ->check(CLI::Range(0, asperity::kMaxThreads));
  app.add_option("--width", options.width, "Window width")->check(CLI::Range(64, 8192));
  app.add_option("--height", options.height, "Window height")->check(CLI::Range(64, 8192));
  app.add_option("--samples", options.samples, "MSAA samples (default: 4 on a GPU, 1 on llvmpipe)")
      ->check(CLI::Range(1, 16));
  app.add_option("--shadow-map", options.shadow_map, "Shadow map size (0 = no shadows)")
      ->check(CLI::Range(0, 8192));
  app.add_option("--shadow-taps", options.shadow_taps,
                 "Shadow filter taps, 1 or 4 (default: 4 on a GPU, 1 on llvmpipe)")
      ->check(CLI::IsMember({1, 4}));
  app.add_option("--frames", options.frames, "Quit after N frames (prints the frame rate)")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--screenshot", options.screenshot, "With --frames: PNG of the last frame");
  bool paused = false;
  app.add_flag("--paused", paused, "Start paused");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  options.play = !paused;
  // One line on stderr for any error, non-zero exit.
  try {
    asperity::viewer::Viewer viewer(options);
    viewer.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "asperity-viewer: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
