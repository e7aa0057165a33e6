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
//
// This file: the public class, building Bullet's world from the bodies, one call's order of
// work and its sorted result. The steps of a call live beside it (detector_impl.hpp).
#include "collision/collision_detector.hpp"

#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

#include "asperity/error.hpp"
#include "collision/bullet_shapes.hpp"
#include "collision/detector_impl.hpp"
#include "collision/mesh_features.hpp"
#include "collision/sdf_pairs.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

using namespace collision_detail;

void CollisionDetector::Impl::release() {
  // The world removes its objects' proxies, so it goes before the objects and broadphase.
  restored_manifolds.clear();
  lazy_algorithms.clear();
  world.reset();
  records.clear();
  broadphase.reset();
  dispatcher.reset();
  config.reset();
}

// Deterministic order (SPEC: same input, same contacts): by (body_a, body_b, key), ties in
// the order found. Linear in the contacts: a counting pass buckets them by body_a, then each
// bucket (a body's few contacts) is insertion-sorted by (body_b, key); only small keys move,
// and each contact is copied once (sorting whole contacts, several hundred bytes each, with
// a comparison sort cost more per contact as the pile grew).
void CollisionDetector::Impl::sortInto(std::vector<Contact>& out) {
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
  forEachOn(workers, order.size(), 256, [&](size_t i) { out[i] = *found[order[i].index].contact; });
}

// found: every contact of this call in the order found (see contacts).
void CollisionDetector::Impl::gatherFound() {
  found.clear();
  for (size_t i = 0; i < manifold_base; ++i) found.push_back(foundOf(contacts[i]));
  for (size_t s = 0; s < manifold_slots; ++s)
    if (manifold_found[s].kept) found.push_back(manifold_found[s]);
  for (size_t i = manifold_base; i < contacts.size(); ++i) found.push_back(foundOf(contacts[i]));
}

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

void CollisionDetector::Impl::addBody(BodyId id, const Body& body, BoxPolyhedra& boxes) {
  for (size_t s = 0; s < body.shapes.size(); ++s) {
    ShapeRecord rec;
    rec.body = id;
    rec.index = static_cast<int>(s);
    rec.body_type = body.type;
    rec.shape = body.shapes[s];
    rec.bounding_radius = boundingRadius(rec.shape);
    rec.size = shapeSize(rec.shape);
    rec.bullet = makeBulletShape(scaledShape(rec.shape, scale), body.type, &boxes);
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
  BoxPolyhedra boxes;
  for (size_t b = 0; b < bodies.size(); ++b) {
    body_types.push_back(bodies[b].type);
    addBody(static_cast<BodyId>(b), bodies[b], boxes);
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
  // A box pair's lists (idleBoxPair, dropStalePoints), one per worker slot, with room for a
  // pair's manifolds and points from the start.
  const size_t slots = workers ? static_cast<size_t>(workers->concurrency()) : 1;
  while (pair_manifolds.size() < slots) {
    pair_manifolds.emplace_back();
    pair_manifolds.back().list.reserve(4);
    pair_manifolds.back().stale.reserve(16);
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

void CollisionDetector::setMaxPairs(int64_t pairs) {
  impl_->max_pairs = pairs;
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
