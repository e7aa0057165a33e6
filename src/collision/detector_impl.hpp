// The collision detector's state and steps (CollisionDetector::Impl), private to src/collision.
// Its steps live in one file per concept:
//   collision_detector.cpp  the public class, building Bullet's world, one call's order of work
//                           and the sorted result;
//   detector_pairs.cpp      Bullet's pair walk: the broadphase filter, the near callback that
//                           routes each pair, and the box pairs run on the pool;
//   detector_manifolds.cpp  Bullet's manifold points into contacts on the true surfaces;
//   detector_direct.cpp     contacts made without Bullet's manifolds: shapes on planes,
//                           cylinder sides and fast shapes swept over the step.
#pragma once

#include <btBulletCollisionCommon.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "asperity/math/state_stream.hpp"
#include "collision/collision_detector.hpp"
#include "collision/cylinder_contacts.hpp"
#include "collision/mesh_features.hpp"
#include "collision/plane_contacts.hpp"
#include "collision/sdf_pairs.hpp"
#include "collision/shape_record.hpp"

namespace asperity {

namespace collision_detail {

// Hulls with more faces than this find their contact axis by GJK/EPA (Impl::gjkAxisPair).
inline constexpr size_t kSatMaxHullFaces = 64;

// One shape's straight sweep over the coming step (Bullet's convex cast): the earliest hit on
// each other shape it may collide with, planes left to their own speculative path.
struct SweepHit {
  int record = -1;
  double fraction = 1.0;  // of the sweep at first touch
  Vec3 point;             // on the other shape at first touch (Bullet units)
  Vec3 normal;            // out of the other shape, toward the swept one
  int triangle = -1;      // of a triangle mesh, as Bullet reports it
};

}  // namespace collision_detail

struct CollisionDetector::Impl {
  using ShapeRecord = collision_detail::ShapeRecord;

  // Broadphase filter: same body, two non-dynamic bodies and ignored pairs never pair up.
  struct PairFilter : btOverlapFilterCallback {
    const Impl* impl = nullptr;
    bool needBroadphaseCollision(btBroadphaseProxy* p0, btBroadphaseProxy* p1) const override;
  };

  // A dispatcher that knows its detector (for the near callback) and applies a fixed
  // contact breaking threshold when the settings give one.
  struct Dispatcher : btCollisionDispatcher {
    Impl* impl;
    Dispatcher(btCollisionConfiguration* config, Impl* owner)
        : btCollisionDispatcher(config), impl(owner) {}
    btPersistentManifold* getNewManifold(const btCollisionObject* b0,
                                         const btCollisionObject* b1) override;
    void freeCollisionAlgorithm(void* algorithm) override;
  };

  // What sorting needs of a contact found, in the order found; a manifold slot's entry is
  // written beside its contact, on the pool.
  struct Found {
    BodyId a, b;
    uint64_t key;
    const Contact* contact;
    bool kept;  // a manifold's gap point is dropped unless gaps are reported
  };
  struct SortKey {
    BodyId b;
    uint64_t key;
    uint32_t index;  // into found
  };
  // A manifold point dropped as stale before the narrowphase: its place on body 0 and its id.
  struct StalePoint {
    const btPersistentManifold* manifold;
    btVector3 local_a;
    void* id;
  };
  // Per worker slot of this call: a box pair's manifolds and stale points, each on its own
  // cache line (two threads writing one line would pass it back and forth for every pair).
  struct alignas(64) ManifoldList {
    btManifoldArray list;
    std::vector<StalePoint> stale;  // the box pair's, between dropStalePoints and keepStaleIds
  };

  CollisionSettings settings;
  double speculative_time = 0.0;  // s, setSpeculativeTime
  int64_t max_pairs = 0;          // setMaxPairs
  double scale = 1.0;             // Bullet's units per metre (bulletScale)
  std::vector<ShapeRecord> records;
  std::vector<BodyType> body_types;
  std::set<std::pair<BodyId, BodyId>> ignored;
  collision_detail::SdfResources sdf;
  std::map<std::shared_ptr<const TriangleMeshData>, std::unique_ptr<collision_detail::MeshFeatures>>
      mesh_features;

  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<Dispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btCollisionWorld> world;
  PairFilter filter;

