// `asperity calibrate`: k_A, k_B and/or mu0 of Eq. 7 fitted to measurements of a material pair
// (src/tribometer/calibrate.cpp), against the tribometer's sampler or the whole-texture cone;
// the fitted values, the residual per row, JSON, a figure, and the values written into a scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "asperity/tribometer/calibrate.hpp"
#include "cli_common.hpp"
#include "polar_figure.hpp"
#include "tribometer_options.hpp"

namespace asperity::cli {
namespace {

struct CalibrateOptions {
  std::string data;
  SurfaceOptions surfaces;
  std::vector<std::string> fit;
  std::string model = "sampler";
  TribometerSettings settings;
  bool json = false;
  std::string svg, png, write;
};

// {"k_a", "k_b", "mu0"} as fitted (only the fitted ones), then "rms_residual".
nlohmann::ordered_json resultJson(const CalibrationRun& c) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (c.spec.fit_k_a) j["k_a"] = c.result.k_a;
  if (c.spec.fit_k_b) j["k_b"] = c.result.k_b;
  if (c.spec.fit_mu0) j["mu0"] = c.result.mu0;
  j["rms_residual"] = c.result.rms_residual;
  return j;
}

// The readable form: the values, then one row per measurement with its residual.
void printTable(const CalibrationRun& c, const std::string& model) {
  char line[160];
  const auto value = [](double x, bool fitted) {
    char buf[48];
    std::snprintf(buf, sizeof(buf), "%.4f (%s)", x, fitted ? "fitted" : "fixed");
    return std::string(buf);
  };
  std::cout << "model: " << model << ", " << c.data.rows.size() << " rows of " << c.data.file
            << "\nk_a = " << value(c.result.k_a, c.spec.fit_k_a)
            << "  k_b = " << value(c.result.k_b, c.spec.fit_k_b)
            << "  mu0 = " << value(c.result.mu0, c.spec.fit_mu0) << '\n';
  std::snprintf(line, sizeof(line),
                "rms residual = %.4f\n  line  angle_deg   measured      model   residual\n",
                c.result.rms_residual);
  std::cout << line;
  for (size_t i = 0; i < c.data.rows.size(); ++i) {
    const Measurement& m = c.data.rows[i];
    std::snprintf(line, sizeof(line), "  %4d  %9.2f  %9.4f  %9.4f  %+9.4f\n", m.line, m.angle_deg,
                  m.mu, c.result.model[i], c.result.residual[i]);
    std::cout << line;
  }
}

// The figure: the measurements as dots, the fitted model through the measured directions.
void writeFigure(const CalibrateOptions& opt, const CalibrationRun& c, const std::string& model) {
  PolarFigure f;
  f.plate = c.surfaces.plate.normal_map.get(), f.block = c.surfaces.block.normal_map.get();
  f.plate_name = plateName(opt.surfaces);
  f.block_name = blockName(opt.surfaces);
  f.title = "Calibration: " + plot::shortName(c.data.file, 40) + " (" + model + " model)";
  char subtitle[160];
  std::snprintf(subtitle, sizeof(subtitle), "k_A = %.4g, k_B = %.4g, mu0 = %.4g, rms residual %.4f",
                c.result.k_a, c.result.k_b, c.result.mu0, c.result.rms_residual);
  f.subtitle = subtitle;
  // The model once per measured direction, in angle order.
  std::map<double, double> fitted;
  PolarCurve measured{{}, {}, {plot::kRed, 0.0, 0.0, false, 3.5, false}, "measured"};
  for (size_t i = 0; i < c.data.rows.size(); ++i) {
    measured.angles_deg.push_back(c.data.rows[i].angle_deg);
    measured.values.push_back(c.data.rows[i].mu);
    fitted[std::fmod(std::fmod(c.data.rows[i].angle_deg, 360.0) + 360.0, 360.0)] =
        c.result.model[i];
  }
  PolarCurve model_curve{
      {}, {}, {plot::kBlue, 0.0, 2.0, false, 0.0, fitted.size() >= 3}, "fitted model"};
  for (const auto& [angle, mu] : fitted)
    model_curve.angles_deg.push_back(angle), model_curve.values.push_back(mu);
  f.curves = {model_curve, measured};
  f.notes = {"radius: mu against sliding toward", "that direction; u, v: the plate's axes"};
  if (!opt.svg.empty()) writePolarFigure(f, opt.svg, true);
  if (!opt.png.empty()) writePolarFigure(f, opt.png, false);
}

// The subcommand's action: calibrate, print, draw, write the scene.
void runCalibrate(const CalibrateOptions& opt, const CLI::App& sub) {
  Diagnostics diagnostics;
  diagnostics.setSink(printWarning);
  const TribometerSource source = sourceFor(opt.surfaces, sub);
  const ModelKind kind = opt.model == "cone" ? ModelKind::Cone : ModelKind::Sampler;
  const CalibrationRun c = calibrate(opt.data, source, opt.fit, kind, opt.settings, diagnostics);
  if (opt.json)
    std::cout << resultJson(c).dump(2) << '\n';
  else
    printTable(c, opt.model);
  if (!opt.svg.empty() || !opt.png.empty()) writeFigure(opt, c, opt.model);
  if (!opt.write.empty()) writeCalibratedScene(c, source, opt.write);
}

// The parameters: which are free and the model fitted against.
void addFitOptions(CLI::App* sub, CalibrateOptions& opt) {
  sub->add_option("--fit", opt.fit, "The free parameters (k_a, k_b, mu0; comma separated)")
      ->delimiter(',');
  sub->add_option("--model", opt.model, "sampler (a sliding block's contacts) or cone")
      ->check(CLI::IsMember({"sampler", "cone"}))
      ->capture_default_str();
}

}  // namespace

void registerCalibrateCommand(CLI::App& app) {
  auto opt = std::make_shared<CalibrateOptions>();
  CLI::App* sub = app.add_subcommand(
      "calibrate", "Fit k_A, k_B and/or mu0 of Eq. 7 to friction measured on a material pair");
  sub->add_option("DATA", opt->data,
                  "Measurements (CSV: angle_deg,mu or angle_deg,tilt_deg or "
                  "angle_deg,speed,distance)")
      ->required();
  addSurfaceOptions(sub, opt->surfaces, true);
  addFitOptions(sub, *opt);
  addRigOptions(sub, opt->settings);
  sub->add_flag("--json", opt->json, "Print the fitted values as JSON");
  sub->add_option("--svg", opt->svg, "Write the figure as SVG");
  sub->add_option("--png", opt->png, "Write the figure as PNG");
  sub->add_option("--write", opt->write, "Write a scene with the fitted values");
  sub->callback([opt, sub]() { runCalibrate(*opt, *sub); });
}

}  // namespace asperity::cli
