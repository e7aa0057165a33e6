// Asperity's friction inside MuJoCo 2.2 (target asperity_mujoco, built when libmujoco-dev is
// found; docs/engines.md). An MJCF model plus a surfaces file (asperity/engines/
// engine_surfaces.hpp) that gives some geoms an Asperity surface by name. Each step runs
// MuJoCo's own stages through its public API, split where the maintainers advise (mujoco
// #717): the position stage up to mj_collision, then every contact that touches a textured
// geom gets Asperity's frame (rows 3-8 of mjContact::frame) and coefficients
// (friction[0..1]), then mj_makeConstraint and the rest of MuJoCo's step. MuJoCo's own solver
// does the rest.
//
// Conventions: MuJoCo's contact normal (frame rows 0-2) points from geom1 to geom2, so geom2 is
// Asperity's A and geom1 its B (SPEC 1: n from B toward A). The pair's own coefficient
// (con->friction[0], [1]) is mu0; Asperity adds k_A mubar_A + k_B mubar_B (Eq. 7).
//
// MuJoCo's cone (pyramidal or elliptic) is symmetric: +d and -d share one coefficient (mujoco
// #514). Per contact and axis the adapter uses the coefficient of the sense the contact slides
// in, else the sense it last slid in (ContactFrictionResult::symmetric_t, _b): exact while a
// contact slides one way, approximate when it reverses or rests under a load that pushes the
// other way (docs/engines.md measures it). Where both coefficients are equal the frame is
// MuJoCo's own, so a flat texture leaves MuJoCo's run bit for bit unchanged. Use the elliptic
// cone: a pyramid shares the normal force among its edges, so with strongly anisotropic
// coefficients its weak axis grips too little.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <span>
#include <string>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/engines/engine_surfaces.hpp"

namespace asperity {

// What the last step did (counts of d->contact entries; times in ms).
struct MujocoFrictionStats {
  int contacts = 0;        // d->ncon
  int textured = 0;        // contacts given Asperity's frame and coefficients
  int unsupported = 0;     // contacts of a textured geom with a geom of a type Asperity lacks
  double friction_ms = 0;  // the whole edit: states, contacts, compute, writing back
  double compute_ms = 0;   // ContactFriction::compute alone (frames and sampling)
  double step_ms = 0;      // the whole step or forward call
};

class MujocoFriction {
 public:
  // `model` must outlive this object. Throws asperity::Error naming the surfaces file and the
  // name for a surface whose geom the model lacks, and naming the geom for a textured geom
  // with condim 1 (friction needs condim 3 or more) or of a type Asperity cannot shape
  // (planes, spheres, capsules, cylinders and boxes can be textured).
  MujocoFriction(const mjModel* model, const EngineSurfaces& surfaces);
  MujocoFriction(const mjModel* model, const std::string& surfaces_file);
  ~MujocoFriction();
  MujocoFriction(const MujocoFriction&) = delete;
  MujocoFriction& operator=(const MujocoFriction&) = delete;

  // mj_step with Asperity's friction. Throws asperity::Error unless the model's integrator is
  // Euler (RK4's and the implicit integrator's inner stages run MuJoCo's collision again).
  void step(mjData* d);
  // mj_forward with Asperity's friction.
  void forward(mjData* d);
  // The edit alone, for callers that run MuJoCo's stages themselves: call it after
  // mj_collision and before mj_makeConstraint.
  void applyToContacts(mjData* d);

  // Results of the last edit, one per textured contact in d->contact order.
  std::span<const ContactFrictionResult> lastResults() const;
  const MujocoFrictionStats& lastStats() const;
  ContactFriction& friction();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace asperity
