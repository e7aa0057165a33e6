// `asperity cone`: the friction limit surface of a flat patch covering every texel of both
// textures (the paper's Fig. 8): mu_{d_k} for N directions (Eq. 7), the box (Eq. 9), as a
// table, JSON, and an SVG / PNG figure.
#include <cstdio>
#include <future>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "asperity/error.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/texture/png_io.hpp"
#include "cli_common.hpp"
#include "cone_plot.hpp"

namespace asperity::cli {
namespace {

struct ConeOptions {
  std::string b_path;
  std::string a_path;  // empty: flat A
  int directions = 16;
  double k_a = 1.0;
  double k_b = 1.0;
  double mu0 = 0.0;
  double mu_max = kDefaultMuMax;
  bool directx = false;
  bool json = false;
  std::string svg;
  std::string png;
};

// Angle of direction k in degrees, from t toward b (SPEC 1).
double angleDeg(int k, int n) {
  return 360.0 * k / n;
}

// {"directions": [{"angle_deg", "mu"}, ...], "box": {"+t", "+b", "-t", "-b"}} in that order.
nlohmann::ordered_json coneJson(const DirectionalMu& mu, const BoxLimit& box) {
  nlohmann::ordered_json dirs = nlohmann::ordered_json::array();
  for (int k = 0; k < mu.count; ++k)
    dirs.push_back({{"angle_deg", angleDeg(k, mu.count)}, {"mu", static_cast<double>(mu.mu[k])}});
  nlohmann::ordered_json j;
  j["directions"] = dirs;
  j["box"] = {
      {"+t", box.mu_pos_t}, {"+b", box.mu_pos_b}, {"-t", box.mu_neg_t}, {"-b", box.mu_neg_b}};
  return j;
}

// The readable form: one row per direction, then the box.
void printTable(std::ostream& os, const ConeOptions& opt, const DirectionalMu& mu,
                const BoxLimit& box) {
  char line[128];
  os << "B: " << opt.b_path << "\nA: " << (opt.a_path.empty() ? "flat" : opt.a_path) << '\n';
  std::snprintf(line, sizeof(line), "mu0 = %g, k_A = %g, k_B = %g, mu_max = %g, N = %d\n", opt.mu0,
                opt.k_a, opt.k_b, opt.mu_max, mu.count);
  os << line << "  angle_deg        mu\n";
  for (int k = 0; k < mu.count; ++k) {
    std::snprintf(line, sizeof(line), "  %9.2f  %8.4f\n", angleDeg(k, mu.count),
                  static_cast<double>(mu.mu[k]));
    os << line;
  }
  std::snprintf(line, sizeof(line), "box: +t %.4f  +b %.4f  -t %.4f  -b %.4f\n", box.mu_pos_t,
                box.mu_pos_b, box.mu_neg_t, box.mu_neg_b);
  os << line;
}

// A normal map read for the cone; texels that are not normals are warned about (SPEC 10).
NormalMap loadConeMap(const std::string& path, GreenConvention green) {
  NormalMapStats stats;
  NormalMap map = loadNormalMapPng(path, green, &stats);
  Diagnostics diagnostics;
  diagnostics.setSink(printWarning);
  warnInvalidTexels(path, stats, diagnostics);
  return map;
}

// The subcommand's action: load, compute (flatPatchCone), print, plot.
void runCone(const ConeOptions& opt) {
  const GreenConvention green = opt.directx ? GreenConvention::DirectX : GreenConvention::OpenGL;
  // Decode A on a second thread while B decodes here: PNG decoding dominates the run time.
  std::future<NormalMap> a_loading;
  if (!opt.a_path.empty())
    a_loading =
        std::async(std::launch::async, [&opt, green]() { return loadConeMap(opt.a_path, green); });
  const NormalMap b = loadConeMap(opt.b_path, green);
  std::optional<NormalMap> a;
  if (a_loading.valid()) a = a_loading.get();

  PatchConeOptions cone;
  cone.directions = opt.directions;
  cone.gains = {opt.mu0, opt.k_a, opt.k_b};
  cone.mu_max = static_cast<float>(opt.mu_max);
  const DirectionalMu mu = flatPatchCone(a ? &*a : nullptr, b, cone);
  const BoxLimit box = BoxLimit::fromDirectional(mu);

  if (opt.json)
    std::cout << coneJson(mu, box).dump(2) << '\n';
  else
    printTable(std::cout, opt, mu, box);

  if (opt.svg.empty() && opt.png.empty()) return;
  ConePlot plot;
  plot.b = &b;
  plot.a = a ? &*a : nullptr;
  plot.b_name = opt.b_path;
  plot.a_name = opt.a_path;
  char subtitle[160];
  std::snprintf(subtitle, sizeof(subtitle),
                "flat patch over all texels;  mu0 = %g,  k_A = %g,  k_B = %g,  mu_max = %g",
                opt.mu0, opt.k_a, opt.k_b, opt.mu_max);
  plot.subtitle = subtitle;
  plot.mu = mu;
  plot.box = box;
  if (!opt.svg.empty()) writeConePlotSvg(plot, opt.svg);
  if (!opt.png.empty()) writeConePlotPng(plot, opt.png);
}

}  // namespace

void registerConeCommand(CLI::App& app) {
  auto opt = std::make_shared<ConeOptions>();
  CLI::App* sub = app.add_subcommand(
      "cone", "Friction limit surface of a flat patch over two normal maps (paper Fig. 8)");

  // Inputs.
  sub->add_option("B", opt->b_path, "Normal map of surface B (PNG, faces +n)")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--a", opt->a_path, "Normal map of surface A (PNG, faces -n); default flat")
      ->check(CLI::ExistingFile);
  sub->add_flag("--directx", opt->directx, "Read green as -bitangent (DirectX convention)");

  // Model parameters (Eq. 7), each checked for NaN and range.
  sub->add_option("--directions", opt->directions, "Number of sample directions N")
      ->check(CLI::Range(kMinDirections, kMaxDirections))
      ->capture_default_str();
  sub->add_option("--k-a", opt->k_a, "Gain k_A of surface A")
      ->check(numberInRange(0.0, 1000.0))
      ->capture_default_str();
  sub->add_option("--k-b", opt->k_b, "Gain k_B of surface B")
      ->check(numberInRange(0.0, 1000.0))
      ->capture_default_str();
  sub->add_option("--mu0", opt->mu0, "Nominal coefficient mu0")
      ->check(numberInRange(0.0, 1000.0))
      ->capture_default_str();
  sub->add_option("--mu-max", opt->mu_max, "Clamp of the ploughing term (2/pi) tan(theta)")
      ->check(positiveNumber())
      ->check(numberInRange(0.0, 1000.0))
      ->capture_default_str();

  // Outputs.
  sub->add_flag("--json", opt->json, "Print JSON instead of a table");
  sub->add_option("--svg", opt->svg, "Write the figure as SVG");
  sub->add_option("--png", opt->png, "Write the figure as PNG");

  sub->callback([opt]() { runCone(*opt); });
}

}  // namespace asperity::cli
