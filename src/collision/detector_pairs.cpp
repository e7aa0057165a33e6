// Bullet's pair walk for the collision stage (detector_impl.hpp): the broadphase filter, the
// near callback that routes each pair to its contact path, and the box-box narrowphase that
// waits for the pool.
#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "collision/contact_geometry.hpp"
#include "collision/detector_impl.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

using namespace collision_detail;

bool CollisionDetector::Impl::PairFilter::needBroadphaseCollision(btBroadphaseProxy* p0,
                                                                  btBroadphaseProxy* p1) const {
  const auto* o0 = static_cast<const btCollisionObject*>(p0->m_clientObject);
  const auto* o1 = static_cast<const btCollisionObject*>(p1->m_clientObject);
  return impl->shouldCollide(o0->getUserIndex(), o1->getUserIndex());
}

btPersistentManifold* CollisionDetector::Impl::Dispatcher::getNewManifold(
    const btCollisionObject* b0, const btCollisionObject* b1) {
  // A restored pair's algorithm takes the manifold saved for it, in its saved place.
  if (!impl->restored_manifolds.empty()) {
    const auto it = impl->restored_manifolds.find(objectPair(b0, b1));
    if (it != impl->restored_manifolds.end()) {
      btPersistentManifold* restored = it->second;
      impl->restored_manifolds.erase(it);
      return restored;
    }
  }
  btPersistentManifold* m = btCollisionDispatcher::getNewManifold(b0, b1);
  if (impl->settings.contact_margin > 0) {
    m->setContactBreakingThreshold(
        static_cast<btScalar>(impl->settings.contact_margin * impl->scale));
  }
  return m;
}

void CollisionDetector::Impl::Dispatcher::freeCollisionAlgorithm(void* algorithm) {
  if (!impl->lazy_algorithms.empty()) {
    const auto lazy = impl->lazy_algorithms.find(algorithm);
    if (lazy != impl->lazy_algorithms.end()) {
      const auto pending = impl->restored_manifolds.find(lazy->second);
      if (pending != impl->restored_manifolds.end()) {
        releaseManifold(pending->second);
        impl->restored_manifolds.erase(pending);
      }
      impl->lazy_algorithms.erase(lazy);
    }
  }
  btCollisionDispatcher::freeCollisionAlgorithm(algorithm);
}

// Bullet's separating-axis search projects every vertex on every pair of edge directions:
// for a hull of many faces (a scanned model's) against another convex shape GJK/EPA finds
// the axis far faster, and the clipping into contact points that follows is the same.
// (Against a triangle mesh Bullet clips only after its own search, so that stays.)
bool CollisionDetector::Impl::gjkAxisPair(int r0, int r1) const {
  const ShapeRecord& a = records[static_cast<size_t>(r0)];
  const ShapeRecord& b = records[static_cast<size_t>(r1)];
  const auto mesh = [](const ShapeRecord& r) { return r.shape.type == ShapeType::TriangleMesh; };
  return (a.hull_planes.size() > kSatMaxHullFaces || b.hull_planes.size() > kSatMaxHullFaces) &&
         !mesh(a) && !mesh(b);
}

// Bullet's narrowphase for ordinary pairs; plane and signed-distance pairs are only recorded.
void CollisionDetector::Impl::nearCallback(btBroadphasePair& pair, btCollisionDispatcher& d,
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
  if (box_pair) {
    dropStalePoints(pair, self->pair_manifolds[0]);
    btCollisionDispatcher::defaultNearCallback(pair, d, info);
    keepStaleIds(self->pair_manifolds[0]);
    return;
  }
  btCollisionDispatcher::defaultNearCallback(pair, d, info);
}

// Bullet's box-box narrowphase adds the step's corners to the pair's manifold (four points at
// most) and only then drops the points the boxes have slid past. A box sliding farther in a
// step than the breaking threshold (a few mm) brings four new corners to four stale points:
// the manifold, full, replaces points to keep the largest area and may replace a new corner
// with the next, and the refresh then drops the stale ones. Such a box kept two or three of
// its four corners, step after step, and rocked on them. The stale points go first here, by
// Bullet's own refresh; keepStaleIds then gives their ids to the new points that Bullet would
// have put in their places (so the solver's warm start follows them, as before).
void CollisionDetector::Impl::dropStalePoints(btBroadphasePair& pair, ManifoldList& scratch) {
  scratch.stale.clear();
  if (!pair.m_algorithm) return;
  scratch.list.resizeNoInitialize(0);
  pair.m_algorithm->getAllContactManifolds(scratch.list);
  for (int k = 0; k < scratch.list.size(); ++k) {
    btPersistentManifold* m = scratch.list[k];
    const size_t first = scratch.stale.size();
    for (int p = 0; p < m->getNumContacts(); ++p) {
      const btManifoldPoint& pt = m->getContactPoint(p);
      scratch.stale.push_back({m, pt.m_localPointA, pt.m_userPersistentData});
    }
    if (scratch.stale.size() == first) continue;
    m->refreshContactPoints(m->getBody0()->getWorldTransform(), m->getBody1()->getWorldTransform());
    // Those still in the manifold are not stale: only the dropped ones stay listed.
    const auto kept = [m](const StalePoint& s) {
      for (int p = 0; p < m->getNumContacts(); ++p)
        if (m->getContactPoint(p).m_userPersistentData == s.id) return true;
      return false;
    };
    scratch.stale.erase(std::remove_if(scratch.stale.begin() + static_cast<std::ptrdiff_t>(first),
                                       scratch.stale.end(), kept),
                        scratch.stale.end());
  }
}