  std::vector<std::pair<int, int>> plane_pairs;      // record pairs found by the broadphase
  std::vector<std::vector<Contact>> plane_contacts;  // per plane pair (collectPlanes)
  std::vector<collision_detail::PlaneScratch> plane_scratch;  // per plane pair, kept
  std::vector<std::pair<BodyId, BodyId>> touching_pairs;      // scratch of collectSwept
  std::vector<collision_detail::SweepHit> sweep_hits;         // scratch of collectSwept
  std::vector<std::pair<int, int>> sdf_pairs;
  // This call's contacts in the order found: contacts[0, manifold_base), then the kept points
  // of manifold_contacts[0, manifold_slots), then contacts[manifold_base, end) (gatherFound).
  std::vector<Contact> contacts;
  std::vector<collision_detail::CylinderSidePoint> side_points;  // scratch of collectCylinderSide
  std::vector<Contact> sorted;  // detect's result when the caller gives no vector
  // Manifold points' contacts, one slot each, reset and filled on the pool. The buffer only
  // grows: making the pile's 4000 default contacts (2 MB) anew on the calling thread every
  // step cost a tenth of its collision stage on two threads.
  std::vector<Contact> manifold_contacts;
  size_t manifold_base = 0, manifold_slots = 0;
  std::vector<Found> manifold_found, found;
  std::vector<SortKey> order;
  std::vector<size_t> bucket_start;  // per body_a, for sortInto
  // Per manifold (collectManifolds), then summed: its first point's slot, its first new id.
  std::vector<size_t> manifold_first, manifold_new;
  // Per worker slot: the nearest-triangle search's buffers, all grown to the largest.
  std::vector<collision_detail::NearestScratch> nearest_scratch;
  // This call's worker threads (null: the calling thread only), and the box-box pairs whose
  // narrowphase waits for them (deferBoxPair).
  const ThreadPool* workers = nullptr;
  std::vector<btBroadphasePair*> deferred;
  std::vector<ManifoldList> pair_manifolds;
  uint64_t next_point_id = 1;
  // A restored state's manifolds (detector_state.cpp) by their pair of objects, until the
  // pair's algorithm asks Dispatcher::getNewManifold for its own.
  using ObjectPair = std::pair<const btCollisionObject*, const btCollisionObject*>;
  static ObjectPair objectPair(const btCollisionObject* a, const btCollisionObject* b) {
    return std::less<>()(a, b) ? ObjectPair{a, b} : ObjectPair{b, a};
  }
  std::map<ObjectPair, btPersistentManifold*> restored_manifolds;
  // Restored algorithms that make their manifold lazily (convex pairs), until they take it: one
  // dropped before that releases its manifold as its destructor would have.
  std::map<void*, ObjectPair> lazy_algorithms;

  ~Impl() { release(); }

  // Pair tests on records (indices into `records`).
  bool shouldCollide(int r0, int r1) const {
    const ShapeRecord& a = records[static_cast<size_t>(r0)];
    const ShapeRecord& b = records[static_cast<size_t>(r1)];
    if (a.body == b.body) return false;
    if (a.body_type != BodyType::Dynamic && b.body_type != BodyType::Dynamic) return false;
    return !ignored.count({std::min(a.body, b.body), std::max(a.body, b.body)});
  }
  bool isPlanePair(int r0, int r1) const {
    return records[static_cast<size_t>(r0)].shape.type == ShapeType::Plane ||
           records[static_cast<size_t>(r1)].shape.type == ShapeType::Plane;
  }
  bool isBoxPair(int r0, int r1) const {
    return records[static_cast<size_t>(r0)].shape.type == ShapeType::Box &&
           records[static_cast<size_t>(r1)].shape.type == ShapeType::Box;
  }
  bool isSdfPair(int r0, int r1) const {
    return settings.mesh_pairs == MeshPairMode::Auto &&
           collision_detail::isSdfPair(records[static_cast<size_t>(r0)],
                                       records[static_cast<size_t>(r1)]);
  }
  bool gjkAxisPair(int r0, int r1) const;

  // How far apart gap contacts of this shape are reported (report_gaps only).
  double gapReach(const ShapeRecord& r) const {
    return settings.contact_margin > 0 ? settings.contact_margin
                                       : 0.02 * collision_detail::shapeSize(r.shape);
  }

