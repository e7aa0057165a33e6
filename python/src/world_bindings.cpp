// asperity.World: a world built from a scene, stepped with the GIL released, its state as
// NumPy arrays, its contacts, and forces, torques and impulses on named bodies.
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "asperity/error.hpp"
#include "asperity/sampler/friction_settings.hpp"
#include "asperity/scene/friction_providers.hpp"
#include "asperity/world/run_loop.hpp"
#include "world_state.hpp"
#ifdef ASPERITY_HAVE_RENDER
#include "asperity/scene/gl_sampler_provider.hpp"
#endif

namespace asperity::python {
namespace {

// An enumeration by the name the CLI and scenes use; ValueError naming the keyword otherwise.
template <typename E>
E lookup(EnumNames<E> names, const std::string& key, const char* what) {
  try {
    return parseName<E>(key, names, what);
  } catch (const Error& e) {
    throwValue(e.what());
  }
}

// The scene with the same overrides as `asperity run`, checked like its options.
std::unique_ptr<PyWorld> makeWorld(const py::handle& scene_arg, std::optional<std::string> sampler,
                                   std::optional<std::string> friction,
                                   std::optional<std::string> frame, std::optional<int> directions,
                                   std::optional<double> patch_width,
                                   std::optional<int> patch_resolution, std::optional<int> threads,
                                   const py::object& state) {
  // Scenes may ask for the core samplers and, when built with OpenGL, "gl".
  InstantiateOptions options;
#ifdef ASPERITY_HAVE_RENDER
  addGlPatchSampler(options.providers);
#endif
  auto w = std::make_unique<PyWorld>();
  w->scene = sceneFrom(scene_arg).desc;
  WorldSettings& s = w->scene.settings;
  if (friction)
    s.limit_surface = lookup<LimitSurfaceKind>(kLimitSurfaceNames, *friction, "friction");
  if (frame) s.frame.mode = lookup<FrameMode>(kFrameModeNames, *frame, "frame");
  if (sampler) {
    if (!options.providers.has(*sampler)) {
      try {
        options.providers.make(*sampler);
      } catch (const Error& e) {
        throwValue(std::string("sampler: ") + e.what());
      }
    }
    w->scene.friction_provider = *sampler;
  }
  if (threads && (*threads < 0 || *threads > kMaxThreads))
    throwValue("threads: must be in 0.." + std::to_string(kMaxThreads) + " (0 = every core), got " +
               std::to_string(*threads));
  if (threads) s.threads = *threads;
  if (directions) s.friction.directions = *directions;
  if (patch_width) s.friction.patch_width = *patch_width;
  if (patch_resolution) s.friction.patch_resolution = *patch_resolution;
  // The ranges every front end shares (the same words as a scene's or the CLI's).
  if (const auto bad = firstInvalidSetting(s.friction)) throwValue(bad->field + " " + bad->message);
  w->world = instantiate(w->scene, options);
  // The scene's and the world's warnings become Python warnings, now and as they come.
  w->world->diagnostics().setSink(warn);
  for (const Body& b : w->world->bodies())
    w->origin_offsets.push_back(b.com_offset.rotation.conjugate() * b.com_offset.position);
  if (!state.is_none()) loadState(*w, state);
  return w;
}

// A 3-vector argument of finite numbers.
Vec3 vec3Arg(const py::handle& value, const char* name) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 1 || a.shape(0) != 3)
    throwType(std::string(name) + " must be a sequence of 3 numbers");
  const Vec3 v(a.at(0), a.at(1), a.at(2));
  if (!v.allFinite()) throwValue(std::string(name) + " must be finite");
  return v;
}

// A load on a named body starting now: forces and torques last `duration` seconds (one step
// by default), impulses fire at the next step. `point` is in world coordinates.
void addLoad(PyWorld& w, const std::string& body, LoadDesc::Kind kind, const Vec3& value,
             const py::object& point, std::optional<double> duration) {
  LoadDesc load;
  load.name = "python";
  load.body = w.bodyId(body);
  load.kind = kind;
  load.value = value;
  const double t = w.world->time(), dt = w.world->settings().dt;
  load.start = t;
  if (duration && !(std::isfinite(*duration) && *duration >= 0.0))
    throwValue("duration: must be a finite number >= 0 (s)");
  load.end = t + (duration ? *duration : 0.5 * dt);
  if (!point.is_none())
    load.local_point =
        w.world->body(load.body).descriptionPose().applyInverse(vec3Arg(point, "point"));
  // Loads that have done their work go first: a controller adds one every step.
  w.world->removeFinishedLoads();
  w.world->addLoad(load);
}

