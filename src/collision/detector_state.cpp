// The collision detector's persistence saved and restored bit for bit (World::saveState,
// docs/checkpoints.md). What the next detect depends on is Bullet's as much as ours:
//   - the broadphase's two trees (their shapes decide the order in which new pairs are found),
//     its proxies' boxes and stage lists, and its counters (which pairs the next cleanup checks);
//   - the pair array in its order (the walk makes new manifolds in that order);
//   - which pairs have their algorithm, and every persistent manifold, in the dispatcher's
//     order, with its points as they are (new points' ids are summed in manifold order, and a
//     point's id is its contact's key);
//   - the next point id.
// All of it is reachable through Bullet's public fields and calls; a restored detector is
// first built afresh by setBodies for the same bodies, then given the saved structures.
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/state_stream.hpp"
#include "collision/detector_impl.hpp"

namespace asperity {
namespace {

int recordOf(const btBroadphaseProxy* proxy) {
  return static_cast<const btCollisionObject*>(proxy->m_clientObject)->getUserIndex();
}

void putVector3(StateWriter& out, const btVector3& v) {
  for (int k = 0; k < 3; ++k) out.put<btScalar>(v[k]);
}

btVector3 getVector3(StateReader& in) {
  btVector3 v(0, 0, 0);
  for (int k = 0; k < 3; ++k) v[k] = in.get<btScalar>();
  return v;
}

// A tree in preorder: per node its box, then a leaf's record or an inner node's two children.
void saveNode(StateWriter& out, const btDbvtNode* node) {
  putVector3(out, node->volume.Mins());
  putVector3(out, node->volume.Maxs());
  out.put<uint8_t>(node->isleaf());
  if (node->isleaf()) {
    out.put<int32_t>(recordOf(static_cast<const btBroadphaseProxy*>(node->data)));
    return;
  }
  saveNode(out, node->childs[0]);
  saveNode(out, node->childs[1]);
}

// A saved number Bullet indexes or loops with, checked before it is used.
void checkCounter(const char* name, int64_t value, int64_t lo, int64_t hi) {
  if (value < lo || value > hi)
    throw Error(std::string("the state's broadphase ") + name + " is " + std::to_string(value) +
                ", outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// Whether `leaf` hangs below the tree's root.
bool isLeafOf(const btDbvt& tree, const btDbvtNode* leaf) {
  const btDbvtNode* n = leaf;
  while (n->parent) n = n->parent;
  return n == tree.m_root;
}

// The broadphase's counters, each in the range Bullet keeps it in: the stage it fills next,
// the percentages of leaves and pairs it revisits a step, and ids and indices that only grow
// from 0 (far below where an int would overflow).
void loadCounters(StateReader& in, btDbvtBroadphase& bp, int fixed_leaves) {
  constexpr int64_t kMaxCount = int64_t{1} << 30;
  const std::pair<const char*, std::pair<int64_t, int64_t>> ranges[] = {
      {"stageCurrent", {0, btDbvtBroadphase::STAGECOUNT - 1}},
      {"fupdates", {0, 100}},
      {"dupdates", {0, 100}},
      {"cupdates", {0, 100}},
      {"newpairs", {0, kMaxCount}},
      {"fixedleft", {0, fixed_leaves}},
      {"pid", {0, kMaxCount}},
      {"cid", {0, kMaxCount}},
      {"gid", {0, kMaxCount}}};
  int* counters[] = {&bp.m_stageCurrent, &bp.m_fupdates, &bp.m_dupdates,
                     &bp.m_cupdates,     &bp.m_newpairs, &bp.m_fixedleft,
                     &bp.m_pid,          &bp.m_cid,      &bp.m_gid};
  for (size_t k = 0; k < std::size(counters); ++k) {
    *counters[k] = in.get<int32_t>();
    checkCounter(ranges[k].first, *counters[k], ranges[k].second.first, ranges[k].second.second);
  }
}

}  // namespace

// Tree nodes are allocated as Bullet allocates them (btDbvt frees them the same way).
struct CollisionDetector::Impl::TreeLoader {
  Impl& impl;
  StateReader& in;
  int depth = 0;
  std::vector<uint8_t> placed = std::vector<uint8_t>(impl.records.size(), 0);  // leaf made
  std::vector<btDbvtNode*> made = {};  // every node allocated, for rebuildBroadphase

  btDbvtProxy* proxy(int record) const {
    if (record < 0 || static_cast<size_t>(record) >= impl.records.size())
      throw Error("the state names collision shape " + std::to_string(record) + " of " +
                  std::to_string(impl.records.size()));
    return static_cast<btDbvtProxy*>(
        impl.records[static_cast<size_t>(record)].object->getBroadphaseHandle());
  }

  btDbvtNode* node(btDbvtNode* parent) {
    // Deeper than any tree of 2^31 leaves could be balanced: a corrupt state.
    if (++depth > 4096) throw Error("the state's broadphase tree is corrupt");
    auto* n = new (btAlignedAlloc(sizeof(btDbvtNode), 16)) btDbvtNode();
    made.push_back(n);
    n->parent = parent;
    n->childs[0] = n->childs[1] = nullptr;
    const btVector3 mi = getVector3(in);
    const btVector3 mx = getVector3(in);
    n->volume = btDbvtVolume::FromMM(mi, mx);
    if (in.get<uint8_t>() != 0) {
      const int32_t record = in.get<int32_t>();
      btDbvtProxy* p = proxy(record);
      // Each proxy is one leaf of one tree: a state that says otherwise would have Bullet free
      // a node twice.
      if (placed[static_cast<size_t>(record)]++ != 0)
        throw Error("the state's broadphase trees hold shape " + std::to_string(record) + " twice");
      n->data = p;
      p->leaf = n;
    } else {
      n->childs[0] = node(n);
      n->childs[1] = node(n);
    }
    --depth;
    return n;
  }

  // Each proxy in one stage list, once (a repeat would make a list a loop); returns the list
  // each proxy is in (-1: none).
  std::vector<int> stageLists(btDbvtBroadphase& bp) {
    std::vector<uint8_t> listed(impl.records.size(), 0);
    std::vector<int> list_of(impl.records.size(), -1);
    for (int stage = 0; stage <= btDbvtBroadphase::STAGECOUNT; ++stage) {
      btDbvtProxy*& head = bp.m_stageRoots[stage];
      std::vector<int32_t> list;
      in.getVector(list);
      head = nullptr;
      btDbvtProxy* previous = nullptr;
      for (const int32_t record : list) {
        btDbvtProxy* p = proxy(record);
        if (listed[static_cast<size_t>(record)]++ != 0)
          throw Error("the state's broadphase lists shape " + std::to_string(record) + " twice");
        list_of[static_cast<size_t>(record)] = stage;
        p->links[0] = previous;
        p->links[1] = nullptr;
        (previous ? previous->links[1] : head) = p;
        previous = p;
      }
    }
    return list_of;
  }
};

void CollisionDetector::Impl::saveBroadphase(StateWriter& out) const {
  const btDbvtBroadphase& bp = *broadphase;
  for (const btDbvt& tree : bp.m_sets) {
    out.put<int32_t>(tree.m_lkhd);
    out.put<int32_t>(tree.m_leaves);
    out.put<uint32_t>(tree.m_opath);
    out.put<uint8_t>(tree.m_root != nullptr);
    if (tree.m_root) saveNode(out, tree.m_root);
  }
  // Each stage's list from its head.
  for (const btDbvtProxy* head : bp.m_stageRoots) {
    std::vector<int32_t> list;
    for (const btDbvtProxy* p = head; p; p = p->links[1]) list.push_back(recordOf(p));
    out.putVector(list);
  }
  for (const ShapeRecord& r : records) {
    const auto* p = static_cast<const btDbvtProxy*>(r.object->getBroadphaseHandle());
    putVector3(out, p->m_aabbMin);
    putVector3(out, p->m_aabbMax);
    out.put<int32_t>(p->stage);
    out.put<int32_t>(p->m_uniqueId);
  }
  const int32_t counters[] = {bp.m_stageCurrent, bp.m_fupdates, bp.m_dupdates,
                              bp.m_cupdates,     bp.m_newpairs, bp.m_fixedleft,
                              bp.m_pid,          bp.m_cid,      bp.m_gid};
  for (const int32_t c : counters) out.put(c);
  out.put<uint32_t>(bp.m_updates_call);
  out.put<uint32_t>(bp.m_updates_done);
  out.put<btScalar>(bp.m_updates_ratio);
  out.put<uint8_t>(bp.m_needcleanup);
}

void CollisionDetector::Impl::loadBroadphase(StateReader& in) {
  TreeLoader loader{*this, in};
  try {
    readBroadphase(in, loader);
  } catch (...) {
    rebuildBroadphase(loader);
    throw;
  }
}

void CollisionDetector::Impl::rebuildBroadphase(TreeLoader& loader) {
  btDbvtBroadphase& bp = *broadphase;
  // The loaded nodes go (a tree cut short by the error is not reachable from its root).
  for (btDbvt& tree : bp.m_sets) {
    tree.m_root = nullptr;
    tree.clear();
  }
  for (btDbvtNode* n : loader.made) btAlignedFree(n);
  loader.made.clear();
  for (btDbvtProxy*& head : bp.m_stageRoots) head = nullptr;
  btDbvtProxy* previous = nullptr;
  for (ShapeRecord& r : records) {
    auto* p = static_cast<btDbvtProxy*>(r.object->getBroadphaseHandle());
    p->leaf = bp.m_sets[0].insert(btDbvtVolume::FromMM(p->m_aabbMin, p->m_aabbMax), p);
    p->stage = 0;
    p->links[0] = previous;
    p->links[1] = nullptr;
    (previous ? previous->links[1] : bp.m_stageRoots[0]) = p;
    previous = p;
  }
  bp.m_stageCurrent = 0;
  bp.m_fixedleft = 0;
  bp.m_fupdates = 1, bp.m_dupdates = 0, bp.m_cupdates = 10, bp.m_newpairs = 1, bp.m_cid = 0;
}

void CollisionDetector::Impl::readBroadphase(StateReader& in, TreeLoader& loader) {
  btDbvtBroadphase& bp = *broadphase;
  std::array<int, 2> leaves{};  // as loaded, per tree
  // Both trees emptied first: from here on every node in them is one the loader made.
  for (btDbvt& tree : bp.m_sets) tree.clear();
  for (size_t t = 0; t < 2; ++t) {
    btDbvt& tree = bp.m_sets[t];
    tree.m_lkhd = in.get<int32_t>();
    tree.m_leaves = in.get<int32_t>();
    tree.m_opath = in.get<uint32_t>();
    const auto before = std::count(loader.placed.begin(), loader.placed.end(), 1);
    if (in.get<uint8_t>() != 0) tree.m_root = loader.node(nullptr);
    leaves[t] =
        static_cast<int>(std::count(loader.placed.begin(), loader.placed.end(), 1) - before);
    // Bullet optimises a share of m_leaves each step: a forged count would run without end.
    checkCounter("tree's leaf count", tree.m_leaves, leaves[t], leaves[t]);
  }
  if (std::find(loader.placed.begin(), loader.placed.end(), 0) != loader.placed.end())
    throw Error("the state's broadphase trees miss a collision shape");
  const std::vector<int> list_of = loader.stageLists(bp);
  for (size_t i = 0; i < records.size(); ++i) {
    auto* p = static_cast<btDbvtProxy*>(records[i].object->getBroadphaseHandle());
    p->m_aabbMin = getVector3(in);
    p->m_aabbMax = getVector3(in);
    p->stage = in.get<int32_t>();
    // Ids come from creation order, the same in every world of the scene; Bullet's pair cache
    // hashes pairs by them, so a changed one would leave its pairs unfindable (and a removal
    // loop without end).
    if (in.get<int32_t>() != p->m_uniqueId)
      throw Error("the state's broadphase gives shape " + std::to_string(i) +
                  " another id than this scene's");
    // A proxy's stage names its list, and the fixed stage its tree (Bullet removes it there).
    if (list_of[i] < 0)
      throw Error("the state's broadphase lists shape " + std::to_string(i) + " in no stage");
    checkCounter("proxy's stage", p->stage, list_of[i], list_of[i]);
    const bool fixed_tree = p->leaf != nullptr && isLeafOf(bp.m_sets[1], p->leaf);
    if (fixed_tree != (p->stage == btDbvtBroadphase::STAGECOUNT))
      throw Error("the state's broadphase puts shape " + std::to_string(i) +
                  " in a tree other than its stage's");
  }
  loadCounters(in, bp, leaves[1]);
  bp.m_updates_call = in.get<uint32_t>();
  bp.m_updates_done = in.get<uint32_t>();
  bp.m_updates_ratio = in.get<btScalar>();
  bp.m_needcleanup = in.get<uint8_t>() != 0;
}

// Pairs in the cache's order, each with whether it has its algorithm; then the manifolds in
// the dispatcher's order with their points' bytes (plain numbers and the id: no pointer).
void CollisionDetector::Impl::savePairs(StateWriter& out) const {
  const btBroadphasePairArray& pairs = world->getPairCache()->getOverlappingPairArray();
  out.put<uint64_t>(static_cast<uint64_t>(pairs.size()));
  for (int i = 0; i < pairs.size(); ++i) {
    out.put<int32_t>(recordOf(pairs[i].m_pProxy0));
    out.put<int32_t>(recordOf(pairs[i].m_pProxy1));
    out.put<uint8_t>(pairs[i].m_algorithm != nullptr);
  }
  const int manifolds = dispatcher->getNumManifolds();
  out.put<uint64_t>(static_cast<uint64_t>(manifolds));
  for (int m = 0; m < manifolds; ++m) {
    const btPersistentManifold* mf = dispatcher->getManifoldByIndexInternal(m);
    out.put<int32_t>(mf->getBody0()->getUserIndex());
    out.put<int32_t>(mf->getBody1()->getUserIndex());
    out.put<int32_t>(mf->getNumContacts());
    for (int p = 0; p < mf->getNumContacts(); ++p)
      out.putBytes(&mf->getContactPoint(p), sizeof(btManifoldPoint));
  }
}

void CollisionDetector::Impl::loadPairs(StateReader& in) {
  TreeLoader loader{*this, in};
  btOverlappingPairCache& cache = *world->getPairCache();
  // The pairs the fresh build found go; the saved ones come back in their order.
  while (cache.getNumOverlappingPairs() > 0) {
    btBroadphasePair& last = cache.getOverlappingPairArray()[cache.getNumOverlappingPairs() - 1];
    cache.removeOverlappingPair(last.m_pProxy0, last.m_pProxy1, dispatcher.get());
  }
  struct SavedPair {
    int32_t r0, r1;
    bool algorithm;
  };
  std::vector<SavedPair> pairs(in.count(9));
  for (SavedPair& p : pairs) {
    p.r0 = in.get<int32_t>();
    p.r1 = in.get<int32_t>();
    p.algorithm = in.get<uint8_t>() != 0;
  }
  // Manifolds first, in the saved order; each pair's algorithm then takes its own through
  // Dispatcher::getNewManifold (at once, or at its first narrowphase for the lazy kinds). The
  // points go in last: a mesh pair's algorithm clears the manifold it is given.
  std::vector<btPersistentManifold*> made;
  std::vector<std::vector<btManifoldPoint>> points;
  loadManifolds(in, loader, made, points);
  for (const SavedPair& p : pairs) {
    btBroadphasePair* pair = cache.addOverlappingPair(loader.proxy(p.r0), loader.proxy(p.r1));
    if (!pair) throw Error("the state pairs collision shapes that this scene never pairs");
    if (!p.algorithm) continue;
    auto* o0 = static_cast<btCollisionObject*>(pair->m_pProxy0->m_clientObject);
    auto* o1 = static_cast<btCollisionObject*>(pair->m_pProxy1->m_clientObject);
    const btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0, o0->getWorldTransform(),
                                      -1, -1);
    const btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1, o1->getWorldTransform(),
                                      -1, -1);
    pair->m_algorithm = dispatcher->findAlgorithm(&w0, &w1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
    if (pair->m_algorithm && restored_manifolds.count(objectPair(o0, o1)))
      lazy_algorithms.emplace(pair->m_algorithm, objectPair(o0, o1));
  }
  for (size_t m = 0; m < made.size(); ++m) {
    made[m]->clearManifold();
    for (const btManifoldPoint& point : points[m]) made[m]->addManifoldPoint(point, true);
  }
  if (static_cast<size_t>(dispatcher->getNumManifolds()) != made.size())
    throw Error("the state's contact manifolds do not fit this scene's shapes");
}

void CollisionDetector::Impl::loadManifolds(StateReader& in, const TreeLoader& loader,
                                            std::vector<btPersistentManifold*>& made,
                                            std::vector<std::vector<btManifoldPoint>>& points) {
  const size_t manifolds = in.count(12);
  restored_manifolds.clear();
  lazy_algorithms.clear();
  made.resize(manifolds);
  points.resize(manifolds);
  for (size_t m = 0; m < manifolds; ++m) {
    const btCollisionObject* o0 = objectOf(loader, in.get<int32_t>());
    const btCollisionObject* o1 = objectOf(loader, in.get<int32_t>());
    made[m] = dispatcher->getNewManifold(o0, o1);
    const int count = in.get<int32_t>();
    if (count < 0 || count > MANIFOLD_CACHE_SIZE)
      throw Error("the state's manifold " + std::to_string(m) + " has " + std::to_string(count) +
                  " points");
    points[m].resize(static_cast<size_t>(count));
    for (btManifoldPoint& point : points[m])
      in.getBytes(static_cast<void*>(&point), sizeof(btManifoldPoint));
    restored_manifolds.emplace(objectPair(o0, o1), made[m]);
  }
}

const btCollisionObject* CollisionDetector::Impl::objectOf(const TreeLoader& loader,
                                                           int record) const {
  return static_cast<const btCollisionObject*>(loader.proxy(record)->m_clientObject);
}

}  // namespace asperity

namespace asperity {

void CollisionDetector::saveState(StateWriter& out, bool structures) const {
  const Impl& s = *impl_;
  out.put<uint64_t>(s.next_point_id);
  if (!structures) return;
  out.put<uint64_t>(s.records.size());
  out.put<uint8_t>(s.world != nullptr);
  if (!s.world) return;
  s.saveBroadphase(out);
  s.savePairs(out);
}

void CollisionDetector::loadState(StateReader& in, bool structures) {
  Impl& s = *impl_;
  s.next_point_id = in.get<uint64_t>();
  if (!structures) return;
  in.expect<uint64_t>(s.records.size(), "collision shapes");
  const bool built = in.get<uint8_t>() != 0;
  if (built != (s.world != nullptr))
    throw Error("the state's collision world does not fit this detector");
  if (!built) return;
  s.loadBroadphase(in);
  s.loadPairs(in);
}

}  // namespace asperity
