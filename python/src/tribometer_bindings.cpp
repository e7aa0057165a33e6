// asperity.tribometer: the virtual tribometer (src/tribometer) with the options of
// `asperity tribometer`, returning NumPy arrays.
#include <cmath>
#include <optional>

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
    if (t != "tilt" && t != "drag") throwValue("--tests: unknown test '" + t + "' (tilt, drag)");
    (t == "tilt" ? settings.tilt : settings.drag) = true;
  }
}

}  // namespace

void bindTribometer(py::module_& m) {
  m.def(
      "tribometer",
      [](const py::handle& b, const py::handle& a, const py::handle& scene,
         const std::vector<std::string>& bodies, int directions, std::optional<double> k_a,
         std::optional<double> k_b, std::optional<double> mu0, double texture_size,
         double block_size, double block_height, double load, const std::vector<std::string>& tests,
         int tracks, int threads, std::optional<std::string> sampler) {
        // The source, as the CLI's options name it.
        TribometerSource source;
        source.plate = textureText(b), source.block = textureText(a);
        source.scene = textureText(scene);
        if (!bodies.empty() && bodies.size() != 2) throwValue("--bodies: expected two body names");
        if (bodies.size() == 2) source.block_body = bodies[0], source.plate_body = bodies[1];
        source.k_a = k_a, source.k_b = k_b, source.mu0 = mu0;
        source.texture_size = texture_size;
        // The rig, then the runs without the GIL.
        TribometerSettings settings;
        settings.directions = directions, settings.block_size = block_size;
        settings.block_height = block_height, settings.load = load;
        settings.tracks = tracks, settings.threads = threads;
        chooseTests(tests, settings);
        Diagnostics diagnostics;
        diagnostics.setSink(warn);
        const TribometerSurfaces surfaces = resolveTribometerSource(source, settings, diagnostics);
        if (sampler) settings.sampler = *sampler;
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

}  // namespace asperity::python