  // Dynamic triangle meshes and hulls made from meshes map contacts to mesh triangles (a
  // triangle lookup, built on first use).
  static bool hasFeatures(const ShapeRecord& r) {
    const bool dynamic_mesh =
        r.shape.type == ShapeType::TriangleMesh && r.body_type == BodyType::Dynamic;
    const bool hull_mesh =
        r.shape.type == ShapeType::ConvexHull && !r.shape.mesh->triangles.empty();
    return dynamic_mesh || hull_mesh;
  }
  // The shape's mesh features, made on first use.
  const collision_detail::MeshFeatures* featuresOf(const ShapeRecord& r) {
    if (!hasFeatures(r)) return nullptr;
    auto& f = mesh_features[r.shape.mesh];
    if (!f) f = std::make_unique<collision_detail::MeshFeatures>(r.shape.mesh);
    return f.get();
  }
  // The same once made (featuresOf): a lookup that worker threads may share.
  const collision_detail::MeshFeatures* madeFeaturesOf(const ShapeRecord& r) const {
    if (!hasFeatures(r)) return nullptr;
    const auto it = mesh_features.find(r.shape.mesh);
    return it == mesh_features.end() ? nullptr : it->second.get();
  }

  // Building (collision_detector.cpp).
  void build(std::span<const Body> bodies);
  void createWorld(size_t shape_count);
  void addBody(BodyId id, const Body& body, collision_detail::BoxPolyhedra& boxes);
  void prepareSdf();
  void release();

  // The persistence saved and restored (detector_state.cpp).
  struct TreeLoader;
  void saveBroadphase(StateWriter& out) const;
  void loadBroadphase(StateReader& in);
  void readBroadphase(StateReader& in, TreeLoader& loader);
  // After a failed load: every proxy a fresh leaf of the dynamic tree, in stage 0, so that
  // Bullet's destructor (which removes each proxy's leaf from its stage's tree) finds whole
  // trees; the loader's nodes are freed.
  void rebuildBroadphase(TreeLoader& loader);
  void savePairs(StateWriter& out) const;
  void loadPairs(StateReader& in);
  // The saved manifolds made empty in their order (points returned, put in after the pairs).
  void loadManifolds(StateReader& in, const TreeLoader& loader,
                     std::vector<btPersistentManifold*>& made,
                     std::vector<std::vector<btManifoldPoint>>& points);
  const btCollisionObject* objectOf(const TreeLoader& loader, int record) const;

  // One call, in order (collision_detector.cpp), and its result sorted.
  void collect(std::span<const Body> bodies, const ThreadPool* pool);
  void sortInto(std::vector<Contact>& out);
  static Found foundOf(const Contact& c) { return {c.body_a, c.body_b, c.key, &c, true}; }
  void gatherFound();

  // Bullet's pair walk (detector_pairs.cpp).
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& d,
                           const btDispatcherInfo& info);
  bool idleBoxPair(btBroadphasePair& pair, int r0, int r1, btManifoldArray& scratch) const;
  static void dropStalePoints(btBroadphasePair& pair, ManifoldList& scratch);
  static void keepStaleIds(ManifoldList& scratch);
  void deferBoxPair(btBroadphasePair& pair, btCollisionDispatcher& d);
  void detectPairs();
  // Throws TooManyPairsError when the broadphase found more pairs than max_pairs.
  void checkPairBudget(const btBroadphasePairArray& pairs) const;
  void processDeferred();

  // Manifold points into contacts (detector_manifolds.cpp).
  void collectManifolds();
  void makeManifoldFeatures();
  void countManifoldPoints();
  void convertManifold(size_t m, uint64_t first_id);
  // Fills c, a default Contact, in place (no 400-byte temporary per point).
  void manifoldContact(const btManifoldPoint& pt, const ShapeRecord& r0, const ShapeRecord& r1,
                       collision_detail::NearestScratch& nearest, Contact& c) const;

  // Contacts made without Bullet's manifolds (detector_direct.cpp). Plane pairs on the pool,
  // each into its own buffer, appended in pair order.
  void collectPlanes();
  void collectPlane(int r0, int r1, std::vector<Contact>& out,
                    collision_detail::PlaneScratch& scratch) const;
  bool collectCylinderSide(int r0, int r1);
  void collectSwept();
  Contact sweptContact(const ShapeRecord& moving, const Vec3& displacement,
                       const collision_detail::SweepHit& hit);
};

}  // namespace asperity
