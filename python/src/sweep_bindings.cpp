// asperity._Sweep: the C++ sweep core (src/sweep) for asperity.sweep, which runs samples here
// on a oneTBB pool or hands index ranges to Dask workers that build their own _Sweep.
#include <cstdio>

#include "asperity/sweep/sweep.hpp"
#include "bindings.hpp"

namespace asperity::python {
namespace {

// A sweep from the scene's JSON text and its file name (for relative paths and messages).
Sweep makeSweep(const std::string& json_text, const std::string& scene_file,
                const std::vector<std::pair<std::string, std::string>>& vary, int64_t samples,
                uint64_t seed, double seconds, const std::vector<std::string>& measures) {
  SweepDesc d;
  d.scene_json = json_text;
  d.scene_file = scene_file;
  for (const auto& [path, spec] : vary) d.vary.push_back(parseVariation(path, spec));
  d.samples = samples;
  d.seed = seed;
  d.seconds = seconds;
  d.measures = measures;
  return Sweep(std::move(d));
}

// The results as columns (dict of arrays keyed like the CSV) and the final states.
py::tuple resultColumns(const Sweep& sweep, const std::vector<SampleResult>& results) {
  const auto n = static_cast<py::ssize_t>(results.size());
  const auto bodies = static_cast<py::ssize_t>(sweep.bodyNames().size());
  const std::vector<std::string> names = sweep.columns();
  // Numeric columns between "sample" and "state_hash", row by row.
  const auto numeric = static_cast<py::ssize_t>(names.size()) - 2;
  py::array_t<double> table({n, numeric});
  py::array_t<int64_t> index(n);
  py::array_t<double> pos({n, bodies, py::ssize_t{3}}), rot({n, bodies, py::ssize_t{4}});
  py::array_t<double> lin({n, bodies, py::ssize_t{3}}), ang({n, bodies, py::ssize_t{3}});
  auto t = table.mutable_unchecked<2>();
  auto p = pos.mutable_unchecked<3>(), q = rot.mutable_unchecked<3>();
  auto v = lin.mutable_unchecked<3>(), w = ang.mutable_unchecked<3>();
  py::list hashes;
  for (py::ssize_t i = 0; i < n; ++i) {
    const SampleResult& r = results[static_cast<size_t>(i)];
    index.mutable_at(i) = r.index;
    py::ssize_t c = 0;
    for (double x : r.values) t(i, c++) = x;
    for (py::ssize_t b = 0; b < bodies; ++b) {
      const Transform& pose = r.poses[static_cast<size_t>(b)];
      const double qs[4] = {pose.rotation.w(), pose.rotation.x(), pose.rotation.y(),
                            pose.rotation.z()};
      for (int k = 0; k < 3; ++k) {
        t(i, c++) = p(i, b, k) = pose.position[k];
        v(i, b, k) = r.linear_velocities[static_cast<size_t>(b)][k];
        w(i, b, k) = r.angular_velocities[static_cast<size_t>(b)][k];
      }
      for (int k = 0; k < 4; ++k) t(i, c++) = q(i, b, k) = qs[k];
    }
    for (double x : r.measures) t(i, c++) = x;
    char hash[17];
    std::snprintf(hash, sizeof(hash), "%016llx", static_cast<unsigned long long>(r.state_hash));
    hashes.append(hash);
  }
  // Columns: views of the table copied out one by one, so each is contiguous.
  py::dict columns;
  columns["sample"] = index;
  for (py::ssize_t c = 0; c < numeric; ++c)
    columns[py::str(names[static_cast<size_t>(c + 1)])] =
        py::module_::import("numpy").attr("ascontiguousarray")(
            table[py::make_tuple(py::slice(py::none(), py::none(), py::none()), c)]);
  columns["state_hash"] = py::module_::import("numpy").attr("array")(hashes, "U16");
  py::dict state;
  state["positions"] = pos, state["orientations"] = rot;
  state["linear_velocities"] = lin, state["angular_velocities"] = ang;
  return py::make_tuple(columns, state);
}

}  // namespace

void bindSweep(py::module_& m) {
  py::class_<Sweep>(m, "_Sweep", "The C++ sweep core; use asperity.sweep.")
      .def(py::init(&makeSweep), py::arg("scene_json"), py::arg("scene_file"), py::arg("vary"),
           py::arg("samples"), py::arg("seed"), py::arg("seconds"), py::arg("measures"))
      .def_property_readonly("columns", &Sweep::columns)
      .def_property_readonly("body_names", &Sweep::bodyNames)
      .def(
          "run",
          [](const Sweep& sweep, const std::vector<int64_t>& indices, int threads) {
            std::vector<SampleResult> results;
            {
              // The samples run on the pool while other Python threads go on.
              py::gil_scoped_release release;
              results = sweep.runAll(threads, indices);
            }
            return resultColumns(sweep, results);
          },
          py::arg("indices"), py::arg("threads"),
          "Runs the samples (all when empty) on a pool of `threads` threads (0 = every core); "
          "returns (columns, final states).")
      .def(
          "csv",
          [](const Sweep& sweep, const std::vector<int64_t>& indices, int threads) {
            std::vector<SampleResult> results;
            {
              py::gil_scoped_release release;
              results = sweep.runAll(threads, indices);
            }
            return sweep.csv(results);
          },
          py::arg("indices"), py::arg("threads"), "Runs the samples; returns the CLI's CSV.");
}

}  // namespace asperity::python
