// The collision stage: broadphase and narrowphase over all bodies' shapes, giving contacts
// that follow the conventions of contact.hpp (normal from B to A, phi >= 0, witness points,
// shape/feature identities, a persistent key per contact for warm starting).
//
// Which body is A (SPEC 1): when exactly one body of the pair is dynamic, it is A (so the
// ground, a static or kinematic body, is always B); when both are dynamic, A is the one with
// the lower id. Body ids are indices into the span given to setBodies/detect.
//
// Identities: shape_a/shape_b index the body's shapes; feature_a/feature_b hold the triangle
// index for triangle meshes (and hulls given with triangles: the triangle nearest to the
// witness point, or one using the touching vertex), the face index for boxes
// (2 * axis + (outward normal along the negative axis ? 1 : 0), axes x, y, z of the box) and
// -1 otherwise. `key` stays the same for as long as the contact persists (Bullet's persistent
// manifolds keep the points alive across calls; signed-distance contacts are keyed by vertex).
//
// Concave meshes: a static TriangleMesh is a BVH of its triangles (Bullet). A dynamic
// TriangleMesh collides as the convex hull of its vertices, except when it is closed (every
// edge shared by two triangles) and meets another closed mesh or a box, sphere, capsule or
// cylinder: then the signed-distance path is used, which sees concave features such as a
// nut's bore. Each side's surface points (mesh vertices plus a grid on each triangle, about
// one cell apart) are queried against the other side's signed distance: a grid field for
// meshes (signed_distance_field.hpp, `sdf_resolution` cells across), the exact distance for
// primitives. Against planes every convex or mesh shape uses its exact vertices.
//
// Scale: every tolerance follows the shapes' sizes. Bullet's margins are 2% of a shape's
// smallest dimension (at most 4 cm) and lie inside boxes, cylinders, spheres and capsules; its
// contact breaking threshold is 2% of the smaller shape's bounding radius; Bullet itself runs
// in units scaled by a power of two so that the smallest dynamic shape is at least 0.2 units
// across (its GJK has absolute tolerances). Witness points and phi are recomputed in double
// on the true surfaces, so margins never show in the contacts: millimetre parts (an M4 nut)
// and metre boxes get the same relative accuracy.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/error.hpp"

namespace asperity {

class ThreadPool;   // parallel/thread_pool.hpp
class StateReader;  // asperity/math/state_stream.hpp
class StateWriter;

// How concave mesh pairs are handled.
enum class MeshPairMode {
  Auto,       // signed distances for dynamic closed meshes (see above)
  ConvexHull  // always Bullet: dynamic meshes as convex hulls
};

struct CollisionSettings {
  // Contacts are reported up to this separation (m); scaled to the scene by the world
  // (e.g. a fraction of the smallest shape) so millimetre parts and metre boxes both work.
  double contact_margin = 0.0;  // 0 = automatic from the bodies' sizes
  // Report contacts that are within the margin but not yet touching, with phi < 0 (the gap).
  // Off by default: every reported contact has phi >= 0 (contact.hpp).
  bool report_gaps = false;

  MeshPairMode mesh_pairs = MeshPairMode::Auto;
  int sdf_resolution = 64;       // grid cells along the longest side of a mesh's box
  int sdf_max_contacts = 32;     // per shape pair and direction, deepest first
  double sdf_min_spacing = 2.0;  // kept contacts lie at least this many grid cells apart
};

// The broadphase found more pairs than setMaxPairs allows; the bodies in most pairs.
class TooManyPairsError : public Error {
 public:
  TooManyPairsError(const std::string& message, std::vector<BodyId> bodies)
      : Error(message), bodies_(std::move(bodies)) {}
  const std::vector<BodyId>& bodies() const { return bodies_; }

 private:
  std::vector<BodyId> bodies_;
};

class CollisionDetector {
 public:
  CollisionDetector();
  ~CollisionDetector();
  CollisionDetector(const CollisionDetector&) = delete;
  CollisionDetector& operator=(const CollisionDetector&) = delete;

  // Rebuilds the collision objects for these bodies (call after adding/removing bodies).
  void setBodies(std::span<const Body> bodies, const CollisionSettings& settings);
  // Updates poses and returns this step's contacts (valid until the next call). Pairs of
  // non-dynamic bodies and pairs filtered by `ignore` are skipped. Contacts are sorted by
  // (body_a, body_b, key).
  const std::vector<Contact>& detect(std::span<const Body> bodies);
  // The same contacts written into `out` (its previous contents replaced); Bullet's contact
  // points become contacts on `pool`'s threads when given (the same bits on any count).
  void detect(std::span<const Body> bodies, std::vector<Contact>& out,
              const ThreadPool* pool = nullptr);
  // Bodies joined by a joint may be excluded from colliding with each other.
  void ignorePair(BodyId a, BodyId b);
  // Time to the next detect (s; the world's dt). A shape that can close more than a quarter of
  // its size toward a plane in that time gets speculative plane contacts (phi < 0) up to that
  // distance, so it cannot pass through the plane in one step; 0 (default) = none.
  void setSpeculativeTime(double seconds);
  // Overlapping shape pairs the broadphase may find in the next detections (0: no limit).
  // Past it detect throws TooManyPairsError before any pair gets its narrowphase state
  // (Bullet's algorithms and manifolds, kilobytes a pair), so bodies piled into one point cost
  // bounded time and memory.
  void setMaxPairs(int64_t pairs);
  // Numbers new contact points from 1 again, as in a new detector (with setBodies and the
  // solver's warm start forgotten: World::forgetContactHistory).
  void restartPointIds();
  // What the next detect depends on beyond the bodies (the next point id and, with
  // `structures`, Bullet's broadphase, pairs and persistent manifolds: detector_state.cpp),
  // saved; loadState puts it into a detector that setBodies has just built for the same
  // bodies, and the detects that follow are those the saved detector would have made, bit for
  // bit. Without `structures` (a detector about to be rebuilt) only the point id is kept.
  // Throws asperity::Error for a state that does not fit these shapes.
  void saveState(StateWriter& out, bool structures) const;
  void loadState(StateReader& in, bool structures);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace asperity
