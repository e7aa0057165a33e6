// Asperity's friction inside ODE's step (asperity/engines/ode.hpp): the near callback hands
// each pair's contacts over, and one batch per step writes Asperity's fdir1, mu and mu2 into
// them before their contact joints are made (SPEC 11).
#include "asperity/engines/ode.hpp"

#include <unordered_map>
#include <vector>

#include "asperity/error.hpp"
#include "engines/ode/ode_geoms.hpp"
#include "math/stopwatch.hpp"

namespace asperity {

struct OdeFriction::Impl {
  EngineSurfaces surfaces;
  ContactFriction friction;
  std::unordered_map<dGeomID, ObjectId> objects;
  std::vector<dGeomID> geom_of;   // per object
  std::vector<uint8_t> textured;  // per object
  std::vector<int> state_stamp;   // per object: the step whose state it holds
  int stamp = 0;
  bool names_checked = false;
  std::vector<dContact> kept;      // handed over since the last finish()
  std::vector<dContact> finished;  // what the last finish() returned
  std::vector<EngineContact> contacts;
  std::vector<size_t> contact_index;  // into `finished`
  std::span<const ContactFrictionResult> results;
  OdeFrictionStats stats;

  explicit Impl(EngineSurfaces s) : surfaces(std::move(s)), friction(surfaces.settings) {}
  ObjectId objectOf(dGeomID geom) const;
  void setState(ObjectId id);
  void collect();
  void writeBack();
};

ObjectId OdeFriction::Impl::objectOf(dGeomID geom) const {
  const auto it = objects.find(geom);
  return it == objects.end() ? kNoObject : it->second;
}

void OdeFriction::Impl::setState(ObjectId id) {
  if (state_stamp[id] == stamp) return;
  state_stamp[id] = stamp;
  friction.setState(id, ode_detail::geomState(geom_of[id]));
}

void OdeFriction::Impl::collect() {
  contacts.clear();
  contact_index.clear();
  ++stamp;
  for (size_t i = 0; i < finished.size(); ++i) {
    const dContactGeom& g = finished[i].geom;
    const ObjectId a = objectOf(g.g1), b = objectOf(g.g2);
    const bool any_texture = (a != kNoObject && textured[a]) || (b != kNoObject && textured[b]);
    if (!any_texture) continue;
    // A textured geom against one not registered keeps the callback's surface.
    if (a == kNoObject || b == kNoObject) {
      ++stats.unsupported;
      continue;
    }
    setState(a);
    setState(b);
    // ODE's normal points from g2 into g1: g1 is A, g2 is B (SPEC 1).
    EngineContact e;
    e.object_a = a;
    e.object_b = b;
    e.point = Vec3(g.pos[0], g.pos[1], g.pos[2]);
    e.normal = Vec3(g.normal[0], g.normal[1], g.normal[2]).normalized();
    // ODE puts the point on one of the two surfaces (which one depends on the collider):
    // twice the overlap, centred on it, keeps both inside the patch's depth clip (SPEC 3).
    e.depth = 2 * std::max(dReal(0), g.depth);
    contacts.push_back(e);
    contact_index.push_back(i);
  }
}

void OdeFriction::Impl::writeBack() {
  for (size_t k = 0; k < results.size(); ++k) {
    const ContactFrictionResult& r = results[k];
    dContact& c = finished[contact_index[k]];
    dSurfaceParameters& s = c.surface;
    // The callback's coefficients are mu0 (Eq. 7): mu along fdir1, mu2 (or mu) across.
    const dReal base_b = (s.mode & dContactMu2) ? s.mu2 : s.mu;
    s.mu += r.symmetric_t;
    if (r.symmetric_t == r.symmetric_b) {
      // Equal axes: ODE's own directions stay.
      if (s.mode & dContactMu2) s.mu2 += r.symmetric_b;
      continue;
    }
    s.mode |= dContactMu2 | dContactFDir1;
    s.mu2 = base_b + r.symmetric_b;
    for (int i = 0; i < 3; ++i) c.fdir1[i] = r.t[i];
    c.fdir1[3] = 0;
  }
}

OdeFriction::OdeFriction(const EngineSurfaces& surfaces)
    : impl_(std::make_unique<Impl>(surfaces)) {}

OdeFriction::OdeFriction(const std::string& surfaces_file)
    : OdeFriction(loadEngineSurfaces(surfaces_file)) {}

OdeFriction::~OdeFriction() = default;

ObjectId OdeFriction::addGeom(dGeomID geom, const std::string& name) {
  Impl& m = *impl_;
  const std::string what = "ODE friction: geom \"" + name + "\"";
  if (name.empty()) throw Error("ODE friction: a geom needs a name");
  if (m.objects.count(geom)) throw Error(what + " is registered already");
  std::optional<Shape> shape = ode_detail::geomShape(geom);
  if (!shape)
    throw Error(what + " is not a plane, sphere, capsule, cylinder or box (class " +
                std::to_string(dGeomGetClass(geom)) + ")");
  // Without a surface of its name the geom takes part flat (it adds nothing).
  const Surface* surface = m.surfaces.find(name);
  if (surface != nullptr) shape->surface = *surface;
  const ObjectId id = m.friction.addObject({name, {*shape}, Vec3::Zero()});
  m.objects.emplace(geom, id);
  m.geom_of.push_back(geom);
  m.textured.push_back(surface != nullptr);
  m.state_stamp.push_back(-1);
  return id;
}

ObjectId OdeFriction::addGeom(dGeomID geom) {
  const auto* name = static_cast<const char*>(dGeomGetData(geom));
  if (name == nullptr)
    throw Error(
        "ODE friction: a geom without user data has no name (set one with "
        "dGeomSetData(geom, (void*)\"name\"))");
  return addGeom(geom, name);
}

void OdeFriction::checkNames() const {
  for (const EngineSurface& e : impl_->surfaces.surfaces)
    if (impl_->friction.findObject(e.name) == kNoObject)
      impl_->surfaces.failAt(e.name,
                             "no geom is registered as \"" + e.name + "\" (OdeFriction::addGeom)");
}

void OdeFriction::collide(const dContact* contacts, int count) {
  impl_->kept.insert(impl_->kept.end(), contacts, contacts + count);
}

std::span<dContact> OdeFriction::finish() {
  Impl& m = *impl_;
  if (!m.names_checked) checkNames();
  m.names_checked = true;
  Stopwatch clock;
  // This step's contacts move to `finished`; the next collide() starts the next step.
  m.finished.swap(m.kept);
  m.kept.clear();
  m.stats = {};
  m.stats.contacts = static_cast<int>(m.finished.size());
  m.collect();
  m.stats.textured = static_cast<int>(m.contacts.size());
  m.results = m.friction.compute(m.contacts);
  m.stats.compute_ms = m.friction.lastComputeMs();
  m.writeBack();
  m.stats.friction_ms = clock.total();
  return m.finished;
}

void OdeFriction::createJoints(dWorldID world, dJointGroupID group) {
  for (const dContact& c : finish()) {
    const dJointID joint = dJointCreateContact(world, group, &c);
    dJointAttach(joint, dGeomGetBody(c.geom.g1), dGeomGetBody(c.geom.g2));
  }
}

std::span<const ContactFrictionResult> OdeFriction::lastResults() const {
  return impl_->results;
}

const OdeFrictionStats& OdeFriction::lastStats() const {
  return impl_->stats;
}

ContactFriction& OdeFriction::friction() {
  return impl_->friction;
}

}  // namespace asperity
