// The Python World: a world built from a scene, and the NumPy views of its state.
#pragma once

#include <memory>

#include "bindings.hpp"

namespace asperity::python {

struct PyWorld {
  SceneDesc scene;
  std::unique_ptr<World> world;
  // Per body, the description frame's origin in the body (centre of mass) frame, q_c^-1 p_c:
  // constant, so reading positions costs one rotation per body.
  std::vector<Vec3> origin_offsets;

  // The body with this name; raises ValueError naming it and listing the known ones.
  BodyId bodyId(const std::string& name) const;
};

// State arrays (B = every body, scene order; the frame the scene wrote, as the CLI's CSV).
py::array_t<double> positions(const PyWorld& w);
py::array_t<double> orientations(const PyWorld& w);  // w, x, y, z
py::array_t<double> linearVelocities(const PyWorld& w);
py::array_t<double> angularVelocities(const PyWorld& w);
// Setters: a (B, 3) or (B, 4) array of finite numbers; raise ValueError / TypeError.
void setPositions(PyWorld& w, const py::handle& values);
void setOrientations(PyWorld& w, const py::handle& values);
void setLinearVelocities(PyWorld& w, const py::handle& values);
void setAngularVelocities(PyWorld& w, const py::handle& values);
// Checkpoints (asperity/world/state_file.hpp), named by a str or os.PathLike.
void saveState(const PyWorld& w, const py::handle& path);
void loadState(PyWorld& w, const py::handle& path);

// Contacts of the last step as a dict of arrays.
py::dict contacts(const PyWorld& w);

// One frame through a headless OpenGL context (render_bindings.cpp).
py::array_t<uint8_t> renderWorld(const PyWorld& w, int width, int height, const py::object& camera,
                                 int samples);

}  // namespace asperity::python
