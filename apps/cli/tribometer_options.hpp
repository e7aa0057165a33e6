// Options shared by `asperity tribometer` and `asperity calibrate`: the two surfaces (textures as
// `asperity cone` takes them, or two bodies of a scene), the values of Eq. 7 given on the
// command line, and the rig the tests run (src/tribometer).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "asperity/tribometer/tribometer.hpp"

namespace asperity::cli {

struct SurfaceOptions {
  std::string b_path;  // the plate (B); empty with --scene
  std::string a_path;  // the block (A); empty: flat
  std::string scene;
  std::vector<std::string> bodies;  // block, plate
  double k_a = 1.0, k_b = 1.0, mu0 = 0.0;
  double texture_size = 0.256;
  bool directx = false;
};

// B, --a, --scene, --bodies, --directx, --texture-size, and --k-a, --k-b, --mu0 described as
// values used (`fixing` false) or as values that fix a fitted parameter (true).
void addSurfaceOptions(CLI::App* sub, SurfaceOptions& opt, bool fixing);

// What the options name; --k-a, --k-b, --mu0 only when given (else the scene's or defaults).
TribometerSource sourceFor(const SurfaceOptions& opt, const CLI::App& sub);

// The names a figure shows: the textures as given, or the scene's bodies.
std::string plateName(const SurfaceOptions& opt);
std::string blockName(const SurfaceOptions& opt);

// --block-size, --block-height, --load, --patch-width, --patch-res, --sampler, --tracks and
// --threads (default 0: every core) into `settings`.
void addRigOptions(CLI::App* sub, TribometerSettings& settings);

}  // namespace asperity::cli
