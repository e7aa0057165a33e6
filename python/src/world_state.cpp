// NumPy views of a world's state: read into fresh arrays without per-body Python objects,
// written back body by body after checking shape and finiteness.
#include <cmath>
#include <filesystem>

#include "asperity/world/state_file.hpp"
#include "world_state.hpp"

namespace asperity::python {
namespace {

// A C-contiguous float64 array of `cols` columns with one row per body; raises otherwise.
py::array_t<double> stateArg(const PyWorld& w, const py::handle& values, py::ssize_t cols,
                             const char* name) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  } catch (const py::error_already_set&) {
  }
  if (!a) throwType(std::string(name) + " must be an array of numbers");
  const auto bodies = static_cast<py::ssize_t>(w.world->bodies().size());
  if (a.ndim() != 2 || a.shape(0) != bodies || a.shape(1) != cols)
    throwValue(std::string(name) + " must have shape (" + std::to_string(bodies) + ", " +
               std::to_string(cols) + ")");
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.size(); ++i)
    if (!std::isfinite(p[i])) throwValue(std::string(name) + " must be finite");
  return a;
}

// Origin of the description frame: descriptionPose().position without the quaternion
// product it also forms (the same bits: p - R (q_c^-1 p_c) == p + R (-(q_c^-1 p_c))).
Vec3 frameOrigin(const Body& b, const Vec3& offset) {
  return b.pose.position - b.pose.rotation * offset;
}

// Velocity of the description frame's origin (the CSV's vx, vy, vz).
Vec3 frameVelocity(const Body& b, const Vec3& offset) {
  return b.linear_velocity + b.angular_velocity.cross(frameOrigin(b, offset) - b.pose.position);
}

// A new (B, cols) array filled row by row.
template <typename Fill>
py::array_t<double> table(const PyWorld& w, py::ssize_t cols, Fill fill) {
  const auto bodies = w.world->bodies();
  py::array_t<double> out({static_cast<py::ssize_t>(bodies.size()), cols});
  double* p = out.mutable_data();
  for (size_t i = 0; i < bodies.size(); ++i) {
    fill(bodies[i], w.origin_offsets[i], p);
    p += cols;
  }
  return out;
}

}  // namespace

BodyId PyWorld::bodyId(const std::string& name) const {
  const BodyId id = world->findBody(name);
  if (id != kNoBody) return id;
  std::string known;
  for (const Body& b : world->bodies()) known += (known.empty() ? "" : ", ") + b.name;
  throwValue("no body named '" + name + "' (bodies: " + known + ")");
}

py::array_t<double> positions(const PyWorld& w) {
  return table(w, 3, [](const Body& b, const Vec3& o, double* p) {
    const Vec3 x = frameOrigin(b, o);
    p[0] = x.x(), p[1] = x.y(), p[2] = x.z();
  });
}

py::array_t<double> orientations(const PyWorld& w) {
  return table(w, 4, [](const Body& b, const Vec3&, double* p) {
    const Quat q = b.descriptionPose().rotation;
    p[0] = q.w(), p[1] = q.x(), p[2] = q.y(), p[3] = q.z();
  });
}

py::array_t<double> linearVelocities(const PyWorld& w) {
  return table(w, 3, [](const Body& b, const Vec3& o, double* p) {
    const Vec3 v = frameVelocity(b, o);
    p[0] = v.x(), p[1] = v.y(), p[2] = v.z();
  });
}

py::array_t<double> angularVelocities(const PyWorld& w) {
  return table(w, 3, [](const Body& b, const Vec3&, double* p) {
    p[0] = b.angular_velocity.x(), p[1] = b.angular_velocity.y(), p[2] = b.angular_velocity.z();
  });
}

// Setting a state restarts from it: what earlier steps left behind (contact points, warm
// starts, kept samples) goes, so the world then evolves as any other restarted there.
namespace {
void restart(PyWorld& w) {
  w.world->forgetContactHistory();
}
}  // namespace

void setPositions(PyWorld& w, const py::handle& values) {
  const auto a = stateArg(w, values, 3, "positions");
  for (BodyId i = 0; i < w.world->bodies().size(); ++i) {
    // The description frame moves; the centre of mass follows through com_offset.
    Body& b = w.world->body(i);
    Transform pose = b.descriptionPose();
    pose.position = Vec3(a.at(i, 0), a.at(i, 1), a.at(i, 2));
    b.pose = pose * b.com_offset;
  }
  restart(w);
}