// The world's hash, contacts and loads on named bodies.
void bindWorldActions(py::class_<PyWorld>& world) {
  world
      .def(
          "state_hash",
          [](const PyWorld& w) {
            char hash[17];
            std::snprintf(hash, sizeof(hash), "%016llx",
                          static_cast<unsigned long long>(w.world->stateHash()));
            return std::string(hash);
          },
          "16 hex digits, equal to `asperity run SCENE --hash` after the same steps.")
      .def_property_readonly(
          "warnings", [](const PyWorld& w) { return w.world->diagnostics().warnings(); },
          "The world's warnings so far (each also issued as a UserWarning when it came).")
      .def("contacts", &contacts,
           "Contacts of the last step as a dict of arrays (C contacts, N directions): body_a, "
           "body_b (C,) int32; points, normals (C, 3); frames (C, 3, 3) rows t, b, n; phi (C,) "
           "depth (m); impulses (C, 3) on A along t, b, n (N s); mu (C, N) float32; "
           "patch_pixels (C,) int32 |P|; fallback (C,) bool.")
      .def(
          "apply_force",
          [](PyWorld& w, const std::string& body, const py::handle& force, const py::object& point,
             std::optional<double> duration) {
            addLoad(w, body, LoadDesc::Kind::Force, vec3Arg(force, "force"), point, duration);
          },
          py::arg("body"), py::arg("force"), py::arg("point") = py::none(),
          py::arg("duration") = py::none(),
          "Force (N, world frame) on a named body at a world point (default: its frame's "
          "origin), for `duration` seconds from now (default: the next step).")
      .def(
          "apply_torque",
          [](PyWorld& w, const std::string& body, const py::handle& torque,
             std::optional<double> duration) {
            addLoad(w, body, LoadDesc::Kind::Torque, vec3Arg(torque, "torque"), py::none(),
                    duration);
          },
          py::arg("body"), py::arg("torque"), py::arg("duration") = py::none(),
          "Torque (N m, world frame) on a named body for `duration` seconds (default: one step).")
      .def(
          "apply_impulse",
          [](PyWorld& w, const std::string& body, const py::handle& impulse,
             const py::object& point) {
            addLoad(w, body, LoadDesc::Kind::Impulse, vec3Arg(impulse, "impulse"), point,
                    std::nullopt);
          },
          py::arg("body"), py::arg("impulse"), py::arg("point") = py::none(),
          "Impulse (N s, world frame) on a named body at a world point, applied at the next "
          "step.")
      .def("__repr__", [](const PyWorld& w) {
        return "<asperity.World t=" + std::to_string(w.world->time()) + " s, " +
               std::to_string(w.world->bodies().size()) + " bodies>";
      });
}

// The clock and the state arrays (assigning any of them restarts from that state).
void bindWorldState(py::class_<PyWorld>& world) {
  world
      .def_property_readonly(
          "time", [](const PyWorld& w) { return w.world->time(); }, "Simulated time (s).")
      .def_property_readonly(
          "step_count", [](const PyWorld& w) { return w.world->stepCount(); }, "Steps taken.")
      .def_property_readonly(
          "dt", [](const PyWorld& w) { return w.world->settings().dt; }, "Time step (s).")
      .def_property_readonly(
          "body_names",
          [](const PyWorld& w) {
            py::list names;
            for (const Body& b : w.world->bodies()) names.append(b.name);
            return names;
          },
          "Names of the bodies in scene order (the rows of the state arrays).")
      .def_property("positions", &positions, &setPositions,
                    "(B, 3) float64: origin of each body's frame as the scene wrote it (m). "
                    "Assigning any state array restarts from that state: the contact history "
                    "of earlier steps is forgotten, so worlds set to one state evolve alike.")
      .def_property("orientations", &orientations, &setOrientations,
                    "(B, 4) float64: unit quaternion w, x, y, z of each body's frame.")
      .def_property("linear_velocities", &linearVelocities, &setLinearVelocities,
                    "(B, 3) float64: velocity of each body frame's origin (m/s).")
      .def_property("angular_velocities", &angularVelocities, &setAngularVelocities,
                    "(B, 3) float64: angular velocity, world frame (rad/s).");
}

}  // namespace

void bindWorld(py::module_& m) {
  py::class_<PyWorld> world(
      m, "World",
      "A simulation world built from a scene (a path, a dict or an "
      "asperity.Scene).\n\nKeyword overrides match `asperity run`: sampler "
      "(constant, cone, cpu, gl), friction (coulomb, box, polygon), frame "
      "(world, body, auto, texture), directions N, patch_width w (m), "
      "patch_resolution R, threads (worker threads of a step, 0 = every "
      "core; the results are the same bits for any count). state: a checkpoint file "
      "(save_state, `asperity run --save-state`) to continue from, bit for "
      "bit.");
  // Construction, stepping and the state arrays.
  world
      .def(py::init(&makeWorld), py::arg("scene"), py::kw_only(), py::arg("sampler") = py::none(),
           py::arg("friction") = py::none(), py::arg("frame") = py::none(),
           py::arg("directions") = py::none(), py::arg("patch_width") = py::none(),
           py::arg("patch_resolution") = py::none(), py::arg("threads") = py::none(),
           py::arg("state") = py::none())
      .def("save_state", &saveState, py::arg("path"),
           "Writes the whole state (docs/checkpoints.md) to path, atomically: a world loaded "
           "from it steps bit for bit as this one would. Raises ValueError naming the file when "
           "it cannot be written.")
      .def("load_state", &loadState, py::arg("path"),
           "Restores a state that save_state (or `asperity run --save-state`) wrote for this "
           "scene, with the same overrides but any thread count. Raises ValueError naming the "
           "file and what is wrong (another scene, another sampler, another format, a truncated "
           "or corrupt file); FileNotFoundError when it does not exist. After an error, build "
           "the world anew.")
      .def(
          "step",
          [](PyWorld& w, int64_t n) {
            if (n < 0 || n > kMaxSteps)
              throwValue("step: n must be in 0.." + std::to_string(kMaxSteps) + ", got " +
                         std::to_string(n));
            // Other Python threads run while this world steps.
            py::gil_scoped_release release;
            runSteps(*w.world, n);
          },
          py::arg("n") = 1, "Advances the world by n steps of dt (the GIL is released).")
      .def(
          "prepare",
          [](PyWorld& w) {
            py::gil_scoped_release release;
            return w.world->prepare();
          },
          "Builds the collision objects and signed distance fields now rather than in the next "
          "step; returns the ms it took (0 when nothing changed since the last build).");
  bindWorldState(world);
  bindWorldActions(world);
}

}  // namespace asperity::python
