// An Asperity scene rebuilt in ODE (ode_scene.hpp).
#include "ode_scene.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>

#include "asperity/error.hpp"
#include "common/engine_setups.hpp"

namespace asperity::ode_scene {

namespace {

constexpr int kMaxContactsPerPair = 8;

// ODE's per-thread data, once per process (ODE itself keeps it global).
void initOde() {
  static const bool done = [] {
    dInitODE2(0);
    std::atexit(dCloseODE);
    return dAllocateODEDataForThread(dAllocateMaskAll) != 0;
  }();
  if (!done) throw Error("ODE could not allocate its data for this thread");
}

// A geom for a shape (no plane: those are made in world coordinates).
dGeomID shapeGeom(dSpaceID space, const Shape& s, const std::string& body) {
  switch (s.type) {
    case ShapeType::Box:
      return dCreateBox(space, 2 * s.half_extents.x(), 2 * s.half_extents.y(),
                        2 * s.half_extents.z());
    case ShapeType::Sphere:
      return dCreateSphere(space, s.radius);
    case ShapeType::Capsule:
      return dCreateCapsule(space, s.radius, 2 * s.half_height);
    case ShapeType::Cylinder:
      return dCreateCylinder(space, s.radius, 2 * s.half_height);
    default:
      throw Error("body \"" + body +
                  "\": ODE's side takes boxes, spheres, capsules, cylinders "
                  "and planes (planes on static bodies)");
  }
}

// The mass of a shape of uniform density, along the geom's own axes (z for capsules and
// cylinders).
dMass shapeMass(const Shape& s) {
  dMass m;
  const Vec3 size = 2 * s.half_extents;
  if (s.type == ShapeType::Box) dMassSetBox(&m, s.density, size.x(), size.y(), size.z());
  if (s.type == ShapeType::Sphere) dMassSetSphere(&m, s.density, s.radius);
  if (s.type == ShapeType::Capsule) dMassSetCapsule(&m, s.density, 3, s.radius, 2 * s.half_height);
  if (s.type == ShapeType::Cylinder)
    dMassSetCylinder(&m, s.density, 3, s.radius, 2 * s.half_height);
  return m;
}

void setPose(dGeomID geom, const Transform& pose) {
  const Vec3& p = pose.position;
  const Quat& q = pose.rotation;
  const dQuaternion wxyz = {q.w(), q.x(), q.y(), q.z()};
  dGeomSetPosition(geom, p.x(), p.y(), p.z());
  dGeomSetQuaternion(geom, wxyz);
}

}  // namespace

OdeScene::OdeScene(const SceneDesc& scene, const OdeOptions& options)
    : dt_(scene.settings.dt), mu0_(scene.settings.friction.mu0) {
  if (!scene.joints.empty() || !scene.springs.empty() || !scene.loads.empty())
    throw Error("ODE's side takes no joints, springs or loads");
  initOde();
  // QuickStep shuffles its rows with ODE's one random generator: seed it, so that every run of
  // a scene is the same.
  dRandSetSeed(0);
  // World and contacts as the peers' benchmark tunes them.
  world_ = dWorldCreate();
  const Vec3& g = scene.settings.gravity;
  dWorldSetGravity(world_, g.x(), g.y(), g.z());
  dWorldSetQuickStepNumIterations(world_, 20);
  dWorldSetERP(world_, 0.5);
  dWorldSetCFM(world_, 1e-5);
  space_ = dHashSpaceCreate(nullptr);
  contacts_ = dJointGroupCreate(0);
  for (const BodyDesc& b : scene.bodies) addBody(b, options);
}

OdeScene::~OdeScene() {
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(space_);
  dWorldDestroy(world_);
}

void OdeScene::addBody(const BodyDesc& b, const OdeOptions& options) {
  if (b.shapes.size() != 1)
    throw Error("body \"" + b.name + "\": ODE's side takes one shape per body");
  const Shape& s = b.shapes[0];
  const Transform pose = b.pose * s.local;
  dGeomID geom = nullptr;
  if (s.type == ShapeType::Plane) {
    // n . x = d in world coordinates.
    if (b.type != BodyType::Static) throw Error("body \"" + b.name + "\": a plane must be static");
    const Vec3 n = pose.rotation * s.plane_normal;
    geom = dCreatePlane(space_, n.x(), n.y(), n.z(), s.plane_offset + n.dot(pose.position));
  } else {
    geom = shapeGeom(space_, s, b.name);
    setPose(geom, pose);
  }
  // A dynamic body at the shape's pose, launched with the body's velocities.
  if (b.type == BodyType::Dynamic) {
    dBodyID body = dBodyCreate(world_);
    const dMass mass = shapeMass(s);
    dBodySetMass(body, &mass);
    const dQuaternion q = {pose.rotation.w(), pose.rotation.x(), pose.rotation.y(),
                           pose.rotation.z()};
    dBodySetPosition(body, pose.position.x(), pose.position.y(), pose.position.z());
    dBodySetQuaternion(body, q);
    dGeomSetBody(geom, body);
    const Vec3 v = b.linear_velocity + b.angular_velocity.cross(pose.position - b.pose.position);
    dBodySetLinearVel(body, v.x(), v.y(), v.z());
    dBodySetAngularVel(body, b.angular_velocity.x(), b.angular_velocity.y(),
                       b.angular_velocity.z());
    if (options.translation_only) dBodySetMaxAngularSpeed(body, 0);
    bodies_.emplace_back(b.name, body);
  }
  names_.push_back(b.name);
  dGeomSetData(geom, const_cast<char*>(names_.back().c_str()));
  geoms_.push_back(geom);
}

void OdeScene::registerGeoms(OdeFriction& friction) const {
  for (dGeomID geom : geoms_) friction.addGeom(geom);
}

void OdeScene::nearCallback(void* data, dGeomID o1, dGeomID o2) {
  auto* self = static_cast<OdeScene*>(data);
  dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  if (b1 == nullptr && b2 == nullptr) return;
  // The callback's own surface: Coulomb friction mu0 (Asperity adds to it).
  dContact c[kMaxContactsPerPair];
  const int n = dCollide(o1, o2, kMaxContactsPerPair, &c[0].geom, sizeof(dContact));
  for (int i = 0; i < n; ++i) {
    c[i].surface = dSurfaceParameters{};
    c[i].surface.mode = dContactApprox1;
    c[i].surface.mu = self->mu0_;
  }
  if (self->friction_ != nullptr) {
    self->friction_->collide(c, n);
    return;
  }
  for (int i = 0; i < n; ++i)
    dJointAttach(dJointCreateContact(self->world_, self->contacts_, &c[i]), b1, b2);
}

void OdeScene::step(OdeFriction* friction) {
  friction_ = friction;
  dSpaceCollide(space_, this, &nearCallback);
  // With Asperity: the step's contacts get their friction in one batch, then their joints.
  if (friction != nullptr) friction->createJoints(world_, contacts_);
  friction_ = nullptr;
  dWorldQuickStep(world_, dt_);
  dJointGroupEmpty(contacts_);
}

std::map<std::string, Vec3> OdeScene::positions() const {
  std::map<std::string, Vec3> out;
  for (const auto& [name, body] : bodies_) {
    const dReal* p = dBodyGetPosition(body);
    out[name] = Vec3(p[0], p[1], p[2]);
  }
  return out;
}

std::vector<double> OdeScene::state() const {
  std::vector<double> out;
  for (const auto& entry : bodies_) {
    const dReal* p = dBodyGetPosition(entry.second);
    const dReal* q = dBodyGetQuaternion(entry.second);
    const dReal* v = dBodyGetLinearVel(entry.second);
    const dReal* w = dBodyGetAngularVel(entry.second);
    out.insert(out.end(), {p[0], p[1], p[2], q[0], q[1], q[2], q[3]});
    out.insert(out.end(), {v[0], v[1], v[2], w[0], w[1], w[2]});
  }
  return out;
}

void OdeScene::restore(const std::vector<double>& state) {
  const double* s = state.data();
  for (const auto& entry : bodies_) {
    const dQuaternion q = {s[3], s[4], s[5], s[6]};
    dBodySetPosition(entry.second, s[0], s[1], s[2]);
    dBodySetQuaternion(entry.second, q);
    dBodySetLinearVel(entry.second, s[7], s[8], s[9]);
    dBodySetAngularVel(entry.second, s[10], s[11], s[12]);
    s += 13;
  }
}

RunResult run(const SceneDesc& scene, double seconds, bool with_asperity,
              const OdeOptions& options) {
  OdeScene ode(scene, options);
  std::unique_ptr<OdeFriction> friction;
  if (with_asperity) {
    friction = std::make_unique<OdeFriction>(
        parseEngineSurfaces(engine_setups::surfacesFile(scene), scene.source_file));
    ode.registerGeoms(*friction);
  }
  // Steps of dt, with or without Asperity's friction.
  RunResult out;
  const auto steps = std::llround(seconds / ode.dt());
  for (long long i = 0; i < steps; ++i) {
    ode.step(friction.get());
    const std::vector<double> state = ode.state();
    out.trajectory.insert(out.trajectory.end(), state.begin(), state.end());
  }
  if (friction) out.stats = friction->lastStats();
  out.positions = ode.positions();
  return out;
}

}  // namespace asperity::ode_scene
