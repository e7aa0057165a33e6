// Asperity's friction inside MuJoCo's step (asperity/engines/mujoco.hpp): MuJoCo's stages in
// its own order, with Asperity's frames and coefficients written into the contacts between
// mj_collision and mj_makeConstraint (mujoco #717; SPEC 11).
#include "asperity/engines/mujoco.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "engines/mujoco/mujoco_geoms.hpp"
#include "math/stopwatch.hpp"

namespace asperity {

using mujoco_detail::GeomObjects;

void mujoco_detail::checkMujocoVersion(int library, int header, const std::string& library_text) {
  if (library / 10 != 22 || library != header) {
    throw Error("MuJoCo adapter: written for MuJoCo 2.2 (built with headers " +
                std::to_string(header) + "), but the library is " + library_text + " (" +
                std::to_string(library) + ")");
  }
}

struct MujocoFriction::Impl {
  const mjModel* model = nullptr;
  ContactFriction friction;
  GeomObjects geoms;
  std::vector<EngineContact> contacts;  // this step's textured contacts
  std::vector<int> contact_index;       // their index in d->contact
  std::vector<int> state_stamp;         // per geom: the step whose state it holds
  int stamp = 0;
  bool velocities_ready = false;  // mj_comVel ran for this edit
  std::span<const ContactFrictionResult> results;
  MujocoFrictionStats stats;

  Impl(const mjModel* m, const EngineSurfaces& surfaces) : model(m), friction(surfaces.settings) {
    mujoco_detail::checkMujocoVersion(mj_version(), mjVERSION_HEADER, mj_versionString());
    geoms = mujoco_detail::registerGeoms(m, surfaces, friction);
    state_stamp.assign(static_cast<size_t>(m->ngeom), -1);
  }
  void setState(mjData* d, int geom);
  void collect(mjData* d);
  void writeBack(mjData* d) const;
  void apply(mjData* d);
  void positionStage(mjData* d);
};

void MujocoFriction::Impl::setState(mjData* d, int geom) {
  int& seen = state_stamp[static_cast<size_t>(geom)];
  if (seen == stamp) return;
  seen = stamp;
  // Geom velocities need cvel at this step's positions (mj_fwdVelocity computes it again).
  if (!velocities_ready) mj_comVel(model, d);
  velocities_ready = true;
  friction.setState(geoms.object[static_cast<size_t>(geom)],
                    mujoco_detail::geomState(model, d, geom));
}

void MujocoFriction::Impl::collect(mjData* d) {
  contacts.clear();
  contact_index.clear();
  ++stamp;
  velocities_ready = false;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const auto g1 = static_cast<size_t>(c.geom1), g2 = static_cast<size_t>(c.geom2);
    if (c.exclude != 0 || (!geoms.textured[g1] && !geoms.textured[g2])) continue;
    // A textured geom against one Asperity cannot shape keeps MuJoCo's friction.
    if (geoms.object[g1] == kNoObject || geoms.object[g2] == kNoObject) {
      ++stats.unsupported;
      continue;
    }
    setState(d, c.geom1);
    setState(d, c.geom2);
    // MuJoCo's normal points from geom1 to geom2: geom2 is A, geom1 is B (SPEC 1).
    EngineContact e;
    e.object_a = geoms.object[g2];
    e.object_b = geoms.object[g1];
    e.point = Vec3(c.pos[0], c.pos[1], c.pos[2]);
    e.normal = Vec3(c.frame[0], c.frame[1], c.frame[2]);
    e.depth = mujoco_detail::contactDepth(model, c);
    contacts.push_back(e);
    contact_index.push_back(i);
  }
}

void MujocoFriction::Impl::writeBack(mjData* d) const {
  for (size_t k = 0; k < results.size(); ++k) {
    const ContactFrictionResult& r = results[k];
    mjContact& c = d->contact[contact_index[k]];
    // Asperity's tangents in rows 3-8 where the axes differ; else MuJoCo's frame stays.
    if (r.symmetric_t != r.symmetric_b) {
      std::copy(r.t.data(), r.t.data() + 3, c.frame + 3);
      std::copy(r.b.data(), r.b.data() + 3, c.frame + 6);
    }
    // The pair's own coefficients are mu0 (Eq. 7); condim 3 reads friction[0] and [1].
    c.friction[0] += r.symmetric_t;
    c.friction[1] += r.symmetric_b;
  }
}

void MujocoFriction::Impl::apply(mjData* d) {
  Stopwatch clock;
  stats = {};
  stats.contacts = d->ncon;
  collect(d);
  stats.textured = static_cast<int>(contacts.size());
  results = friction.compute(contacts);
  stats.compute_ms = friction.lastComputeMs();
  writeBack(d);
  stats.friction_ms = clock.total();
}

void MujocoFriction::Impl::positionStage(mjData* d) {
  const mjModel* m = model;
  // mj_fwdPosition's parts in MuJoCo 2.2's order, the edit after collision.
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_camlight(m, d);
  mj_tendon(m, d);
  mj_crb(m, d);
  mj_factorM(m, d);
  mj_collision(m, d);
  apply(d);
  mj_makeConstraint(m, d);
  mj_transmission(m, d);
  mj_projectConstraint(m, d);
  // What mj_forward does after the position stage itself.
  mj_sensorPos(m, d);
  if (m->opt.enableflags & mjENBL_ENERGY) mj_energyPos(m, d);
}

MujocoFriction::MujocoFriction(const mjModel* model, const EngineSurfaces& surfaces)
    : impl_(std::make_unique<Impl>(model, surfaces)) {}

MujocoFriction::MujocoFriction(const mjModel* model, const std::string& surfaces_file)
    : MujocoFriction(model, loadEngineSurfaces(surfaces_file)) {}

MujocoFriction::~MujocoFriction() = default;

void MujocoFriction::applyToContacts(mjData* d) {
  impl_->apply(d);
}

void MujocoFriction::forward(mjData* d) {
  Stopwatch clock;
  impl_->positionStage(d);
  // Velocity, actuation, acceleration and MuJoCo's constraint solver, as mj_forward.
  mj_forwardSkip(impl_->model, d, mjSTAGE_POS, 0);
  impl_->stats.step_ms = clock.total();
}

void MujocoFriction::step(mjData* d) {
  const mjModel* m = impl_->model;
  if (m->opt.integrator != mjINT_EULER)
    throw Error(
        "MuJoCo friction: the model's integrator must be Euler (RK4's and the implicit "
        "integrator's inner stages would run MuJoCo's collision again)");
  Stopwatch clock;
  // mj_step's order: checks, forward, check, the integrator.
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  forward(d);
  mj_checkAcc(m, d);
  if (m->opt.enableflags & mjENBL_FWDINV) mj_compareFwdInv(m, d);
  mj_Euler(m, d);
  impl_->stats.step_ms = clock.total();
}

std::span<const ContactFrictionResult> MujocoFriction::lastResults() const {
  return impl_->results;
}

const MujocoFrictionStats& MujocoFriction::lastStats() const {
  return impl_->stats;
}

ContactFriction& MujocoFriction::friction() {
  return impl_->friction;
}

}  // namespace asperity
