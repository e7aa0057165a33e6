// The collision stage.
//
// Bullet's role: Bullet's collision module (single precision, no dynamics world) finds the
// pairs (btDbvtBroadphase) and runs the narrowphase (btCollisionDispatcher over a
// btCollisionWorld): box-box clipping, GJK/EPA and polyhedral clipping for convex pairs, BVH
// traversal for static triangle meshes, all in units scaled to the scene (bulletScale) so that
// its absolute tolerances suit millimetre parts. Its persistent manifolds keep contact points alive
// across calls; each point gets an id stored in the manifold point, from which the contact key
// is hashed. Everything after that is done here in double precision: witness points from the
// manifold's local points through the double body poses, put back onto the true surfaces
// (Bullet's margins removed, primitives exact: contact_geometry), phi from the witness points.
//
// Three kinds of pairs bypass Bullet's narrowphase: shapes against planes (plane_contacts:
// exact points, a box resting flat gets its four corners in one call), pairs with a dynamic
// closed mesh (sdf_pairs: signed distances), both only recorded by the near callback, and
// boxes, capsules and spheres against a cylinder's side (cylinder_contacts: radial normals),
// done in the near callback, which falls back to Bullet near the cylinder's caps.
//
// One Bullet collision object per shape (not a btCompoundShape per body): Bullet stores a
// compound's child index and a mesh's triangle index in the same manifold field, so separate
// objects are what keeps both Contact::shape_* and Contact::feature_*.
//
// A/B rule: when exactly one body is dynamic it is A (the ground is B); when both are
// dynamic, the lower id is A. The normal points from B toward A, phi >= 0 is the depth.
#include "collision/collision_detector.hpp"

#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>
#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "asperity/error.hpp"
#include "collision/bullet_shapes.hpp"
#include "collision/contact_geometry.hpp"
#include "collision/cylinder_contacts.hpp"
#include "collision/mesh_features.hpp"
#include "collision/plane_contacts.hpp"
#include "collision/sdf_pairs.hpp"
#include "collision/shape_record.hpp"
#include "collision/signed_distance_field.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

// collectManifolds makes contacts anew in slots that held others (std::construct_at).
static_assert(std::is_trivially_destructible_v<Contact>);

using namespace collision_detail;

namespace {

// Hulls with more faces than this find their contact axis by GJK/EPA (Impl::gjkAxisPair).
constexpr size_t kSatMaxHullFaces = 64;

// Bullet grows hulls and triangles by their margins in some of its algorithms and not in
// others; the witness point is put back onto the true surface from what is known exactly:
// the hull's face planes, the static mesh's triangle.
Vec3 onTrueSurface(const ShapeRecord& r, const Vec3& witness, const Vec3& outward, int feature) {
  if (!r.hull_planes.empty()) {
    // Signed distance to the hull (exact near a face), removed along the contact normal.
    const Vec3 local = r.world.applyInverse(witness);
    double s = -1e300;
    for (const Vec4& p : r.hull_planes) s = std::max(s, p.head<3>().dot(local) + p.w());
    return witness - s * outward;
  }
  if (r.shape.type == ShapeType::TriangleMesh && feature >= 0 &&
      feature < static_cast<int>(r.shape.mesh->triangles.size())) {
    const auto& tri = r.shape.mesh->triangles[static_cast<size_t>(feature)];
    const auto& v = r.shape.mesh->vertices;
    return r.world.apply(
        closestPointOnTriangle(r.world.applyInverse(witness), v[static_cast<size_t>(tri[0])],
                               v[static_cast<size_t>(tri[1])], v[static_cast<size_t>(tri[2])]));
  }
  return witness;
}

// One shape's straight sweep over the coming step (Bullet's convex cast): the earliest hit on
// each other shape it may collide with, planes left to their own speculative path.
struct SweepHit {
  int record = -1;
  double fraction = 1.0;  // of the sweep at first touch
  Vec3 point;             // on the other shape at first touch (Bullet units)
  Vec3 normal;            // out of the other shape, toward the swept one
  int triangle = -1;      // of a triangle mesh, as Bullet reports it
};

template <class Filter>
struct SweepHits : btCollisionWorld::ConvexResultCallback {
  Filter accepts;
  std::vector<SweepHit>& hits;  // the caller's, kept between sweeps
  SweepHits(Filter f, std::vector<SweepHit>& out) : accepts(f), hits(out) { hits.clear(); }
  bool needsCollision(btBroadphaseProxy* proxy) const override {
    return accepts(static_cast<const btCollisionObject*>(proxy->m_clientObject)->getUserIndex());
  }
  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool normal_in_world) override {
    const int record = r.m_hitCollisionObject->getUserIndex();
    const btVector3 n = normal_in_world ? r.m_hitNormalLocal
                                        : r.m_hitCollisionObject->getWorldTransform().getBasis() *
                                              r.m_hitNormalLocal;
    const int triangle = r.m_localShapeInfo ? r.m_localShapeInfo->m_triangleIndex : -1;
    const SweepHit hit{record, r.m_hitFraction, fromBt(r.m_hitPointLocal), fromBt(n).normalized(),
                       triangle};
    auto same = std::find_if(hits.begin(), hits.end(),
                             [&](const SweepHit& h) { return h.record == record; });
    if (same == hits.end()) {
      hits.push_back(hit);
    } else if (hit.fraction < same->fraction) {
      *same = hit;
    }
    // Every shape along the way is reported, not only the nearest: the first may be a floor
    // slid along, which the sweep does not approach.
    return m_closestHitFraction;
  }
};

}  // namespace

