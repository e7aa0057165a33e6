// An Asperity scene rebuilt in ODE: static bodies as body-less geoms, dynamic ones as bodies
// with one geom each, every geom named after its body through its user data (a C string), so
// that OdeFriction::addGeom(geom) finds its surface. Shapes: boxes, spheres, capsules,
// cylinders and planes, one per body; no joints, springs or loads. Contacts as the peers'
// benchmark sets them: dContactApprox1 (Coulomb), mu = the scene's mu0, world ERP 0.5 and CFM
// 1e-5, dWorldQuickStep with 20 iterations, up to 8 contacts per pair.
#pragma once

#include <ode/ode.h>

#include <deque>
#include <map>
#include <string>
#include <vector>

#include "asperity/engines/ode.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity::ode_scene {

// Dynamic bodies whose angular speed is held at 0 (dBodySetMaxAngularSpeed): they cannot turn,
// so their faces stay parallel to what they slide on (a check of the adapter alone: a tilted
// flat face ploughs a little in Asperity's model, SPEC 2).
struct OdeOptions {
  bool translation_only = false;
};

class OdeScene {
 public:
  // Initialises ODE for this thread on first use. Throws asperity::Error naming what ODE's side
  // cannot hold.
  explicit OdeScene(const SceneDesc& scene, const OdeOptions& options = {});
  ~OdeScene();
  OdeScene(const OdeScene&) = delete;
  OdeScene& operator=(const OdeScene&) = delete;

  // Registers every geom with `friction` by its user data (the body's name).
  void registerGeoms(OdeFriction& friction) const;
  // One step of dt: collision (through `friction` when not null), contact joints, QuickStep.
  void step(OdeFriction* friction);
  double dt() const { return dt_; }
  // Each dynamic body's position by name.
  std::map<std::string, Vec3> positions() const;
  // Every dynamic body's position, quaternion, linear and angular velocity, one after the other.
  std::vector<double> state() const;
  // Puts the bodies back where state() saw them.
  void restore(const std::vector<double>& state);

 private:
  static void nearCallback(void* data, dGeomID o1, dGeomID o2);
  void addBody(const BodyDesc& desc, const OdeOptions& options);

  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  std::vector<dGeomID> geoms_;
  std::vector<std::pair<std::string, dBodyID>> bodies_;
  std::deque<std::string> names_;    // the geoms' user data (stable addresses)
  OdeFriction* friction_ = nullptr;  // during step()
  double dt_ = 0.01;
  double mu0_ = 0.2;
};

// The scene in ODE for `seconds`, with Asperity's friction when `with_asperity` (else ODE's own
// with mu0).
struct RunResult {
  std::map<std::string, Vec3> positions;  // each dynamic body's at the end, by name
  std::vector<double> trajectory;         // OdeScene::state() after every step
  OdeFrictionStats stats;                 // of the last step (zero without Asperity)
};
RunResult run(const SceneDesc& scene, double seconds, bool with_asperity,
              const OdeOptions& options = {});

}  // namespace asperity::ode_scene
