#include "tribometer_options.hpp"

#include <string>

#include "cli_common.hpp"

namespace asperity::cli {

void addSurfaceOptions(CLI::App* sub, SurfaceOptions& opt, bool fixing) {
  // The surfaces.
  sub->add_option("B", opt.b_path, "Plate's normal map (PNG, or gen:NAME:SEED[:P=V,...])");
  sub->add_option("--a", opt.a_path, "Block's normal map (PNG or gen:...); default flat");
  sub->add_option("--scene", opt.scene, "Scene whose two bodies are tested (with --bodies)");
  sub->add_option("--bodies", opt.bodies, "A,B: the block's and the plate's body names")
      ->delimiter(',')
      ->expected(2);
  sub->add_flag("--directx", opt.directx, "Read green as -bitangent (DirectX convention)");
  sub->add_option("--texture-size", opt.texture_size, "Metres one texture repeat covers")
      ->check(numberInRange(1e-4, 100.0))
      ->capture_default_str();
  // Eq. 7's values: used as given, or fixing a parameter of the fit.
  const std::string use = fixing ? "Fix " : "";
  sub->add_option("--k-a", opt.k_a, use + "the block's gain k_A (default 1, or the scene's)")
      ->check(numberInRange(0.0, 1000.0));
  sub->add_option("--k-b", opt.k_b, use + "the plate's gain k_B (default 1, or the scene's)")
      ->check(numberInRange(0.0, 1000.0));
  sub->add_option("--mu0", opt.mu0, use + "the nominal coefficient mu0 (default 0, or the scene's)")
      ->check(numberInRange(0.0, 1000.0));
}

TribometerSource sourceFor(const SurfaceOptions& opt, const CLI::App& sub) {
  TribometerSource source;
  source.plate = opt.b_path, source.block = opt.a_path, source.scene = opt.scene;
  if (opt.bodies.size() == 2) source.block_body = opt.bodies[0], source.plate_body = opt.bodies[1];
  if (sub.count("--k-a")) source.k_a = opt.k_a;
  if (sub.count("--k-b")) source.k_b = opt.k_b;
  if (sub.count("--mu0")) source.mu0 = opt.mu0;
  source.texture_size = opt.texture_size;
  source.directx = opt.directx;
  if (sub.count("--sampler")) source.sampler = sub.get_option("--sampler")->as<std::string>();
  return source;
}

std::string plateName(const SurfaceOptions& opt) {
  return opt.scene.empty() || opt.bodies.size() != 2 ? opt.b_path : opt.bodies[1];
}

std::string blockName(const SurfaceOptions& opt) {
  return opt.scene.empty() || opt.bodies.size() != 2 ? opt.a_path : opt.bodies[0];
}

void addRigOptions(CLI::App* sub, TribometerSettings& s) {
  // The block.
  sub->add_option("--block-size", s.block_size, "Side of the block's square base (m)")
      ->check(numberInRange(1e-3, 10.0))
      ->capture_default_str();
  sub->add_option("--block-height", s.block_height, "Height of the block (m)")
      ->check(numberInRange(1e-3, 10.0))
      ->capture_default_str();
  sub->add_option("--load", s.load, "Normal load: the block's weight (N)")
      ->check(numberInRange(1e-3, 1e6))
      ->capture_default_str();
  // The friction stage (a scene gives its own).
  sub->add_option("--patch-width", s.friction.patch_width, "Patch width w (m)")
      ->check(settingRange("patch_width", friction_range::patch_width))
      ->capture_default_str();
  sub->add_option("--patch-res", s.friction.patch_resolution, "Patch resolution R (pixels)")
      ->check(settingRange("patch_resolution", friction_range::patch_resolution))
      ->capture_default_str();
  sub->add_option_function<std::string>(
         "--texel-reading",
         [&s](const std::string& name) {
           s.friction.texel_reading =
               parseName<TexelReading>(name, kTexelReadingNames, "--texel-reading");
         },
         "How patch pixels read the normal map: nearest (one texel a facet) or bilinear")
      ->check(CLI::IsMember(namesOf<TexelReading>(kTexelReadingNames)))
      ->default_str("nearest");
  sub->add_option("--sampler", s.sampler, "Friction provider: cpu, cone or constant")
      ->check(CLI::IsMember({"cpu", "cone", "constant"}))
      ->capture_default_str();
  // The runs.
  sub->add_option("--tracks", s.tracks, "Runs per test and direction, side by side")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  s.threads = 0;
  sub->add_option("--threads", s.threads, "Threads (0 = every core); same numbers on any")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
}

}  // namespace asperity::cli