struct CollisionDetector::Impl {
  // Broadphase filter: same body, two non-dynamic bodies and ignored pairs never pair up.
  struct PairFilter : btOverlapFilterCallback {
    const Impl* impl = nullptr;
    bool needBroadphaseCollision(btBroadphaseProxy* p0, btBroadphaseProxy* p1) const override {
      const auto* o0 = static_cast<const btCollisionObject*>(p0->m_clientObject);
      const auto* o1 = static_cast<const btCollisionObject*>(p1->m_clientObject);
      return impl->shouldCollide(o0->getUserIndex(), o1->getUserIndex());
    }
  };

  // A dispatcher that knows its detector (for the near callback) and applies a fixed
  // contact breaking threshold when the settings give one.
  struct Dispatcher : btCollisionDispatcher {
    Impl* impl;
    Dispatcher(btCollisionConfiguration* config, Impl* owner)
        : btCollisionDispatcher(config), impl(owner) {}
    btPersistentManifold* getNewManifold(const btCollisionObject* b0,
                                         const btCollisionObject* b1) override {
      btPersistentManifold* m = btCollisionDispatcher::getNewManifold(b0, b1);
      if (impl->settings.contact_margin > 0) {
        m->setContactBreakingThreshold(
            static_cast<btScalar>(impl->settings.contact_margin * impl->scale));
      }
      return m;
    }
  };

  CollisionSettings settings;
  double speculative_time = 0.0;  // s, setSpeculativeTime
  double scale = 1.0;             // Bullet's units per metre (bulletScale)
  std::vector<ShapeRecord> records;
  std::vector<BodyType> body_types;
  std::set<std::pair<BodyId, BodyId>> ignored;
  SdfResources sdf;
  std::map<std::shared_ptr<const TriangleMeshData>, std::unique_ptr<MeshFeatures>> mesh_features;

  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<Dispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btCollisionWorld> world;
  PairFilter filter;

  std::vector<std::pair<int, int>> plane_pairs;      // record pairs found by the broadphase
  std::vector<std::vector<Contact>> plane_contacts;  // per plane pair (collectPlanes)
  std::vector<collision_detail::PlaneScratch> plane_scratch;  // per plane pair, kept
  std::vector<std::pair<BodyId, BodyId>> touching_pairs;      // scratch of collectSwept
  std::vector<SweepHit> sweep_hits;                           // scratch of collectSwept
  std::vector<std::pair<int, int>> sdf_pairs;
  // This call's contacts in the order found: contacts[0, manifold_base), then the kept points
  // of manifold_contacts[0, manifold_slots), then contacts[manifold_base, end) (gatherFound).
  std::vector<Contact> contacts;
  std::vector<CylinderSidePoint> side_points;  // scratch of collectCylinderSide
  std::vector<Contact> sorted;                 // detect's result when the caller gives no vector
  // Manifold points' contacts, one slot each, reset and filled on the pool. The buffer only
  // grows: making the pile's 4000 default contacts (2 MB) anew on the calling thread every
  // step cost a tenth of its collision stage on two threads.
  std::vector<Contact> manifold_contacts;
  size_t manifold_base = 0, manifold_slots = 0;
  // What sorting needs of a contact found, in the order found; a manifold slot's entry is
  // written beside its contact, on the pool.
  struct Found {
    BodyId a, b;
    uint64_t key;
    const Contact* contact;
    bool kept;  // a manifold's gap point is dropped unless gaps are reported
  };
  std::vector<Found> manifold_found, found;
  struct SortKey {
    BodyId b;
    uint64_t key;
    uint32_t index;  // into found
  };
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
  // Per worker slot of this call: idleBoxPair's list of a pair's manifolds, each on its own
  // cache line (two threads writing one line would pass it back and forth for every pair).
  struct alignas(64) ManifoldList {
    btManifoldArray list;
  };
  std::vector<ManifoldList> pair_manifolds;
  uint64_t next_point_id = 1;

  ~Impl() { release(); }

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

  // Bullet's separating-axis search projects every vertex on every pair of edge directions:
  // for a hull of many faces (a scanned model's) against another convex shape GJK/EPA finds
  // the axis far faster, and the clipping into contact points that follows is the same.
  // (Against a triangle mesh Bullet clips only after its own search, so that stays.)
  bool gjkAxisPair(int r0, int r1) const {
    const ShapeRecord& a = records[static_cast<size_t>(r0)];
    const ShapeRecord& b = records[static_cast<size_t>(r1)];
    const auto mesh = [](const ShapeRecord& r) { return r.shape.type == ShapeType::TriangleMesh; };
    return (a.hull_planes.size() > kSatMaxHullFaces || b.hull_planes.size() > kSatMaxHullFaces) &&
           !mesh(a) && !mesh(b);
  }

  bool isSdfPair(int r0, int r1) const {
    return settings.mesh_pairs == MeshPairMode::Auto &&
           collision_detail::isSdfPair(records[static_cast<size_t>(r0)],
                                       records[static_cast<size_t>(r1)]);
  }

