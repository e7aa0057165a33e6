// `asperity tribometer`: the tilt table and the drag test of a block on a plate in N
// directions (src/tribometer), for two textures or two bodies of a scene; a table, JSON, and an
// SVG / PNG figure of mu_s, mu_k and mu_model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/tribometer/tribometer.hpp"
#include "cli_common.hpp"
#include "polar_figure.hpp"
#include "tribometer_options.hpp"

namespace asperity::cli {
namespace {

struct TribometerOptions {
  SurfaceOptions surfaces;
  std::vector<std::string> tests{"tilt", "drag"};
  TribometerSettings settings;
  bool json = false;
  std::string svg, png;
};

// A coefficient as JSON: the number, or null where the test gave none.
nlohmann::ordered_json orNull(const std::optional<double>& x) {
  return x ? nlohmann::ordered_json(*x) : nlohmann::ordered_json(nullptr);
}

// {"directions": [{"angle_deg", "mu_s", "mu_k", "mu_model"}, ...]}.
nlohmann::ordered_json resultJson(const TribometerResult& r) {
  nlohmann::ordered_json dirs = nlohmann::ordered_json::array();
  for (const TribometerDirection& d : r.directions)
    dirs.push_back({{"angle_deg", d.angle_deg},
                    {"mu_s", orNull(d.mu_s)},
                    {"mu_k", orNull(d.mu_k)},
                    {"mu_model", orNull(d.mu_model)}});
  return {{"directions", dirs}};
}

// A table cell: the number, or why there is none.
std::string cell(const std::optional<double>& x, const char* none) {
  char buf[32];
  if (x)
    std::snprintf(buf, sizeof(buf), "%9.4f", *x);
  else
    std::snprintf(buf, sizeof(buf), "%9s", none);
  return buf;
}

// The readable form: what was tested, then one row per direction.
void printTable(const std::string& subtitle, const TribometerResult& r) {
  std::cout << subtitle << "\n  angle_deg       mu_s       mu_k   mu_model\n";
  for (const TribometerDirection& d : r.directions) {
    char angle[32];
    std::snprintf(angle, sizeof(angle), "  %9.2f", d.angle_deg);
    std::cout << angle << "  " << cell(d.mu_s, d.toppled ? "toppled" : "no slide") << "  "
              << cell(d.mu_k, "stuck") << "  " << cell(d.mu_model, "-") << '\n';
  }
}

// One coefficient per direction, NaN where the test gave none.
std::vector<double> column(const TribometerResult& r,
                           std::optional<double> TribometerDirection::*field) {
  std::vector<double> values;
  for (const TribometerDirection& d : r.directions)
    values.push_back((d.*field).value_or(std::nan("")));
  return values;
}

// The figure: the maps as named (or the scene's bodies), mu_s, mu_k, and mu_model dashed on top
// (where it mostly covers mu_k).
void writeFigure(const TribometerOptions& opt, const TribometerSurfaces& surfaces,
                 const std::string& subtitle, const TribometerResult& result) {
  PolarFigure f;
  f.plate = surfaces.plate.normal_map.get();
  f.block = surfaces.block.normal_map.get();
  f.plate_name = plateName(opt.surfaces);
  f.block_name = blockName(opt.surfaces);
  f.title = "Tribometer: block A = " + (f.block_name.empty() ? "flat" : f.block_name) +
            " on plate B = " + f.plate_name;
  f.subtitle = subtitle;
  std::vector<double> angles;
  for (const TribometerDirection& d : result.directions) angles.push_back(d.angle_deg);
  f.curves = {{angles,
               column(result, &TribometerDirection::mu_s),
               {plot::kRed, 0.0, 1.5, false, 3.0, true},
               "mu_s: tilt table"},
              {angles,
               column(result, &TribometerDirection::mu_k),
               {plot::kBlue, 0.0, 2.0, false, 3.5, true},
               "mu_k: drag test"},
              {angles,
               column(result, &TribometerDirection::mu_model),
               {plot::kGreen, 0.0, 2.0, true, 0.0, true},
               "mu_model: the contacts' mu"}};
  f.notes = {"gaps: no slide / no steady sliding", "radius: mu against sliding toward",
             "that direction; u, v: the plate's axes"};
  if (!opt.svg.empty()) writePolarFigure(f, opt.svg, true);
  if (!opt.png.empty()) writePolarFigure(f, opt.png, false);
}

// The subcommand's action: surfaces, runs, then table or JSON, then the figure.
void runTribometerCommand(const TribometerOptions& opt, const CLI::App& sub) {
  TribometerSettings settings = opt.settings;
  Diagnostics diagnostics;
  diagnostics.setSink(printWarning);
  const TribometerSurfaces surfaces =
      resolveTribometerSource(sourceFor(opt.surfaces, sub), settings, diagnostics);
  settings.tilt = std::find(opt.tests.begin(), opt.tests.end(), "tilt") != opt.tests.end();
  settings.drag = std::find(opt.tests.begin(), opt.tests.end(), "drag") != opt.tests.end();
  const TribometerResult result = runTribometer(surfaces, settings);
  char subtitle[200];
  std::snprintf(subtitle, sizeof(subtitle),
                "mu0 = %g, k_A = %g, k_B = %g, block %g x %g x %g m, %g N, sampler %s",
                settings.friction.mu0, surfaces.block.gain, surfaces.plate.gain,
                settings.block_size, settings.block_size, settings.block_height, settings.load,
                settings.sampler.c_str());
  if (opt.json)
    std::cout << resultJson(result).dump(2) << '\n';
  else
    printTable(subtitle, result);
  if (!opt.svg.empty() || !opt.png.empty()) writeFigure(opt, surfaces, subtitle, result);
}

// What is tested beyond the rig: how many directions, which tests, the ploughing clamp.
void addTestOptions(CLI::App* sub, TribometerOptions& opt) {
  sub->add_option("--directions", opt.settings.directions, "Number of test directions N")
      ->check(CLI::Range(1, 360))
      ->capture_default_str();
  sub->add_option("--tests", opt.tests, "Which tests: tilt, drag (comma separated)")
      ->delimiter(',')
      ->check(CLI::IsMember({"tilt", "drag"}));
  sub->add_option("--mu-max", opt.settings.friction.mu_max, "Clamp of the ploughing term")
      ->check(settingRange("mu_max", friction_range::mu_max))
      ->capture_default_str();
}

}  // namespace

void registerTribometerCommand(CLI::App& app) {
  auto opt = std::make_shared<TribometerOptions>();
  CLI::App* sub = app.add_subcommand(
      "tribometer", "Tilt table and drag test of a block on a plate in N directions (SPEC 12)");
  addSurfaceOptions(sub, opt->surfaces, false);
  addRigOptions(sub, opt->settings);
  addTestOptions(sub, *opt);
  sub->add_flag("--json", opt->json, "Print JSON instead of a table");
  sub->add_option("--svg", opt->svg, "Write the figure as SVG");
  sub->add_option("--png", opt->png, "Write the figure as PNG");
  sub->callback([opt, sub]() { runTribometerCommand(*opt, *sub); });
}

}  // namespace asperity::cli
