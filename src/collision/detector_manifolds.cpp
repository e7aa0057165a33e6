// Bullet's manifold points into contacts (detector_impl.hpp): witness points from the
// manifold's local points through the double-precision poses, put back onto the true surfaces
// (Bullet's margins removed), mesh triangles as features, and persistent ids for the keys.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>

#include "collision/contact_geometry.hpp"
#include "collision/detector_impl.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

// collectManifolds makes contacts anew in slots that held others (std::construct_at).
static_assert(std::is_trivially_destructible_v<Contact>);

using namespace collision_detail;

namespace {

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

}  // namespace

namespace {

btPersistentManifold* manifoldAt(btDispatcher& dispatcher, size_t m) {
  return dispatcher.getManifoldByIndexInternal(static_cast<int>(m));
}

}  // namespace

// Manifold points into contacts, on the pool when there is one: features first, then each
// manifold's slots and new ids, then every manifold converted into its own slots.
void CollisionDetector::Impl::collectManifolds() {
  makeManifoldFeatures();
  countManifoldPoints();
  // Then every manifold on the pool: its new points numbered in order (the ids a serial pass
  // in manifold order would give, on any thread count; Bullet keeps them while a point is
  // matched), and its points converted into its own slots (new, default Contacts).
  const size_t manifolds = manifold_first.size() - 1;
  manifold_base = contacts.size();
  manifold_slots = manifold_first[manifolds];
  const uint64_t first_id = next_point_id;
  next_point_id += manifold_new[manifolds];
  if (manifold_contacts.size() < manifold_slots) {
    manifold_contacts.resize(manifold_slots);
    manifold_found.resize(manifold_slots);
  }
  nearest_scratch.resize(workers ? static_cast<size_t>(workers->concurrency()) : 1);
  forEachOn(workers, manifolds, 32, [&](size_t m) { convertManifold(m, first_id); });
  // Whichever thread converts a mesh's contacts next finds buffers large enough.
  for (auto& scratch : nearest_scratch) {
    for (const auto& other : nearest_scratch) scratch.reserveLike(other);
  }
}

void CollisionDetector::Impl::makeManifoldFeatures() {
  // Mesh features are made on first use, on this thread (hulls and dynamic meshes only).
  if (!std::any_of(records.begin(), records.end(), hasFeatures)) return;
  const auto count = static_cast<size_t>(dispatcher->getNumManifolds());
  for (size_t m = 0; m < count; ++m) {
    const btPersistentManifold* mf = manifoldAt(*dispatcher, m);
    featuresOf(records[static_cast<size_t>(mf->getBody0()->getUserIndex())]);
    featuresOf(records[static_cast<size_t>(mf->getBody1()->getUserIndex())]);
  }
}

void CollisionDetector::Impl::countManifoldPoints() {
  // Each manifold's points and new points (without a persistent id yet), counted per manifold
  // on the pool, then summed in manifold order: a manifold's first slot and its first new id.
  const auto manifolds = static_cast<size_t>(dispatcher->getNumManifolds());
  manifold_first.resize(manifolds + 1);
  manifold_new.resize(manifolds + 1);
  forEachOn(workers, manifolds, 64, [&](size_t m) {
    const btPersistentManifold* mf = manifoldAt(*dispatcher, m);
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
}

// Manifold m's points into its slots, its new points numbered from first_id + manifold_new[m].
void CollisionDetector::Impl::convertManifold(size_t m, uint64_t first_id) {
  btPersistentManifold* mf = manifoldAt(*dispatcher, m);
  auto& nearest = nearest_scratch[workers ? static_cast<size_t>(workers->slot()) : 0];
  const ShapeRecord& r0 = records[static_cast<size_t>(mf->getBody0()->getUserIndex())];
  const ShapeRecord& r1 = records[static_cast<size_t>(mf->getBody1()->getUserIndex())];
  uint64_t id = first_id + manifold_new[m];
  for (int p = 0; p < mf->getNumContacts(); ++p) {
    btManifoldPoint& pt = mf->getContactPoint(p);
    if (!pt.m_userPersistentData)
      pt.m_userPersistentData = reinterpret_cast<void*>(static_cast<uintptr_t>(id++));
    const size_t slot = manifold_first[m] + static_cast<size_t>(p);
    Contact& c = *std::construct_at(&manifold_contacts[slot]);  // a default Contact again
    manifoldContact(pt, r0, r1, nearest, c);
    c.key =
        contactKey(c, static_cast<uint64_t>(reinterpret_cast<uintptr_t>(pt.m_userPersistentData)));
    manifold_found[slot] = foundOf(c);
    manifold_found[slot].kept = settings.report_gaps || c.phi >= 0;
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

}  // namespace asperity
