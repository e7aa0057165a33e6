// asperity.load_scene and asperity.Scene: scene files and dicts, validated by the same parser
// as the CLI (errors name the JSON path), and written back as dicts.
#include <filesystem>
#include <fstream>

#include "asperity/error.hpp"
#include "bindings.hpp"

namespace asperity::python {
namespace {

namespace fs = std::filesystem;

// A scene file: validated by loadScene, its JSON kept for sweeps.
PyScene loadFile(const std::string& path) {
  if (!fs::is_regular_file(path)) throwFileNotFound(path + ": cannot open file");
  PyScene s;
  s.desc = loadScene(path);
  std::ifstream in(path);
  s.json = nlohmann::json::parse(in);
  return s;
}

// A dict: relative file names resolve against base_dir (default: the current folder).
PyScene loadDict(const py::dict& dict, const std::string& base_dir) {
  PyScene s;
  s.json = toJson(dict);
  const std::string name = base_dir.empty() ? "<dict>" : (fs::path(base_dir) / "<dict>").string();
  s.desc = parseScene(s.json, name);
  return s;
}

}  // namespace

PyScene sceneFrom(const py::handle& scene) {
  if (py::isinstance<PyScene>(scene)) return scene.cast<PyScene>();
  if (py::isinstance<py::dict>(scene)) return loadDict(scene.cast<py::dict>(), "");
  if (py::isinstance<py::str>(scene) || py::hasattr(scene, "__fspath__"))
    return loadFile(py::str(py::module_::import("os").attr("fspath")(scene)).cast<std::string>());
  throwType("scene must be a path, a dict or an asperity.Scene, got " +
            py::str(py::type::of(scene).attr("__name__")).cast<std::string>());
}

void bindScene(py::module_& m) {
  py::class_<PyScene>(m, "Scene",
                      "A validated scene (docs/scene-format.md): load it with load_scene, "
                      "build worlds from it, write it back with to_dict.")
      .def(
          "to_dict", [](const PyScene& s) { return fromJson(sceneToJson(s.desc)); },
          "The scene as a dict with every setting written out (the JSON of a scene file).")
      .def(
          "save", [](const PyScene& s, const std::string& path) { saveScene(s.desc, path); },
          py::arg("path"), "Writes the scene as a JSON file (relative file names kept correct).")
      .def_property_readonly(
          "body_names",
          [](const PyScene& s) {
            py::list names;
            for (const BodyDesc& b : s.desc.bodies) names.append(b.name);
            return names;
          },
          "Names of the bodies, in scene order.")
      .def_property_readonly(
          "source_file", [](const PyScene& s) { return s.desc.source_file; },
          "The file the scene came from ('' for a dict).")
      .def_property_readonly(
          "friction_provider", [](const PyScene& s) { return s.desc.friction_provider; },
          "The scene's friction provider name (\"friction_provider\" in its settings).")
      .def_property_readonly(
          "sampler", [](const PyScene& s) { return s.desc.friction_provider; },
          "The scene's friction provider name (the same as friction_provider).")
      .def_property_readonly(
          "dt", [](const PyScene& s) { return s.desc.settings.dt; }, "Time step (s).")
      .def("__repr__", [](const PyScene& s) {
        return "<asperity.Scene '" + s.desc.source_file + "' with " +
               std::to_string(s.desc.bodies.size()) + " bodies>";
      });

  m.def(
      "load_scene",
      [](const py::handle& scene, const std::string& base_dir) {
        PyScene s = py::isinstance<py::dict>(scene) ? loadDict(scene.cast<py::dict>(), base_dir)
                                                    : sceneFrom(scene);
        // Deprecated keys are warned about here, once: worlds built from `s` do not repeat it.
        for (const std::string& warning : s.desc.warnings) warn(warning);
        s.desc.warnings.clear();
        return s;
      },
      py::arg("path_or_dict"), py::arg("base_dir") = "",
      "Loads a scene from a JSON file (str or os.PathLike) or a dict of the same structure.\n\n"
      "Relative file names in a dict resolve against base_dir (default: the current folder).\n"
      "Raises FileNotFoundError for a missing file, ValueError naming the JSON path of a bad\n"
      "value (the CLI's message), TypeError for something that is not a path or a dict.\n"
      "Deprecated keys are read with a UserWarning naming the key to use instead.");
}

}  // namespace asperity::python
