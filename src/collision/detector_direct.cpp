// Contacts the collision stage makes without Bullet's manifolds (detector_impl.hpp): shapes on
// planes (exact points, speculative for fast shapes), boxes, capsules and spheres on a
// cylinder's side, and fast shapes swept over the step against everything else.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "collision/contact_geometry.hpp"
#include "collision/detector_impl.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

using namespace collision_detail;

namespace {

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

}  // namespace asperity