// A new point takes the id of the stale point nearest to it on body 0 within the breaking
// threshold: the one getCacheEntry would have replaced by it, keeping the id.
void CollisionDetector::Impl::keepStaleIds(ManifoldList& scratch) {
  for (int k = 0; k < scratch.list.size() && !scratch.stale.empty(); ++k) {
    btPersistentManifold* m = scratch.list[k];
    const btScalar reach = m->getContactBreakingThreshold() * m->getContactBreakingThreshold();
    for (int p = 0; p < m->getNumContacts(); ++p) {
      btManifoldPoint& pt = m->getContactPoint(p);
      if (pt.m_userPersistentData) continue;
      StalePoint* nearest = nullptr;
      btScalar best = reach;
      for (StalePoint& s : scratch.stale) {
        if (s.manifold != m || !s.id) continue;
        const btScalar d = (s.local_a - pt.m_localPointA).length2();
        if (d < best) best = d, nearest = &s;
      }
      if (nearest) pt.m_userPersistentData = nearest->id, nearest->id = nullptr;
    }
  }
}

// A box pair whose algorithm and manifold exist (made in pair order, as without this test)
// and whose manifold is empty, with its boxes apart along a face normal by more than
// rounding: the narrowphase would add no point and have none to refresh, so it is skipped.
// In a pile most pairs are such neighbours: the broadphase's boxes, grown by Bullet's
// margins, overlap theirs.
bool CollisionDetector::Impl::idleBoxPair(btBroadphasePair& pair, int r0, int r1,
                                          btManifoldArray& scratch) const {
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
void CollisionDetector::Impl::deferBoxPair(btBroadphasePair& pair, btCollisionDispatcher& d) {
  if (!pair.m_algorithm) {
    auto* o0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject);
    auto* o1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject);
    if (!d.needsCollision(o0, o1)) return;
    const btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0, o0->getWorldTransform(),
                                      -1, -1);
    const btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1, o1->getWorldTransform(),
                                      -1, -1);
    pair.m_algorithm = d.findAlgorithm(&w0, &w1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  }
  if (pair.m_algorithm) deferred.push_back(&pair);
}

void CollisionDetector::Impl::checkPairBudget(const btBroadphasePairArray& pairs) const {
  const int64_t budget = max_pairs;
  if (budget <= 0 || pairs.size() <= budget) return;
  // The bodies in most pairs, most first (ties by id), three at most.
  std::map<BodyId, int64_t> count;
  for (int i = 0; i < pairs.size(); ++i)
    for (const btBroadphaseProxy* p : {pairs[i].m_pProxy0, pairs[i].m_pProxy1})
      ++count[records[static_cast<size_t>(
                          static_cast<const btCollisionObject*>(p->m_clientObject)->getUserIndex())]
                  .body];
  std::vector<std::pair<int64_t, BodyId>> ranked;
  for (const auto& [body, n] : count) ranked.push_back({-n, body});
  std::sort(ranked.begin(), ranked.end());
  std::vector<BodyId> worst;
  std::string counts;
  for (size_t k = 0; k < std::min<size_t>(3, ranked.size()); ++k) {
    worst.push_back(ranked[k].second);
    counts += (k ? ", " : "") + std::to_string(-ranked[k].first);
  }
  throw TooManyPairsError(std::to_string(pairs.size()) + " overlapping shape pairs, more than " +
                              "max_pairs " + std::to_string(budget) + " (pairs of the bodies in " +
                              "most: " + counts + ")",
                          std::move(worst));
}

// Bullet's step (AABBs, broadphase, its walk over the pairs with nearCallback). On several
// threads the walk is ours, over the same pair array in the same order: a box pair goes
// straight to deferBoxPair (a pile's pairs, step after step, are only listed there), not
// through nearCallback's tests of every other kind of pair.
void CollisionDetector::Impl::detectPairs() {
  world->updateAabbs();
  world->computeOverlappingPairs();
  btBroadphasePairArray& pairs = world->getPairCache()->getOverlappingPairArray();
  checkPairBudget(pairs);
  if (!workers || pair_manifolds.size() == 1) {
    // Bullet's own walk (performDiscreteCollisionDetection's last part).
    world->getDispatcher()->dispatchAllCollisionPairs(
        world->getPairCache(), world->getDispatchInfo(), world->getDispatcher());
    return;
  }
  const btDispatcherInfo& info = world->getDispatchInfo();
  for (int i = 0; i < pairs.size(); ++i) {
    btBroadphasePair& pair = pairs[i];
    const int r0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject)->getUserIndex();
    const int r1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject)->getUserIndex();
    if (isBoxPair(r0, r1)) {
      deferBoxPair(pair, *dispatcher);
    } else {
      nearCallback(pair, *dispatcher, info);
    }
  }
}

void CollisionDetector::Impl::processDeferred() {
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
    ManifoldList& scratch = pair_manifolds[static_cast<size_t>(workers->slot())];
    dropStalePoints(pair, scratch);
    const btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0, o0->getWorldTransform(),
                                      -1, -1);
    const btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1, o1->getWorldTransform(),
                                      -1, -1);
    btManifoldResult result(&w0, &w1);
    pair.m_algorithm->processCollision(&w0, &w1, info, &result);
    keepStaleIds(scratch);
  });
  deferred.clear();
}

}  // namespace asperity
