// World.render: one frame of the world's current state through a headless EGL context (the
// renderer of `asperity render`), as an (H, W, 3) uint8 array.
#include "asperity/error.hpp"
#include "world_state.hpp"
#ifdef ASPERITY_HAVE_RENDER
#include "asperity/gl/context.hpp"
#include "asperity/render/renderer.hpp"
#include "asperity/render/world_view.hpp"
#endif

namespace asperity::python {

py::array_t<uint8_t> renderWorld(const PyWorld& w, int width, int height, const py::object& camera,
                                 int samples) {
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throwValue("render: width and height must be in 16..8192, got " + std::to_string(width) +
               " x " + std::to_string(height));
  if (samples < 1 || samples > 16) throwValue("render: samples must be in 1..16");
#ifdef ASPERITY_HAVE_RENDER
  // camera: six numbers eye, target (as --camera), else the scene's, else one framing bodies.
  std::optional<render::Camera> cam;
  if (!camera.is_none()) {
    const auto a = py::array_t<double, py::array::forcecast>::ensure(camera);
    if (!a || a.ndim() != 1 || a.shape(0) != 6)
      throwType("render: camera must be 6 numbers: eye x, y, z, target x, y, z (m)");
    std::string text;
    for (py::ssize_t i = 0; i < 6; ++i) text += (i ? "," : "") + std::to_string(a.at(i));
    cam = render::parseCamera(text, "render: camera");
  }
  render::Image image;
  try {
    // A context of its own for this frame; failing to get one is a RuntimeError.
    gl::GlContext context;
    render::RendererOptions ro;
    ro.width = width;
    ro.height = height;
    ro.samples = samples;
    render::Renderer renderer(ro);
    render::WorldView view;
    if (!cam)
      cam = w.scene.camera
                ? render::lookAt(w.scene.camera->eye, w.scene.camera->target, w.scene.camera->fov_y)
                : view.defaultCamera(*w.world, double(width) / height);
    // The bodies only, as `asperity render` draws them by default (--layers none).
    render::WorldViewOptions options;
    options.debug.layers = 0;
    render::RenderScene frame;
    view.update(*w.world, options, frame);
    renderer.render(frame, *cam);
    image = renderer.readPixels();
  } catch (const Error& e) {
    throw std::runtime_error(std::string("render: no OpenGL context: ") + e.what());
  }
  py::array_t<uint8_t> out({static_cast<py::ssize_t>(image.height),
                            static_cast<py::ssize_t>(image.width), py::ssize_t{3}});
  std::copy(image.rgb.begin(), image.rgb.end(), out.mutable_data());
  return out;
#else
  (void)w, (void)camera;
  throw std::runtime_error("render: this asperity was built without OpenGL (ASPERITY_WITH_GL=OFF)");
#endif
}

void bindRender(py::module_& m) {
  py::type world = m.attr("World");
  world.attr("render") = py::cpp_function(
      &renderWorld, py::is_method(world), py::name("render"), py::arg("width") = 640,
      py::arg("height") = 480, py::kw_only(), py::arg("camera") = py::none(),
      py::arg("samples") = 4,
      "One frame of the current state as an (H, W, 3) uint8 array, rows top to bottom, through "
      "a headless OpenGL context. camera: (eye x, y, z, target x, y, z) in m; default the "
      "scene's camera, else one framing the bodies. RuntimeError where no OpenGL context can "
      "be made.");
}

}  // namespace asperity::python
