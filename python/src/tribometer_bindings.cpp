// asperity.tribometer and asperity.calibrate: the virtual tribometer and the calibration of
// Eq. 7's gains (src/tribometer) with the options of the two commands, returning NumPy arrays.
#include <cmath>
#include <optional>

#include "asperity/tribometer/calibrate.hpp"
#include "asperity/tribometer/tribometer.hpp"
#include "bindings.hpp"

namespace asperity::python {
namespace {

// A texture argument: None, a path or a gen:NAME:SEED text.
std::string textureText(const py::handle& value) {
  if (value.is_none()) return "";
  if (!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__"))
    throwType("textures must be paths or 'gen:NAME:SEED[:P=V,...]' strings");
  return py::str(py::module_::import("os").attr("fspath")(value));
}

// One column of the result: a coefficient per direction, NaN where the test gave none.
py::array_t<double> column(const TribometerResult& r,
                           std::optional<double> TribometerDirection::*field) {
  py::array_t<double> out(static_cast<py::ssize_t>(r.directions.size()));
  for (size_t k = 0; k < r.directions.size(); ++k)
    out.mutable_at(static_cast<py::ssize_t>(k)) = (r.directions[k].*field).value_or(std::nan(""));
  return out;
}

// The result as a dict of arrays.
py::dict resultDict(const TribometerResult& r) {
  const auto n = static_cast<py::ssize_t>(r.directions.size());
  py::array_t<double> angles(n);
  py::array_t<bool> toppled(n);
  for (py::ssize_t k = 0; k < n; ++k) {
    angles.mutable_at(k) = r.directions[static_cast<size_t>(k)].angle_deg;
    toppled.mutable_at(k) = r.directions[static_cast<size_t>(k)].toppled;
  }
  py::dict d;
  d["angle_deg"] = angles, d["mu_s"] = column(r, &TribometerDirection::mu_s);
  d["mu_k"] = column(r, &TribometerDirection::mu_k);
  d["mu_model"] = column(r, &TribometerDirection::mu_model);
  d["toppled"] = toppled;
  return d;
}

// Which tests of `tests` ("tilt", "drag") run.
void chooseTests(const std::vector<std::string>& tests, TribometerSettings& settings) {
  settings.tilt = settings.drag = false;
  for (const std::string& t : tests) {
    if (t != "tilt" && t != "drag") throwValue("tests: unknown test '" + t + "' (tilt, drag)");
    (t == "tilt" ? settings.tilt : settings.drag) = true;
  }
}

// The surfaces as the commands name them: textures or two bodies of a scene, given values.
TribometerSource makeSource(const py::handle& b, const py::handle& a, const py::handle& scene,
                            const std::vector<std::string>& bodies, std::optional<double> k_a,
                            std::optional<double> k_b, std::optional<double> mu0,
                            double texture_size, std::optional<std::string> sampler) {
  TribometerSource source;
  source.plate = textureText(b), source.block = textureText(a);
  source.scene = textureText(scene);
  if (!bodies.empty() && bodies.size() != 2)
    throwValue("bodies: expected two body names, got " + std::to_string(bodies.size()));
  if (bodies.size() == 2) source.block_body = bodies[0], source.plate_body = bodies[1];
  source.k_a = k_a, source.k_b = k_b, source.mu0 = mu0;
  source.texture_size = texture_size;
  source.sampler = std::move(sampler);
  return source;
}

// The rig both run.
TribometerSettings makeRig(double block_size, double block_height, double load, int tracks,
                           int threads) {
  TribometerSettings settings;
  settings.block_size = block_size, settings.block_height = block_height, settings.load = load;
  settings.tracks = tracks, settings.threads = threads;
  return settings;
}

// A calibration as a dict: the CLI's JSON (the fitted keys, rms_residual) and the rows.
py::dict calibrationDict(const CalibrationRun& c) {
  py::dict d;
  if (c.spec.fit_k_a) d["k_a"] = c.result.k_a;
  if (c.spec.fit_k_b) d["k_b"] = c.result.k_b;
  if (c.spec.fit_mu0) d["mu0"] = c.result.mu0;
  d["rms_residual"] = c.result.rms_residual;
  const auto n = static_cast<py::ssize_t>(c.data.rows.size());
  py::array_t<double> angle(n), measured(n), model(n), residual(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto k = static_cast<size_t>(i);
    angle.mutable_at(i) = c.data.rows[k].angle_deg, measured.mutable_at(i) = c.data.rows[k].mu;
    model.mutable_at(i) = c.result.model[k], residual.mutable_at(i) = c.result.residual[k];
  }
  d["angle_deg"] = angle, d["measured"] = measured, d["model"] = model, d["residual"] = residual;
  return d;
}

// asperity.tribometer.
void defineTribometer(py::module_& m) {
  m.def(
      "tribometer",
      [](const py::handle& b, const py::handle& a, const py::handle& scene,
         const std::vector<std::string>& bodies, int directions, std::optional<double> k_a,
         std::optional<double> k_b, std::optional<double> mu0, double texture_size,
         double block_size, double block_height, double load, const std::vector<std::string>& tests,
         int tracks, int threads, std::optional<std::string> sampler) {
        // The source and the rig, as the CLI's options name them; then the runs without the GIL.
        const TribometerSource source =
            makeSource(b, a, scene, bodies, k_a, k_b, mu0, texture_size, sampler);
        TribometerSettings settings = makeRig(block_size, block_height, load, tracks, threads);
        settings.directions = directions;
        chooseTests(tests, settings);
        Diagnostics diagnostics;
        diagnostics.setSink(warn);
        const TribometerSurfaces surfaces = resolveTribometerSource(source, settings, diagnostics);
        TribometerResult result;
        {
          py::gil_scoped_release release;
          result = runTribometer(surfaces, settings);
        }
        return resultDict(result);
      },
      py::arg("b") = py::none(), py::arg("a") = py::none(), py::kw_only(),
      py::arg("scene") = py::none(), py::arg("bodies") = std::vector<std::string>{},
      py::arg("directions") = 16, py::arg("k_a") = py::none(), py::arg("k_b") = py::none(),
      py::arg("mu0") = py::none(), py::arg("texture_size") = 0.256, py::arg("block_size") = 0.1,
      py::arg("block_height") = 0.025, py::arg("load") = 10.0,
      py::arg("tests") = std::vector<std::string>{"tilt", "drag"}, py::arg("tracks") = 4,
      py::arg("threads") = 0, py::arg("sampler") = py::none(),
      "The virtual tribometer (`asperity tribometer`, docs/tribometer.md): a block (texture a, "
      "flat when None) on a plate (texture b), each a PNG path or 'gen:NAME:SEED[:P=V,...]', or "
      "two bodies (block, plate) of a scene; the tilt table and the drag test in `directions` "
      "directions. Returns {'angle_deg', 'mu_s', 'mu_k', 'mu_model': (N,) float64 (NaN where a "
      "test gave none), 'toppled': (N,) bool}; the same numbers on any thread count.");
}

// asperity.calibrate.
void defineCalibrate(py::module_& m) {
  m.def(
      "calibrate",
      [](const py::handle& data, const py::handle& b, const py::handle& a, const py::handle& scene,
         const std::vector<std::string>& bodies, std::optional<double> k_a,
         std::optional<double> k_b, std::optional<double> mu0, const std::vector<std::string>& fit,
         const std::string& model, double texture_size, double block_size, double block_height,
         double load, int tracks, int threads, std::optional<std::string> sampler,
         const py::handle& write) {
        if (model != "sampler" && model != "cone")
          throwValue("model: must be sampler or cone, got '" + model + "'");
        const TribometerSource source =
            makeSource(b, a, scene, bodies, k_a, k_b, mu0, texture_size, sampler);
        const TribometerSettings settings =
            makeRig(block_size, block_height, load, tracks, threads);
        const ModelKind kind = model == "cone" ? ModelKind::Cone : ModelKind::Sampler;
        Diagnostics diagnostics;
        diagnostics.setSink(warn);
        // The model's runs without the GIL (warnings come before, from resolving the surfaces).
        CalibrationRun c;
        const std::string file = textureText(data);
        {
          py::gil_scoped_release release;
          c = calibrate(file, source, fit, kind, settings, diagnostics);
        }
        if (!write.is_none()) writeCalibratedScene(c, source, textureText(write));
        return calibrationDict(c);
      },
      py::arg("data"), py::arg("b") = py::none(), py::arg("a") = py::none(), py::kw_only(),
      py::arg("scene") = py::none(), py::arg("bodies") = std::vector<std::string>{},
      py::arg("k_a") = py::none(), py::arg("k_b") = py::none(), py::arg("mu0") = py::none(),
      py::arg("fit") = std::vector<std::string>{}, py::arg("model") = "sampler",
      py::arg("texture_size") = 0.256, py::arg("block_size") = 0.1, py::arg("block_height") = 0.025,
      py::arg("load") = 10.0, py::arg("tracks") = 4, py::arg("threads") = 0,
      py::arg("sampler") = py::none(), py::arg("write") = py::none(),
      "Fits k_a, k_b and/or mu0 of Eq. 7 to measurements (`asperity calibrate`, "
      "docs/calibration.md): data is a CSV of angle_deg,mu or angle_deg,tilt_deg or "
      "angle_deg,speed,distance; the surfaces as for tribometer(); k_a, k_b, mu0 given are fixed, "
      "fit names the free ones. Returns the fitted keys and 'rms_residual' (the CLI's JSON) and "
      "'angle_deg', 'measured', 'model', 'residual' per row as arrays; write=PATH also writes a "
      "scene with the fitted values.");
}

}  // namespace

void bindTribometer(py::module_& m) {
  defineTribometer(m);
  defineCalibrate(m);
}

}  // namespace asperity::python
