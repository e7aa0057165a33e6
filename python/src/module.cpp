// The extension module asperity._asperity: errors translated to Python's, then each part.
#include <filesystem>

#include "asperity/error.hpp"
#include "bindings.hpp"

namespace asperity::python {

nlohmann::json toJson(const py::handle& object) {
  // Python's json module writes exactly the JSON a scene file would hold.
  const py::object dumps = py::module_::import("json").attr("dumps");
  std::string text;
  try {
    text = dumps(object, py::arg("allow_nan") = false).cast<std::string>();
  } catch (const py::error_already_set& e) {
    throwType(std::string("scene dict is not JSON data: ") + e.what());
  }
  return nlohmann::json::parse(text);
}

py::object fromJson(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

void warn(const std::string& message) {
  // Called from a world's diagnostics sink too, which may run with the GIL released.
  const py::gil_scoped_acquire gil;
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

void throwFileNotFound(const std::string& message) {
  PyErr_SetString(PyExc_FileNotFoundError, message.c_str());
  throw py::error_already_set();
}

void throwType(const std::string& message) {
  throw py::type_error(message);
}

void throwValue(const std::string& message) {
  throw py::value_error(message);
}

}  // namespace asperity::python

PYBIND11_MODULE(_asperity, m) {
  namespace py = pybind11;
  using namespace asperity::python;
  m.doc() = "Asperity: rigid bodies whose friction comes from the normal maps of their surfaces.";
  // The library's one exception type carries a one-line message naming the culprit.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const asperity::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bindScene(m);
  bindWorld(m);
  bindTexture(m);
  bindSweep(m);
  bindTribometer(m);
  bindBatch(m);
  bindRender(m);
}
