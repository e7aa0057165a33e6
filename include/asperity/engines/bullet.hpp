// Asperity's friction inside a Bullet 3 world (btDiscreteDynamicsWorld; target asperity::bullet,
// docs/engines.md). Bullet keeps its collision detection, islands and solver; Asperity gives
// each contact point its frame and its four box bounds (SPEC 4):
//
//   btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
//   asperity::BulletFriction friction(world, settings);  // installs its own solver
//   friction.attach(ground, "ground", sawtooth_surface);  // shapes read from Bullet's
//   friction.attach(box, "box", asperity::Surface{});     // flat: mu0 and the ground's texture
//   world.stepSimulation(0.01f, 0);
//
// Where in Bullet's step: btDiscreteDynamicsWorld::solveConstraints calls the constraint
// solver's prepareSolve once per step, after collision detection and before the islands are
// solved. The solver installed here (a subclass of btSequentialImpulseConstraintSolver) then
// hands every contact point of the dispatcher's manifolds whose two objects are attached to
// ContactFriction in one batch, and sets each point's m_lateralFrictionDir1/2 to (t, b) with
// BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED (the world's solver mode gets
// SOLVER_ENABLE_FRICTION_DIRECTION_CACHING | SOLVER_USE_2_FRICTION_DIRECTIONS). In each PGS
// iteration it bounds a friction row by its own sense: the row along t to
// [-mu_neg_t lambda_n, mu_pos_t lambda_n], the row along b likewise (Bullet's own solver
// clamps both senses to +-mu lambda_n). No global callback is used: worlds are independent.
//
// Conventions: Bullet's manifold point holds m_normalWorldOnB, the normal on body 1 pointing
// toward body 0, and its friction rows push body 0 along +dir. Body 0 is A and body 1 is B of
// SPEC 1, n = m_normalWorldOnB, except that a lone dynamic object is A (Asperity's own rule,
// which also keeps the patch sampler's work small): when body 0 is static or kinematic the
// sides swap, n = -m_normalWorldOnB, and the bounds written to Bullet's rows are mirrored
// (body 0's friction along +d is A's along -d). The depth is -getDistance() (>= 0 when
// touching); the point is the midpoint of the two witness points.
#pragma once

#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/engines/engine_surfaces.hpp"

class btCollisionObject;
class btCollisionShape;
class btDiscreteDynamicsWorld;

namespace asperity {

class BulletFriction {
 public:
  // Installs Asperity's friction in `world` (its solver replaced, its solver modes extended).
  // The world must outlive this object; destroying it gives the world back its previous
  // solver and solver mode. Throws asperity::Error for bad settings (ContactFriction's).
  explicit BulletFriction(btDiscreteDynamicsWorld& world, ContactFrictionSettings settings = {});
  ~BulletFriction();
  BulletFriction(const BulletFriction&) = delete;
  BulletFriction& operator=(const BulletFriction&) = delete;

  // Registers `object` with its surfaces. desc.shapes lie in the object's frame (a rigid
  // body's centre-of-mass frame, as Bullet's world transform); one shape, or one per child of
  // a btCompoundShape in child order. Throws asperity::Error naming the object for a null or
  // already attached object, a shape count that does not match, or ContactFriction's checks.
  ObjectId attach(btCollisionObject* object, const ObjectDesc& desc);
  // The same with the shapes read from the object's collision shape (box, sphere, capsule,
  // cylinder, static plane, or a compound of those), each carrying `surface` (resolved here
  // when it still names an unloaded normal map). Throws asperity::Error naming the object and
  // the shape for other shapes.
  ObjectId attach(btCollisionObject* object, const std::string& name, const Surface& surface);
  // Attaches each entry of a surfaces file to the object of that name. A name that `objects`
  // lacks is an error naming the name and the file (nothing is attached then).
  void attach(const EngineSurfaces& file, const std::map<std::string, btCollisionObject*>& objects);
  // Stops handling `object`'s contacts (call it before removing the object from the world);
  // its contacts get Bullet's own friction again. Unknown objects are ignored.
  void detach(btCollisionObject* object);

  // The contacts of the last step that Asperity handled, as handed to ContactFriction, and
  // what it gave back (same order). Valid until the next step.
  std::span<const EngineContact> lastContacts() const;
  std::span<const ContactFrictionResult> lastResults() const;
  // Wall-clock time of the last step's friction update (ms): gathering the manifolds' points,
  // ContactFriction::compute, and writing frames and bounds back.
  double lastUpdateMs() const;
  ContactFriction& contactFriction();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The Asperity shapes of a Bullet collision shape (see BulletFriction::attach), each carrying
// `surface`. Throws asperity::Error naming `what` and the shape for shapes it cannot describe.
std::vector<Shape> shapesOfBulletShape(const btCollisionShape& shape, const Surface& surface,
                                       const std::string& what);

}  // namespace asperity
