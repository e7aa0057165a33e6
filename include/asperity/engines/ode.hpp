// Asperity's friction inside ODE 0.16 (target asperity_ode, built when libode-dev is found;
// docs/engines.md). Geoms are registered under names that a surfaces file (asperity/engines/
// engine_surfaces.hpp) gives surfaces to; the near callback hands each pair's contacts from
// dCollide over, and after dSpaceCollide every contact of the step gets, in one batch,
// Asperity's first friction direction (fdir1 with dContactFDir1) and coefficients (mu, and mu2
// with dContactMu2) before its contact joint is made:
//
//   void near(void* data, dGeomID o1, dGeomID o2) {
//     dContact c[8];
//     const int n = dCollide(o1, o2, 8, &c[0].geom, sizeof(dContact));
//     for (int i = 0; i < n; ++i) c[i].surface = my_surface;  // mu = mu0, mode as you like
//     static_cast<asperity::OdeFriction*>(data)->collide(c, n);
//   }
//   dSpaceCollide(space, &friction, &near);
//   friction.createJoints(world, contact_group);
//   dWorldQuickStep(world, dt);
//
// One batch per step rather than one call per pair: patch samples are kept across steps and
// the sense a contact last slid in is remembered only for the contacts of one batch
// (ContactFriction::compute), and a batch can use the thread pool.
//
// Conventions: ODE's contact normal points from g2 into g1, so g1 is Asperity's A and g2 its B
// (SPEC 1). The surface the callback set is mu0: its mu (and mu2 with dContactMu2) along
// Asperity's axes; Asperity adds k_A mubar_A + k_B mubar_B (Eq. 7). ODE's friction bounds are
// +-mu (symmetric): per contact and axis the coefficient of the sense the contact slides in,
// else last slid in (as MuJoCo's adapter, asperity/engines/mujoco.hpp). Where both axes get the
// same coefficient the contact keeps ODE's own directions, so a flat texture leaves ODE's run
// bit for bit unchanged.
#pragma once

#include <ode/ode.h>

#include <memory>
#include <span>
#include <string>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/engines/engine_surfaces.hpp"

namespace asperity {

// What the last finish() did (times in ms).
struct OdeFrictionStats {
  int contacts = 0;        // contacts handed over by collide() this step
  int textured = 0;        // contacts given Asperity's direction and coefficients
  int unsupported = 0;     // contacts of a textured geom with a geom not registered
  double friction_ms = 0;  // the whole of finish(): states, compute, writing back
  double compute_ms = 0;   // ContactFriction::compute alone (frames and sampling)
};

class OdeFriction {
 public:
  explicit OdeFriction(const EngineSurfaces& surfaces);
  explicit OdeFriction(const std::string& surfaces_file);
  ~OdeFriction();
  OdeFriction(const OdeFriction&) = delete;
  OdeFriction& operator=(const OdeFriction&) = delete;

  // Registers a geom (plane, sphere, capsule, cylinder or box) under `name`: the surfaces
  // file's surface of that name, or flat when it has none. Throws asperity::Error naming the
  // geom for another geom class, a geom or name registered twice, or an empty name.
  ObjectId addGeom(dGeomID geom, const std::string& name);
  // The same, named by the geom's user data: a NUL-terminated string set with
  // dGeomSetData(geom, (void*)"floor"). Throws asperity::Error when the geom has no data.
  ObjectId addGeom(dGeomID geom);
  // Throws asperity::Error naming the surfaces file and the name for a surface that no
  // registered geom carries (finish() checks it too, on its first call).
  void checkNames() const;

  // In the near callback, after dCollide: keeps a pair's contacts with the surface the
  // callback gave them.
  void collide(const dContact* contacts, int count);
  // After dSpaceCollide: the step's contacts with Asperity's friction written into their
  // surface and fdir1, in collide() order; valid until the next finish(). Collide() calls
  // after it belong to the next step.
  std::span<dContact> finish();
  // finish(), then one contact joint per contact in `group`, attached to the geoms' bodies.
  void createJoints(dWorldID world, dJointGroupID group);

  // Results of the last finish(), one per textured contact in order.
  std::span<const ContactFrictionResult> lastResults() const;
  const OdeFrictionStats& lastStats() const;
  ContactFriction& friction();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace asperity
