// An Asperity scene (asperity/scene/scene.hpp) built as a Bullet world, for running the same
// set-up in both engines (the Bullet demo, the adapter's tests and benchmark): every body becomes
// a btRigidBody with the mass, inertia, pose and velocities a World gives it, its shapes become
// Bullet's (as Asperity's collision stage builds them), and BulletFriction gets every body's
// surfaces. Bodies only: joints, springs, loads and meshes read from files are errors.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "asperity/engines/bullet.hpp"
#include "asperity/scene/scene.hpp"

class btDiscreteDynamicsWorld;
class btRigidBody;

namespace asperity {

struct BulletSceneOptions {
  // false: plain Bullet, its own solver and friction (each contact gets mu0: every object's
  // friction is sqrt(mu0), and Bullet multiplies the two).
  bool asperity_friction = true;
  // Plain Bullet with two friction directions per contact, as BulletFriction runs it
  // (SOLVER_USE_2_FRICTION_DIRECTIONS); false: Bullet's default, one direction along the
  // sliding velocity (no resistance across it).
  bool two_friction_directions = true;
  // Overrides the scene's frame mode (e.g. Auto, whose t follows the sliding as Bullet's own
  // friction directions do).
  std::optional<FrameMode> frame_mode;
};

// The ContactFriction settings a scene's World would use: its friction settings, provider,
// frame mode and axes, Auto's sliding speed and threads.
ContactFrictionSettings contactFrictionSettings(const SceneDesc& scene);

class BulletScene {
 public:
  // Builds the world (dt, gravity and PGS iterations from the scene's settings; no
  // deactivation, so that bodies never sleep). Throws asperity::Error naming the scene's file
  // and the culprit.
  explicit BulletScene(const SceneDesc& scene, const BulletSceneOptions& options = {});
  ~BulletScene();
  BulletScene(const BulletScene&) = delete;
  BulletScene& operator=(const BulletScene&) = delete;

  // One step of the scene's dt (stepSimulation(dt, 0): no interpolation, no sub-steps).
  void step();
  double time() const;

  btDiscreteDynamicsWorld& world();
  // The body of that name; throws asperity::Error for an unknown name.
  btRigidBody& body(std::string_view name);
  // A body's centre of mass (m).
  Vec3 position(std::string_view name);
  // Every body by name (what BulletFriction::attach takes with a surfaces file).
  const std::map<std::string, btCollisionObject*>& objects() const;
  // Null for plain Bullet.
  BulletFriction* friction();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The engine a scene runs in for slideDistances: Asperity's World, Bullet with Asperity's
// friction, or plain Bullet with mu0.
enum class SceneEngine { Asperity, Bullet, PlainBullet };
inline constexpr std::pair<const char*, SceneEngine> kSceneEngineNames[] = {
    {"asperity", SceneEngine::Asperity},
    {"bullet", SceneEngine::Bullet},
    {"plain", SceneEngine::PlainBullet}};

// How far each dynamic body's centre of mass moved across gravity in `seconds` (m), by name in
// the scene's order: the distance a launched box slid. `options` apply to the Bullet runs
// (its asperity_friction is set from `engine`).
std::vector<std::pair<std::string, double>> slideDistances(const SceneDesc& scene,
                                                           SceneEngine engine, double seconds,
                                                           BulletSceneOptions options = {});

}  // namespace asperity
