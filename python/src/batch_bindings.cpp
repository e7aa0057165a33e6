// asperity._Batch: the C++ batch of worlds (src/batch) for asperity.Batch: state arrays as
// read-only NumPy views of the batch's own buffers, actions from (n, 3) arrays, resets, the
// drawn values and the hashes; stepping and resetting release the GIL.
#include <cstdio>

#include "asperity/batch/batch.hpp"
#include "asperity/world/run_loop.hpp"
#include "bindings.hpp"

namespace asperity::python {
namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A batch from the scene's JSON text and its file name (for relative paths and messages).
std::unique_ptr<Batch> makeBatch(const std::string& json_text, const std::string& scene_file,
                                 const std::vector<std::pair<std::string, std::string>>& vary,
                                 int64_t n, uint64_t seed, int threads) {
  BatchDesc d;
  d.scene_json = json_text;
  d.scene_file = scene_file;
  for (const auto& [path, spec] : vary) d.vary.push_back(parseVariation(path, spec));
  d.worlds = n;
  d.seed = seed;
  d.threads = threads;
  std::unique_ptr<Batch> batch;
  {
    py::gil_scoped_release release;
    batch = std::make_unique<Batch>(std::move(d));
  }
  // The scene's warnings once (every world has the same), as asperity.World issues them.
  for (const std::string& w : batch->world(0).diagnostics().warnings()) warn(w);
  return batch;
}

// "(a, b, c)" for messages.
std::string shapeText(const std::vector<py::ssize_t>& shape) {
  std::string s = "(";
  for (size_t k = 0; k < shape.size(); ++k) s += (k ? ", " : "") + std::to_string(shape[k]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

// An array of float64 of exactly `shape`, else TypeError / ValueError naming `name`.
Doubles arrayArg(const py::handle& values, const std::vector<py::ssize_t>& shape,
                 const std::string& name) {
  Doubles a;
  try {
    a = Doubles::ensure(values);
  } catch (const py::error_already_set&) {
  }
  if (!a) throwType(name + " must be an array of numbers");
  const std::vector<py::ssize_t> got(a.shape(), a.shape() + a.ndim());
  if (got != shape)
    throwValue(name + " must have shape " + shapeText(shape) + ", got " + shapeText(got));
  return a;
}

// A read-only (n, B, width) view of one of the batch's state buffers; the view keeps the
// batch alive, and each step or reset refreshes what it shows.
py::array stateView(const py::object& self, const std::vector<double>& data, py::ssize_t width) {
  const Batch& b = self.cast<const Batch&>();
  const auto n = static_cast<py::ssize_t>(b.size());
  const auto bodies = static_cast<py::ssize_t>(b.bodyNames().size());
  const auto d = static_cast<py::ssize_t>(sizeof(double));
  py::array view(py::dtype::of<double>(), {n, bodies, width}, {bodies * width * d, width * d, d},
                 data.data(), self);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

// One action for every world from an (n, 3) array, or (n,) for joint targets.
void setAction(Batch& b, BatchAction kind, uint32_t target, const py::handle& values,
               const std::string& name) {
  const auto n = static_cast<py::ssize_t>(b.size());
  std::vector<py::ssize_t> shape = {n};
  if (kind != BatchAction::JointTarget) shape.push_back(3);
  const Doubles a = arrayArg(values, shape, name);
  b.setAction(kind, target, std::span<const double>(a.data(), static_cast<size_t>(a.size())));
}

// reset()'s state dict: each given part, with its shape checked, copied once.
BatchState stateArg(const Batch& b, const py::dict& state) {
  BatchState s;
  const auto n = static_cast<py::ssize_t>(b.size());
  const auto bodies = static_cast<py::ssize_t>(b.bodyNames().size());
  const std::pair<const char*, std::vector<double>*> parts[] = {
      {"positions", &s.positions},
      {"orientations", &s.orientations},
      {"linear_velocities", &s.linear_velocities},
      {"angular_velocities", &s.angular_velocities}};
  for (const auto& [key, value] : state) {
    const std::string name = py::str(key);
    size_t k = 0;
    while (k < 4 && name != parts[k].first) ++k;
    if (k == 4)
      throwValue("reset: state has no part '" + name +
                 "' (positions, orientations, linear_velocities, angular_velocities)");
    const Doubles a =
        arrayArg(value, {n, bodies, py::ssize_t{k == 1 ? 4 : 3}}, "reset: state['" + name + "']");
    parts[k].second->assign(a.data(), a.data() + a.size());
  }
  return s;
}

// reset(mask, state, samples) with Python's arguments.
void reset(Batch& b, const py::object& mask, const py::object& state, const py::object& samples) {
  const auto n = static_cast<py::ssize_t>(b.size());
  std::vector<uint8_t> chosen;
  if (!mask.is_none()) {
    const auto m = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(mask);
    if (!m) throwType("reset: mask must be an array of booleans");
    if (m.ndim() != 1 || m.shape(0) != n)
      throwValue("reset: mask must have shape (" + std::to_string(n) + ",)");
    chosen.assign(m.data(), m.data() + n);
  }
  std::vector<int64_t> indices;
  if (!samples.is_none()) {
    const auto s = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(samples);
    if (!s) throwType("reset: samples must be an array of integers");
    if (s.ndim() != 1 || s.shape(0) != n)
      throwValue("reset: samples must have shape (" + std::to_string(n) + ",)");
    indices.assign(s.data(), s.data() + n);
  }
  if (!state.is_none() && !py::isinstance<py::dict>(state))
    throwType("reset: state must be a dict of arrays such as {'positions': ...}");
  const BatchState given = state.is_none() ? BatchState() : stateArg(b, state.cast<py::dict>());
  py::gil_scoped_release release;
  b.reset(chosen, state.is_none() ? nullptr : &given, indices);
}

// The varied values, one (n,) array per variation path.
py::dict values(const Batch& b) {
  py::dict out;
  const auto n = static_cast<py::ssize_t>(b.size());
  for (size_t j = 0; j < b.desc().vary.size(); ++j) {
    py::array_t<double> column(n);
    for (py::ssize_t i = 0; i < n; ++i) column.mutable_at(i) = b.values(i)[j];
    out[py::str(b.desc().vary[j].path)] = column;
  }
  return out;
}

// Each world's hash as 16 hex digits, in a NumPy array of strings.
py::object stateHashes(const Batch& b) {
  py::list hashes;
  for (const uint64_t h : b.stateHashes()) {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h));
    hashes.append(text);
  }
  return py::module_::import("numpy").attr("array")(hashes, "U16");
}

// The actions: one method per kind, each taking a body (or joint) name and an array.
void bindActions(py::class_<Batch>& batch) {
  const auto body = [](BatchAction kind, const char* method, const char* argument) {
    return [=](Batch& b, const std::string& target, const py::handle& values) {
      const std::string name = std::string(method) + "('" + target + "'): " + argument;
      setAction(b, kind, b.bodyIndex(target), values, name);
    };
  };
  batch
      .def("set_force", body(BatchAction::Force, "set_force", "force"), py::arg("body"),
           py::arg("force"),
           "Force (N, world frame) on a dynamic body's frame origin, one row per world ((n, 3)), "
           "for every step of the next step() call.")
      .def("set_torque", body(BatchAction::Torque, "set_torque", "torque"), py::arg("body"),
           py::arg("torque"),
           "Torque (N m, world frame) on a dynamic body, (n, 3), for the next step() call.")
      .def("set_velocity", body(BatchAction::LinearVelocity, "set_velocity", "velocity"),
           py::arg("body"), py::arg("velocity"),
           "Velocity (m/s) of a kinematic or dynamic body's frame origin, (n, 3), set before each "
           "step of the next step() call.")
      .def("set_angular_velocity",
           body(BatchAction::AngularVelocity, "set_angular_velocity", "angular_velocity"),
           py::arg("body"), py::arg("angular_velocity"),
           "Angular velocity (rad/s, world frame), (n, 3), set before each step of the next "
           "step() call (before set_velocity's, which keeps the frame origin's velocity).")
      .def(
          "set_joint_target",
          [](Batch& b, const std::string& joint, const py::handle& lengths) {
            setAction(b, BatchAction::JointTarget, b.jointIndex(joint), lengths,
                      "set_joint_target('" + joint + "'): lengths");
          },
          py::arg("joint"), py::arg("lengths"),
          "Rest length (m) of a distance joint, one per world ((n,)); it stays until set again.")
      .def("clear_actions", &Batch::clearActions, "Forgets the actions set since the last step.");
}

}  // namespace

void bindBatch(py::module_& m) {
  py::class_<Batch> batch(m, "_Batch", "The C++ batch of worlds; use asperity.Batch.");
  batch
      .def(py::init(&makeBatch), py::arg("scene_json"), py::arg("scene_file"), py::arg("vary"),
           py::arg("n"), py::arg("seed"), py::arg("threads"))
      .def(
          "step",
          [](Batch& b, int64_t k) {
            if (k > kMaxSteps)
              throwValue("step: k must be in 0.." + std::to_string(kMaxSteps) + ", got " +
                         std::to_string(k));
            py::gil_scoped_release release;
            b.step(k);
          },
          py::arg("k") = 1,
          "Steps every world k times on the pool (the GIL is released), with the actions set "
          "since the last step; then forgets them.")
      .def("reset", &reset, py::arg("mask") = py::none(), py::arg("state") = py::none(),
           py::arg("samples") = py::none(),
           "Puts the worlds where mask is true (all when None) back to their initial state as "
           "new worlds; `state` ({'positions': (n, B, 3), ...}) replaces parts of it, `samples` "
           "((n,) ints) makes world i sample samples[i] with that sample's values.")
      .def("state_hashes", &stateHashes, "(n,) strings of 16 hex digits, World.state_hash's.");
  // The state views and what describes the worlds.
  const auto view = [](std::vector<double> BatchState::*part, py::ssize_t width) {
    return [part, width](const py::object& self) {
      return stateView(self, self.cast<const Batch&>().state().*part, width);
    };
  };
  batch.def_property_readonly("positions", view(&BatchState::positions, 3))
      .def_property_readonly("orientations", view(&BatchState::orientations, 4))
      .def_property_readonly("linear_velocities", view(&BatchState::linear_velocities, 3))
      .def_property_readonly("angular_velocities", view(&BatchState::angular_velocities, 3))
      .def_property_readonly("values", &values)
      .def_property_readonly("samples",
                             [](const Batch& b) {
                               py::array_t<int64_t> s(static_cast<py::ssize_t>(b.size()));
                               for (int64_t i = 0; i < b.size(); ++i) s.mutable_at(i) = b.sample(i);
                               return s;
                             })
      .def_property_readonly("times",
                             [](const Batch& b) {
                               py::array_t<double> t(static_cast<py::ssize_t>(b.size()));
                               for (int64_t i = 0; i < b.size(); ++i)
                                 t.mutable_at(i) = b.world(i).time();
                               return t;
                             })
      .def_property_readonly("dt", [](const Batch& b) { return b.world(0).settings().dt; })
      .def_property_readonly("body_names", &Batch::bodyNames)
      .def_property_readonly("joint_names", &Batch::jointNames)
      .def("__len__", &Batch::size);
  bindActions(batch);
}

}  // namespace asperity::python
