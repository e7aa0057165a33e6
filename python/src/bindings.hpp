// Shared pieces of the Python bindings: the parts each file registers, JSON <-> Python
// conversion through Python's json module, and the errors Python sees.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <string>

#include "asperity/scene/scene.hpp"

namespace asperity::python {

namespace py = pybind11;

// A loaded scene: the validated description and the JSON it came from (sweeps vary the JSON).
struct PyScene {
  SceneDesc desc;
  nlohmann::json json;
};

// Each file's part of the module.
void bindScene(py::module_& m);
void bindWorld(py::module_& m);
void bindTexture(py::module_& m);
void bindSweep(py::module_& m);
void bindTribometer(py::module_& m);
void bindBatch(py::module_& m);
void bindRender(py::module_& m);

// Python object (dict, list, numbers, strings) to JSON and back.
nlohmann::json toJson(const py::handle& object);
py::object fromJson(const nlohmann::json& json);

// Raises FileNotFoundError with `message` (the CLI's words).
[[noreturn]] void throwFileNotFound(const std::string& message);
// Raises TypeError / ValueError with `message`.
[[noreturn]] void throwType(const std::string& message);
[[noreturn]] void throwValue(const std::string& message);

// A scene from a path, a dict or a loaded Scene. Throws FileNotFoundError for a missing file.
PyScene sceneFrom(const py::handle& scene);

// Issues a library warning (Diagnostics) as warnings.warn(message, UserWarning); raises when a
// warnings filter turns it into an error.
void warn(const std::string& message);

}  // namespace asperity::python