void setOrientations(PyWorld& w, const py::handle& values) {
  const auto a = stateArg(w, values, 4, "orientations");
  for (BodyId i = 0; i < w.world->bodies().size(); ++i) {
    const Quat q(a.at(i, 0), a.at(i, 1), a.at(i, 2), a.at(i, 3));
    if (!(q.norm() > 1e-12)) throwValue("orientations: row " + std::to_string(i) + " is zero");
  }
  for (BodyId i = 0; i < w.world->bodies().size(); ++i) {
    // Unit quaternions (w, x, y, z); the frame the scene wrote turns, the body follows.
    Body& b = w.world->body(i);
    Transform pose = b.descriptionPose();
    pose.rotation = Quat(a.at(i, 0), a.at(i, 1), a.at(i, 2), a.at(i, 3)).normalized();
    b.pose = pose * b.com_offset;
  }
  restart(w);
}

void setLinearVelocities(PyWorld& w, const py::handle& values) {
  const auto a = stateArg(w, values, 3, "linear_velocities");
  for (BodyId i = 0; i < w.world->bodies().size(); ++i) {
    // v_com = v_origin - w x (origin - com).
    Body& b = w.world->body(i);
    const Vec3 v(a.at(i, 0), a.at(i, 1), a.at(i, 2));
    b.linear_velocity =
        v - b.angular_velocity.cross(b.descriptionPose().position - b.pose.position);
  }
  restart(w);
}

void setAngularVelocities(PyWorld& w, const py::handle& values) {
  const auto a = stateArg(w, values, 3, "angular_velocities");
  for (BodyId i = 0; i < w.world->bodies().size(); ++i) {
    // The frame origin keeps its velocity: v_com follows the new angular velocity.
    Body& b = w.world->body(i);
    const Vec3 v_origin = frameVelocity(b, w.origin_offsets[i]);
    b.angular_velocity = Vec3(a.at(i, 0), a.at(i, 1), a.at(i, 2));
    b.linear_velocity =
        v_origin - b.angular_velocity.cross(b.descriptionPose().position - b.pose.position);
  }
  restart(w);
}

py::dict contacts(const PyWorld& w) {
  const std::vector<Contact>& cs = w.world->contacts();
  const auto n = static_cast<py::ssize_t>(cs.size());
  int directions = 0;
  for (const Contact& c : cs) directions = std::max(directions, c.mu.count);
  // One array per field, filled in one pass.
  py::array_t<int32_t> body_a(n), body_b(n), pixels(n);
  py::array_t<double> points({n, py::ssize_t{3}}), normals({n, py::ssize_t{3}});
  py::array_t<double> frames({n, py::ssize_t{3}, py::ssize_t{3}}), impulses({n, py::ssize_t{3}});
  py::array_t<double> phi(n);
  py::array_t<float> mu({n, static_cast<py::ssize_t>(directions)});
  py::array_t<bool> fallback(n);
  auto pa = body_a.mutable_unchecked<1>(), pb = body_b.mutable_unchecked<1>();
  auto px = pixels.mutable_unchecked<1>();
  auto pp = points.mutable_unchecked<2>(), pn = normals.mutable_unchecked<2>();
  auto pf = frames.mutable_unchecked<3>();
  auto pi = impulses.mutable_unchecked<2>();
  auto pphi = phi.mutable_unchecked<1>();
  auto pmu = mu.mutable_unchecked<2>();
  auto pfb = fallback.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const Contact& c = cs[static_cast<size_t>(i)];
    pa(i) = static_cast<int32_t>(c.body_a), pb(i) = static_cast<int32_t>(c.body_b);
    px(i) = c.covered_pixels;
    pphi(i) = c.phi;
    pfb(i) = c.fallback;
    // Frame rows t, b, n; impulses on A along them (N s).
    const double lambdas[3] = {c.lambda_t, c.lambda_b, c.lambda_n};
    for (int k = 0; k < 3; ++k) {
      pp(i, k) = c.point[k], pn(i, k) = c.normal[k];
      pf(i, 0, k) = c.t[k], pf(i, 1, k) = c.b[k], pf(i, 2, k) = c.normal[k];
      pi(i, k) = lambdas[k];
    }
    for (int k = 0; k < directions; ++k)
      pmu(i, k) = k < c.mu.count ? c.mu.mu[static_cast<size_t>(k)] : std::nanf("");
  }
  py::dict d;
  d["body_a"] = body_a, d["body_b"] = body_b, d["points"] = points, d["normals"] = normals;
  d["frames"] = frames, d["phi"] = phi, d["impulses"] = impulses, d["mu"] = mu;
  d["patch_pixels"] = pixels, d["fallback"] = fallback;
  return d;
}

static std::string pathArg(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

void saveState(const PyWorld& w, const py::handle& path) {
  const std::string file = pathArg(path);
  py::gil_scoped_release release;
  saveStateFile(*w.world, file, sceneStateId(w.scene));
}

void loadState(PyWorld& w, const py::handle& path) {
  const std::string file = pathArg(path);
  if (!std::filesystem::exists(file)) throwFileNotFound(file + ": no such file");
  py::gil_scoped_release release;
  loadStateFile(*w.world, file, sceneStateId(w.scene));
}

}  // namespace asperity::python