  // Bullet's narrowphase for ordinary pairs; plane and signed-distance pairs are only recorded.
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& d,
                           const btDispatcherInfo& info) {
    Impl* self = static_cast<Dispatcher&>(d).impl;
    const int r0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject)->getUserIndex();
    const int r1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject)->getUserIndex();
    if (self->isPlanePair(r0, r1)) {
      self->plane_pairs.emplace_back(r0, r1);
      return;
    }
    if (self->isSdfPair(r0, r1)) {
      self->sdf_pairs.emplace_back(r0, r1);
      return;
    }
    if (self->collectCylinderSide(r0, r1)) {
      // Bullet's manifold for the pair, from steps it served, would report stale points.
      if (pair.m_algorithm) self->world->getPairCache()->cleanOverlappingPair(pair, &d);
      return;
    }
    if (self->gjkAxisPair(r0, r1)) {
      btDispatcherInfo gjk_axis = info;
      gjk_axis.m_enableSatConvex = false;
      btCollisionDispatcher::defaultNearCallback(pair, d, gjk_axis);
      return;
    }
    // On one thread (one slot) the idle test runs here, so a skipped pair costs no deferral; on
    // several, beside the narrowphase.
    const bool box_pair = self->isBoxPair(r0, r1);
    if (box_pair && self->pair_manifolds.size() == 1 &&
        self->idleBoxPair(pair, r0, r1, self->pair_manifolds[0].list))
      return;
    if (box_pair && self->workers) {
      self->deferBoxPair(pair, d);
      return;
    }
    btCollisionDispatcher::defaultNearCallback(pair, d, info);
  }

  bool isBoxPair(int r0, int r1) const {
    return records[static_cast<size_t>(r0)].shape.type == ShapeType::Box &&
           records[static_cast<size_t>(r1)].shape.type == ShapeType::Box;
  }

  // A box pair whose algorithm and manifold exist (made in pair order, as without this test)
  // and whose manifold is empty, with its boxes apart along a face normal by more than
  // rounding: the narrowphase would add no point and have none to refresh, so it is skipped.
  // In a pile most pairs are such neighbours: the broadphase's boxes, grown by Bullet's
  // margins, overlap theirs.
  bool idleBoxPair(btBroadphasePair& pair, int r0, int r1, btManifoldArray& scratch) const {
    if (!pair.m_algorithm) return false;
    const ShapeRecord& a = records[static_cast<size_t>(r0)];
    const ShapeRecord& b = records[static_cast<size_t>(r1)];
    const double size = std::max(a.shape.half_extents.maxCoeff(), b.shape.half_extents.maxCoeff());
    const double gap = 1e-3 * size + settings.contact_margin;
    if (!collision_detail::boxesApart(a.shape.half_extents, a.axes, a.world.position,
                                      b.shape.half_extents, b.axes, b.world.position, gap)) {
      return false;
    }
    scratch.resizeNoInitialize(0);
    pair.m_algorithm->getAllContactManifolds(scratch);
    for (int k = 0; k < scratch.size(); ++k) {
      if (scratch[k]->getNumContacts() > 0) return false;
    }
    return true;
  }

  // Bullet's defaultNearCallback up to the narrowphase: the pair's algorithm (and with it, for
  // two boxes, its manifold) is made here, in pair order as before; processDeferred then runs
  // the box-box narrowphase of every such pair, each writing only its own manifold. A pair
  // that has its algorithm is only listed: processDeferred asks needsCollision, on the pool.
  void deferBoxPair(btBroadphasePair& pair, btCollisionDispatcher& d) {
    if (!pair.m_algorithm) {
      auto* o0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject);
      auto* o1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject);
      if (!d.needsCollision(o0, o1)) return;
      const btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0,
                                        o0->getWorldTransform(), -1, -1);
      const btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1,
                                        o1->getWorldTransform(), -1, -1);
      pair.m_algorithm = d.findAlgorithm(&w0, &w1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
    }
    if (pair.m_algorithm) deferred.push_back(&pair);
  }

  // Bullet's step (AABBs, broadphase, its walk over the pairs with nearCallback). On several
  // threads the walk is ours, over the same pair array in the same order: a box pair goes
  // straight to deferBoxPair (a pile's pairs, step after step, are only listed there), not
  // through nearCallback's tests of every other kind of pair.
  void detectPairs() {
    if (!workers || pair_manifolds.size() == 1) {
      world->performDiscreteCollisionDetection();
      return;
    }
    world->updateAabbs();
    world->computeOverlappingPairs();
    btBroadphasePairArray& pairs = world->getPairCache()->getOverlappingPairArray();
    const btDispatcherInfo& info = world->getDispatchInfo();
    for (int i = 0; i < pairs.size(); ++i) {
      btBroadphasePair& pair = pairs[i];
      const int r0 =
          static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject)->getUserIndex();
      const int r1 =
          static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject)->getUserIndex();
      if (isBoxPair(r0, r1)) {
        deferBoxPair(pair, *dispatcher);
      } else {
        nearCallback(pair, *dispatcher, info);
      }
    }
  }

  void processDeferred() {
    const btDispatcherInfo& info = world->getDispatchInfo();
    workers->forEach(deferred.size(), 16, [&](size_t k) {
      btBroadphasePair& pair = *deferred[k];
      auto* o0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject);
      auto* o1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject);
      if (!dispatcher->needsCollision(o0, o1)) return;  // read-only: safe on any thread
      if (pair_manifolds.size() > 1 &&
          idleBoxPair(pair, o0->getUserIndex(), o1->getUserIndex(),
                      pair_manifolds[static_cast<size_t>(workers->slot())].list)) {
        return;
      }
      const btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0,
                                        o0->getWorldTransform(), -1, -1);
      const btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1,
                                        o1->getWorldTransform(), -1, -1);
      btManifoldResult result(&w0, &w1);
      pair.m_algorithm->processCollision(&w0, &w1, info, &result);
    });
    deferred.clear();
  }

  void release() {
    // The world removes its objects' proxies, so it goes before the objects and broadphase.
    world.reset();
    records.clear();
    broadphase.reset();
    dispatcher.reset();
    config.reset();
  }

  // How far apart gap contacts of this shape are reported (report_gaps only).
  double gapReach(const ShapeRecord& r) const {
    return settings.contact_margin > 0 ? settings.contact_margin : 0.02 * shapeSize(r.shape);
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
  const MeshFeatures* featuresOf(const ShapeRecord& r) {
    if (!hasFeatures(r)) return nullptr;
    auto& f = mesh_features[r.shape.mesh];
    if (!f) f = std::make_unique<MeshFeatures>(r.shape.mesh);
    return f.get();
  }
  // The same once made (featuresOf): a lookup that worker threads may share.
  const MeshFeatures* madeFeaturesOf(const ShapeRecord& r) const {
    if (!hasFeatures(r)) return nullptr;
    const auto it = mesh_features.find(r.shape.mesh);
    return it == mesh_features.end() ? nullptr : it->second.get();
  }

  // Deterministic order (SPEC: same input, same contacts): by (body_a, body_b, key), ties in
  // the order found. Linear in the contacts: a counting pass buckets them by body_a, then each
  // bucket (a body's few contacts) is insertion-sorted by (body_b, key); only small keys move,
  // and each contact is copied once (sorting whole contacts, several hundred bytes each, with
  // a comparison sort cost more per contact as the pile grew).
  void sortInto(std::vector<Contact>& out) {
    gatherFound();
    bucket_start.assign(body_types.size() + 1, 0);
    for (const Found& f : found) ++bucket_start[f.a + 1];
    for (size_t b = 1; b < bucket_start.size(); ++b) bucket_start[b] += bucket_start[b - 1];
    order.resize(found.size());
    for (size_t i = 0; i < found.size(); ++i) {
      const Found& f = found[i];
      order[bucket_start[f.a]++] = SortKey{f.b, f.key, static_cast<uint32_t>(i)};
    }
    // bucket_start[b] now ends bucket b; bucket b begins where bucket b - 1 ends. Small
    // buckets by insertion, a body with many contacts by a comparison sort.
    const auto less = [](const SortKey& x, const SortKey& y) {
      return std::tie(x.b, x.key, x.index) < std::tie(y.b, y.key, y.index);
    };
    size_t begin = 0;
    for (const size_t end : bucket_start) {
      if (end - begin > 16) {
        std::sort(order.begin() + static_cast<std::ptrdiff_t>(begin),
                  order.begin() + static_cast<std::ptrdiff_t>(end), less);
      } else {
        for (size_t i = begin + 1; i < end; ++i) {
          const SortKey k = order[i];
          size_t j = i;
          for (; j > begin && less(k, order[j - 1]); --j) order[j] = order[j - 1];
          order[j] = k;
        }
      }
      begin = end;
    }
    out.resize(found.size());
    forEachOn(workers, order.size(), 256,
              [&](size_t i) { out[i] = *found[order[i].index].contact; });
  }

  static Found foundOf(const Contact& c) { return {c.body_a, c.body_b, c.key, &c, true}; }

  // found: every contact of this call in the order found (see contacts).
  void gatherFound() {
    found.clear();
    for (size_t i = 0; i < manifold_base; ++i) found.push_back(foundOf(contacts[i]));
    for (size_t s = 0; s < manifold_slots; ++s)
      if (manifold_found[s].kept) found.push_back(manifold_found[s]);
    for (size_t i = manifold_base; i < contacts.size(); ++i) found.push_back(foundOf(contacts[i]));
  }

  void collect(std::span<const Body> bodies, const ThreadPool* pool);

  void build(std::span<const Body> bodies);
  void prepareSdf();
  void createWorld(size_t shape_count);
  void addBody(BodyId id, const Body& body);
  void collectManifolds();
  // Fills c, a default Contact, in place (no 400-byte temporary per point).
  void manifoldContact(const btManifoldPoint& pt, const ShapeRecord& r0, const ShapeRecord& r1,
                       collision_detail::NearestScratch& nearest, Contact& c) const;
  // Plane pairs on the pool, each into its own buffer, appended in pair order.
  void collectPlanes();
  void collectPlane(int r0, int r1, std::vector<Contact>& out,
                    collision_detail::PlaneScratch& scratch) const;
  bool collectCylinderSide(int r0, int r1);
  void collectSwept();
  Contact sweptContact(const ShapeRecord& moving, const Vec3& displacement, const SweepHit& hit);
};

