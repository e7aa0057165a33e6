// Signed-distance contacts (see sdf_contacts.hpp).
#include "collision/sdf_contacts.hpp"

#include <algorithm>

namespace asperity::collision_detail {

std::vector<SdfHit> sdfHits(const SignedDistanceField& field, const Transform& field_world,
                            std::span<const Vec3> points, const Transform& points_world,
                            const SdfQuery& query) {
  // Every query point in the field's frame; keep those below the distance threshold.
  const Transform to_field = field_world.inverse() * points_world;
  std::vector<SdfHit> hits;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 local = to_field.apply(points[i]);
    const SignedDistanceField::Sample s = field.sample(local);
    if (!s.inside_grid || s.distance >= query.max_distance) continue;
    SdfHit hit;
    hit.vertex = static_cast<int>(i);
    hit.triangle = s.triangle;
    hit.distance = s.distance;
    hit.point = field_world.apply(local);
    hit.outward = field_world.rotation * s.gradient;
    // The nearest surface point lies along the gradient by the distance.
    hit.surface = field_world.apply(local - s.distance * s.gradient);
    hits.push_back(hit);
  }
  // Deepest first, then greedily drop hits too close to a kept one.
  std::sort(hits.begin(), hits.end(), [](const SdfHit& a, const SdfHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.vertex < b.vertex;
  });
  std::vector<SdfHit> kept;
  const double spacing2 = query.min_spacing * query.min_spacing;
  for (const SdfHit& h : hits) {
    if (static_cast<int>(kept.size()) >= query.max_hits) break;
    const bool crowded = std::any_of(kept.begin(), kept.end(), [&](const SdfHit& k) {
      return (k.point - h.point).squaredNorm() < spacing2;
    });
    if (!crowded) kept.push_back(h);
  }
  return kept;
}

}  // namespace asperity::collision_detail