void CollisionDetector::Impl::createWorld(size_t shape_count) {
  // Bullet's pools of manifolds and pair algorithms hold 4096 each by default; past that every
  // new pair is a separate heap allocation, scattered in memory, and a large pile's steps slow
  // down per contact. Room for eight pairs per shape (at most 65536 each).
  btDefaultCollisionConstructionInfo info;
  const int pool = static_cast<int>(std::clamp<size_t>(8 * shape_count, 4096, 65536));
  info.m_defaultMaxPersistentManifoldPoolSize = pool;
  info.m_defaultMaxCollisionAlgorithmPoolSize = pool;
  config = std::make_unique<btDefaultCollisionConfiguration>(info);
  dispatcher = std::make_unique<Dispatcher>(config.get(), this);
  dispatcher->setDispatcherFlags(btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
  dispatcher->setNearCallback(&Impl::nearCallback);
  broadphase = std::make_unique<btDbvtBroadphase>();
  world = std::make_unique<btCollisionWorld>(dispatcher.get(), broadphase.get(), config.get());
  // Separating-axis tests for polyhedra (boxes, hulls, triangles): a box face on a mesh face
  // is clipped into its corner points in one call, as box-box is.
  world->getDispatchInfo().m_enableSatConvex = true;
  filter.impl = this;
  world->getPairCache()->setOverlapFilterCallback(&filter);
}

void CollisionDetector::Impl::addBody(BodyId id, const Body& body) {
  for (size_t s = 0; s < body.shapes.size(); ++s) {
    ShapeRecord rec;
    rec.body = id;
    rec.index = static_cast<int>(s);
    rec.body_type = body.type;
    rec.shape = body.shapes[s];
    rec.bounding_radius = boundingRadius(rec.shape);
    rec.size = shapeSize(rec.shape);
    rec.bullet = makeBulletShape(scaledShape(rec.shape, scale), body.type);
    // Closed meshes may take the signed-distance path (sdf_pairs).
    rec.closed_mesh = rec.shape.type == ShapeType::TriangleMesh && isClosedMesh(*rec.shape.mesh);
    // Face planes of hulls, for putting witness points back onto the true surface.
    if (rec.bullet.shape->getShapeType() == CONVEX_HULL_SHAPE_PROXYTYPE) {
      const auto* hull = static_cast<const btConvexHullShape*>(rec.bullet.shape.get());
      if (const btConvexPolyhedron* poly = hull->getConvexPolyhedron()) {
        for (int f = 0; f < poly->m_faces.size(); ++f) {
          const btScalar* p = poly->m_faces[f].m_plane;
          rec.hull_planes.emplace_back(p[0], p[1], p[2], p[3] / scale);
        }
      }
    }
    rec.world = body.pose * rec.shape.local;
    rec.object = std::make_unique<btCollisionObject>();
    rec.object->setCollisionShape(rec.bullet.shape.get());
    rec.object->setWorldTransform(toBt(rec.world, scale));
    rec.object->setUserIndex(static_cast<int>(records.size()));
    rec.object->setActivationState(DISABLE_DEACTIVATION);
    if (body.type == BodyType::Static) {
      rec.object->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    } else if (body.type == BodyType::Kinematic) {
      rec.object->setCollisionFlags(btCollisionObject::CF_KINEMATIC_OBJECT);
    }
    records.push_back(std::move(rec));
  }
}

void CollisionDetector::Impl::collectManifolds() {
  const int count = dispatcher->getNumManifolds();
  auto manifold = [&](size_t m) {
    return dispatcher->getManifoldByIndexInternal(static_cast<int>(m));
  };
  auto record = [&](const btCollisionObject* o) -> const ShapeRecord& {
    return records[static_cast<size_t>(o->getUserIndex())];
  };
  // Mesh features are made on first use, on this thread (hulls and dynamic meshes only).
  if (std::any_of(records.begin(), records.end(), hasFeatures)) {
    for (size_t m = 0; m < static_cast<size_t>(count); ++m) {
      featuresOf(record(manifold(m)->getBody0()));
      featuresOf(record(manifold(m)->getBody1()));
    }
  }
  // Each manifold's points and new points (without a persistent id yet), counted per manifold
  // on the pool, then summed in manifold order: a manifold's first slot and its first new id.
  const size_t manifolds = static_cast<size_t>(count);
  manifold_first.resize(manifolds + 1);
  manifold_new.resize(manifolds + 1);
  forEachOn(workers, manifolds, 64, [&](size_t m) {
    const btPersistentManifold* mf = manifold(m);
    size_t fresh = 0;
    for (int p = 0; p < mf->getNumContacts(); ++p)
      fresh += mf->getContactPoint(p).m_userPersistentData == nullptr;
    manifold_first[m + 1] = static_cast<size_t>(mf->getNumContacts());
    manifold_new[m + 1] = fresh;
  });
  manifold_first[0] = manifold_new[0] = 0;
  for (size_t m = 0; m < manifolds; ++m) {
    manifold_first[m + 1] += manifold_first[m];
    manifold_new[m + 1] += manifold_new[m];
  }
  // Then every manifold on the pool: its new points numbered in order (the ids a serial pass
  // in manifold order would give, on any thread count; Bullet keeps them while a point is
  // matched), and its points converted into its own slots (new, default Contacts).
  manifold_base = contacts.size();
  manifold_slots = manifold_first[manifolds];
  const uint64_t first_id = next_point_id;
  next_point_id += manifold_new[manifolds];
  if (manifold_contacts.size() < manifold_slots) {
    manifold_contacts.resize(manifold_slots);
    manifold_found.resize(manifold_slots);
  }
  nearest_scratch.resize(workers ? static_cast<size_t>(workers->concurrency()) : 1);
  const auto convert = [&](size_t m) {
    btPersistentManifold* mf = manifold(m);
    auto& nearest = nearest_scratch[workers ? static_cast<size_t>(workers->slot()) : 0];
    const ShapeRecord& r0 = record(mf->getBody0());
    const ShapeRecord& r1 = record(mf->getBody1());
    uint64_t id = first_id + manifold_new[m];
    for (int p = 0; p < mf->getNumContacts(); ++p) {
      btManifoldPoint& pt = mf->getContactPoint(p);
      if (!pt.m_userPersistentData)
        pt.m_userPersistentData = reinterpret_cast<void*>(static_cast<uintptr_t>(id++));
      const size_t slot = manifold_first[m] + static_cast<size_t>(p);
      Contact& c = *std::construct_at(&manifold_contacts[slot]);  // a default Contact again
      manifoldContact(pt, r0, r1, nearest, c);
      c.key = contactKey(
          c, static_cast<uint64_t>(reinterpret_cast<uintptr_t>(pt.m_userPersistentData)));
      manifold_found[slot] = foundOf(c);
      manifold_found[slot].kept = settings.report_gaps || c.phi >= 0;
    }
  };
  forEachOn(workers, manifolds, 32, convert);
  // Whichever thread converts a mesh's contacts next finds buffers large enough.
  for (auto& scratch : nearest_scratch) {
    for (const auto& other : nearest_scratch) scratch.reserveLike(other);
  }
}

void CollisionDetector::Impl::manifoldContact(const btManifoldPoint& pt, const ShapeRecord& r0,
                                              const ShapeRecord& r1,
                                              collision_detail::NearestScratch& nearest,
                                              Contact& c) const {
  // Bullet's body 0 and 1 in A/B order.
  const bool swap = !isA(r0, r1);
  const ShapeRecord& ra = swap ? r1 : r0;
  const ShapeRecord& rb = swap ? r0 : r1;
  c.body_a = ra.body, c.body_b = rb.body;
  c.shape_a = ra.index, c.shape_b = rb.index;
  // Witness points from the local points through the double-precision poses.
  const Vec3 w0 = r0.world.apply(fromBt(pt.m_localPointA) / scale);
  const Vec3 w1 = r1.world.apply(fromBt(pt.m_localPointB) / scale);
  const Vec3 n = fromBt(pt.m_normalWorldOnB).normalized();
  c.witness_a = swap ? w1 : w0;
  c.witness_b = swap ? w0 : w1;
  c.normal = swap ? Vec3(-n) : n;
  // Triangle indices of static meshes, as Bullet reports them.
  const auto bvhTriangle = [](const ShapeRecord& r, int index) {
    return r.shape.type == ShapeType::TriangleMesh && r.body_type != BodyType::Dynamic ? index : -1;
  };
  c.feature_a = bvhTriangle(ra, swap ? pt.m_index1 : pt.m_index0);
  c.feature_b = bvhTriangle(rb, swap ? pt.m_index0 : pt.m_index1);
  c.witness_a = onTrueSurface(ra, c.witness_a, -c.normal, c.feature_a);
  c.witness_b = onTrueSurface(rb, c.witness_b, c.normal, c.feature_b);
  // Hull contacts of meshes: the mesh triangle nearest to the witness point.
  if (const MeshFeatures* f = madeFeaturesOf(ra)) {
    c.feature_a = f->nearestTriangle(ra.world.applyInverse(c.witness_a),
                                     ra.world.rotation.conjugate() * -c.normal, nearest);
  }
  if (const MeshFeatures* f = madeFeaturesOf(rb)) {
    c.feature_b = f->nearestTriangle(rb.world.applyInverse(c.witness_b),
                                     rb.world.rotation.conjugate() * c.normal, nearest);
  }
  // Exact primitive surfaces, the plane's normal, phi and box faces in double.
  finishContact(c, ra.shape, ra.world, rb.shape, rb.world);
}

void CollisionDetector::Impl::collectPlanes() {
  // Mesh features are made on first use, on this thread.
  for (const auto& [r0, r1] : plane_pairs) {
    featuresOf(records[static_cast<size_t>(r0)]);
    featuresOf(records[static_cast<size_t>(r1)]);
  }
  if (plane_contacts.size() < plane_pairs.size()) {
    plane_contacts.resize(plane_pairs.size());
    plane_scratch.resize(plane_pairs.size());
  }
  forEachOn(workers, plane_pairs.size(), 8, [&](size_t k) {
    plane_contacts[k].clear();
    collectPlane(plane_pairs[k].first, plane_pairs[k].second, plane_contacts[k], plane_scratch[k]);
  });
  for (size_t k = 0; k < plane_pairs.size(); ++k)
    contacts.insert(contacts.end(), plane_contacts[k].begin(), plane_contacts[k].end());
}

void CollisionDetector::Impl::collectPlane(int r0, int r1, std::vector<Contact>& out,
                                           collision_detail::PlaneScratch& scratch) const {
  // The plane is always B (its body is static or kinematic, the other one dynamic).
  const bool plane_first = records[static_cast<size_t>(r0)].shape.type == ShapeType::Plane;
  const ShapeRecord& ra = records[static_cast<size_t>(plane_first ? r1 : r0)];
  const ShapeRecord& rb = records[static_cast<size_t>(plane_first ? r0 : r1)];
  if (ra.shape.type == ShapeType::Plane) return;  // two planes never touch
  const WorldPlane plane = worldPlane(rb.shape, rb.world);
  double reach = settings.report_gaps ? gapReach(ra) : 0.0;
  // A fast shape: speculative contacts as far as it can close toward the plane this step, so
  // the solver stops it at the surface instead of a step beyond it (docs/collision.md).
  const double sweep =
      speculative_time * (std::max(0.0, (rb.velocity - ra.velocity).dot(plane.normal)) +
                          ra.angular_speed * ra.bounding_radius);
  if (sweep > 0.25 * ra.size) reach = std::max(reach, sweep);
  for (const PlanePoint& p : planePoints(ra.shape, ra.world, plane, reach, scratch)) {
    Contact c;
    c.body_a = ra.body, c.body_b = rb.body;
    c.shape_a = ra.index, c.shape_b = rb.index;
    c.normal = plane.normal;
    c.witness_a = p.point;
    c.witness_b = p.point - p.distance * plane.normal;
    c.phi = -p.distance;
    c.point = 0.5 * (c.witness_a + c.witness_b);
    if (ra.shape.type == ShapeType::Box) c.feature_a = boxFace(ra.world, -c.normal);
    if (const MeshFeatures* f = madeFeaturesOf(ra)) {
      c.feature_a = f->triangleAtVertex(p.id, ra.world.rotation.conjugate() * -c.normal);
    }
    c.key = contactKey(c, static_cast<uint64_t>(p.id) | kPlanePointTag);
    out.push_back(c);
  }
}

// A box, capsule or sphere against a cylinder's side; false leaves the pair to Bullet.
bool CollisionDetector::Impl::collectCylinderSide(int r0, int r1) {
  const ShapeRecord& x = records[static_cast<size_t>(r0)];
  const ShapeRecord& y = records[static_cast<size_t>(r1)];
  const bool x_cylinder = x.shape.type == ShapeType::Cylinder;
  const ShapeRecord& cyl = x_cylinder ? x : y;
  const ShapeRecord& other = x_cylinder ? y : x;
  if (cyl.shape.type != ShapeType::Cylinder || !isCylinderSideShape(other.shape.type)) {
    return false;
  }
  const double reach = settings.report_gaps ? gapReach(other) : 0.0;
  if (!cylinderSidePoints(cyl.shape, cyl.world, other.shape, other.world, reach, side_points)) {
    return false;
  }
  const bool other_is_a = isA(other, cyl);
  const ShapeRecord& ra = other_is_a ? other : cyl;
  const ShapeRecord& rb = other_is_a ? cyl : other;
  for (const CylinderSidePoint& p : side_points) {
    Contact c;
    c.body_a = ra.body, c.body_b = rb.body;
    c.shape_a = ra.index, c.shape_b = rb.index;
    c.normal = other_is_a ? p.normal : Vec3(-p.normal);
    c.witness_a = other_is_a ? p.on_shape : p.on_cylinder;
    c.witness_b = other_is_a ? p.on_cylinder : p.on_shape;
    finishContact(c, ra.shape, ra.world, rb.shape, rb.world);
    // Gaps are kept: the lifted end of a face along the side (speculative, cylinder_contacts).
    c.key = contactKey(c, static_cast<uint64_t>(p.id) | kCylinderPointTag);
    contacts.push_back(c);
  }
  return true;
}

// Fast shapes against other bodies: a shape that moves more than a quarter of its size this
// step is swept along its velocity; each body it would reach, and does not touch yet, gets a
// speculative contact (phi < 0, the gap at first touch along the normal), so the solver lets it
// close the gap but not pass through a thin wall, a rod or another body (docs/collision.md).
void CollisionDetector::Impl::collectSwept() {
  if (speculative_time <= 0.0 || !world) return;
  // The pairs already in contact, gathered only once a fast shape needs them (a resting pile
  // has none, and thousands of contacts).
  std::vector<std::pair<BodyId, BodyId>>& touching = touching_pairs;
  bool gathered = false;
  for (size_t i = 0; i < records.size(); ++i) {
    const ShapeRecord& r = records[i];
    if (r.body_type != BodyType::Dynamic || !r.bullet.shape->isConvex()) continue;
    const Vec3 displacement = speculative_time * r.velocity;
    if (displacement.norm() <= 0.25 * r.size) continue;
    if (!gathered) {
      touching.clear();
      gatherFound();
      for (const Found& f : found) touching.emplace_back(f.a, f.b);
      std::sort(touching.begin(), touching.end());
      gathered = true;
    }
    const int self = static_cast<int>(i);
    auto accepts = [this, self](int other) {
      return !isPlanePair(self, other) && shouldCollide(self, other);
    };
    SweepHits<decltype(accepts)> sweep(accepts, sweep_hits);
    const btTransform from = toBt(r.world, scale);
    btTransform to = from;
    to.setOrigin(from.getOrigin() + toBt(displacement * scale));
    world->convexSweepTest(static_cast<const btConvexShape*>(r.bullet.shape.get()), from, to,
                           sweep);
    for (const SweepHit& hit : sweep.hits) {
      // Only approaches: a face slid along or a body moved away from needs no contact.
      if (hit.normal.dot(displacement) >= -1e-3 * displacement.norm()) continue;
      const ShapeRecord& other = records[static_cast<size_t>(hit.record)];
      const auto pair =
          isA(r, other) ? std::pair{r.body, other.body} : std::pair{other.body, r.body};
      if (std::binary_search(touching.begin(), touching.end(), pair)) continue;
      contacts.push_back(sweptContact(r, displacement, hit));
    }
  }
}

Contact CollisionDetector::Impl::sweptContact(const ShapeRecord& moving, const Vec3& displacement,
                                              const SweepHit& hit) {
  const ShapeRecord& other = records[static_cast<size_t>(hit.record)];
  const bool moving_is_a = isA(moving, other);
  const ShapeRecord& ra = moving_is_a ? moving : other;
  const ShapeRecord& rb = moving_is_a ? other : moving;
  // The touching points: on the other shape where it is hit, on the moving one where that
  // point of it is now.
  const Vec3 on_other = hit.point / scale;
  const Vec3 on_moving = on_other - hit.fraction * displacement;
  Contact c;
  c.body_a = ra.body, c.body_b = rb.body;
  c.shape_a = ra.index, c.shape_b = rb.index;
  c.normal = moving_is_a ? hit.normal : Vec3(-hit.normal);
  c.witness_a = moving_is_a ? on_moving : on_other;
  c.witness_b = moving_is_a ? on_other : on_moving;
  const bool static_mesh =
      other.shape.type == ShapeType::TriangleMesh && other.body_type != BodyType::Dynamic;
  if (static_mesh) (moving_is_a ? c.feature_b : c.feature_a) = hit.triangle;
  finishContact(c, ra.shape, ra.world, rb.shape, rb.world);
  // Allowed to close the gap and 1 % of its size more: it arrives just inside, where the next
  // step's narrowphase sees a face as a face (several points), not a grazing corner that
  // would leave it spinning on through a thin wall.
  c.phi -= 0.01 * moving.size;
  c.key = contactKey(c, kSweptPointTag);
  return c;
}

CollisionDetector::CollisionDetector() : impl_(std::make_unique<Impl>()) {}
CollisionDetector::~CollisionDetector() = default;

void CollisionDetector::restartPointIds() {
  impl_->next_point_id = 1;
}

void CollisionDetector::setBodies(std::span<const Body> bodies, const CollisionSettings& settings) {
  // Settings first: each bad one named.
  if (settings.sdf_max_contacts < 1) {
    throw Error("collision: sdf_max_contacts must be at least 1");
  }
  if (settings.sdf_resolution < 4) throw Error("collision: sdf_resolution must be at least 4");
  if (!(settings.contact_margin >= 0)) throw Error("collision: contact_margin must be >= 0");
  if (!(settings.sdf_min_spacing >= 0)) throw Error("collision: sdf_min_spacing must be >= 0");
  Impl& s = *impl_;
  s.release();
  s.settings = settings;
  s.scale = bulletScale(bodies);
  s.sdf.reset(settings);
  s.contacts.clear();
  s.sorted.clear();
  s.body_types.clear();
  try {
    s.build(bodies);
  } catch (...) {
    // A shape that cannot be built leaves an empty detector, not half of one.
    s.release();
    s.body_types.clear();
    throw;
  }
}

void CollisionDetector::Impl::build(std::span<const Body> bodies) {
  size_t shape_count = 0;
  for (const Body& b : bodies) shape_count += b.shapes.size();
  createWorld(shape_count);
  // Records for every shape of every body, then the Bullet objects.
  for (size_t b = 0; b < bodies.size(); ++b) {
    body_types.push_back(bodies[b].type);
    addBody(static_cast<BodyId>(b), bodies[b]);
  }
  for (ShapeRecord& rec : records) world->addCollisionObject(rec.object.get());
  prepareSdf();
}

void CollisionDetector::Impl::prepareSdf() {
  // Fields and surface points of dynamic closed meshes now rather than in the first step, and
  // the points of the shapes whose bounding spheres already meet theirs (a bolt through a
  // nut); fields of static meshes and points of shapes met later come on first use.
  if (settings.mesh_pairs != MeshPairMode::Auto) return;
  for (const ShapeRecord& mesh : records) {
    if (!mesh.closed_mesh || mesh.body_type != BodyType::Dynamic) continue;
    sdf.field(mesh);
    sdf.samples(mesh);
    for (const ShapeRecord& other : records) {
      const double reach = mesh.bounding_radius + other.bounding_radius;
      if (other.body != mesh.body && collision_detail::isSdfPair(mesh, other) &&
          (other.world.position - mesh.world.position).squaredNorm() <= reach * reach) {
        sdf.samples(other);
      }
    }
  }
}

void CollisionDetector::Impl::collect(std::span<const Body> bodies, const ThreadPool* pool) {
  if (bodies.size() != body_types.size()) {
    throw Error("collision: detect got " + std::to_string(bodies.size()) +
                " bodies, setBodies had " + std::to_string(body_types.size()));
  }
  // Poses of this call, in double for the contact geometry and in float for Bullet; each
  // record (and its own Bullet object) on its own.
  forEachOn(pool, records.size(), 128, [&](size_t i) {
    ShapeRecord& rec = records[i];
    const Body& body = bodies[rec.body];
    rec.world = body.pose * rec.shape.local;
    if (rec.shape.type == ShapeType::Box) rec.axes = rec.world.rotation.toRotationMatrix();
    rec.object->setWorldTransform(toBt(rec.world, scale));
    rec.velocity = body.pointVelocity(rec.world.position);
    rec.angular_speed = body.angular_velocity.norm();
  });
  contacts.clear();
  manifold_base = manifold_slots = 0;
  plane_pairs.clear();
  sdf_pairs.clear();
  workers = pool;
  // idleBoxPair's lists, one per worker slot, with room for a pair's manifolds from the start.
  const size_t slots = workers ? static_cast<size_t>(workers->concurrency()) : 1;
  while (pair_manifolds.size() < slots) {
    pair_manifolds.emplace_back();
    pair_manifolds.back().list.reserve(4);
  }
  pair_manifolds.resize(slots);
  if (world) detectPairs();
  if (!deferred.empty()) processDeferred();
  if (dispatcher) collectManifolds();
  collectPlanes();
  for (const auto& [r0, r1] : sdf_pairs) {
    sdfPairContacts(records[static_cast<size_t>(r0)], records[static_cast<size_t>(r1)], settings,
                    sdf, contacts);
  }
  collectSwept();
}

const std::vector<Contact>& CollisionDetector::detect(std::span<const Body> bodies) {
  impl_->collect(bodies, nullptr);
  impl_->sortInto(impl_->sorted);
  return impl_->sorted;
}

void CollisionDetector::detect(std::span<const Body> bodies, std::vector<Contact>& out,
                               const ThreadPool* pool) {
  // Straight into the caller's vector: one pass over the contacts fewer than copying them.
  impl_->collect(bodies, pool);
  impl_->sortInto(out);
}

void CollisionDetector::setSpeculativeTime(double seconds) {
  impl_->speculative_time = seconds > 0.0 ? seconds : 0.0;
}

void CollisionDetector::ignorePair(BodyId a, BodyId b) {
  Impl& s = *impl_;
  s.ignored.insert({std::min(a, b), std::max(a, b)});
  if (!s.world) return;
  // Pairs already found stay in Bullet's cache: remove them (and their manifolds) now.
  for (ShapeRecord& x : s.records) {
    if (x.body != a) continue;
    for (ShapeRecord& y : s.records) {
      if (y.body != b) continue;
      s.world->getPairCache()->removeOverlappingPair(
          x.object->getBroadphaseHandle(), y.object->getBroadphaseHandle(), s.dispatcher.get());
    }
  }
}

}  // namespace asperity
