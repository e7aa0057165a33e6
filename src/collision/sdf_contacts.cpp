// Signed-distance contacts (see sdf_contacts.hpp).
#include "collision/sdf_contacts.hpp"

#include <algorithm>
#include <cmath>

namespace asperity::collision_detail {

namespace {

// Subdivisions of a triangle so that its longest edge is cut into pieces below `spacing`.
int subdivisions(const Vec3& a, const Vec3& b, const Vec3& c, double spacing) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return std::max(1, static_cast<int>(std::ceil(longest / spacing)));
}

}  // namespace

SurfaceSamples surfaceSamples(const TriangleMeshData& mesh, double spacing, size_t max_points) {
  auto vertex = [&](int i) { return mesh.vertices[static_cast<size_t>(i)]; };
  // Coarsen the spacing until the estimated count fits.
  for (int attempt = 0; attempt < 32; ++attempt) {
    size_t estimate = 0;
    for (const auto& t : mesh.triangles) {
      const auto n =
          static_cast<size_t>(subdivisions(vertex(t[0]), vertex(t[1]), vertex(t[2]), spacing));
      estimate += (n + 1) * (n + 2) / 2;
    }
    if (estimate <= max_points) break;
    spacing *= 1.5;
  }
  // Barycentric grid points (i / n, j / n) of every triangle, vertices and edges included.
  SurfaceSamples out;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 a = vertex(mesh.triangles[t][0]), b = vertex(mesh.triangles[t][1]),
               c = vertex(mesh.triangles[t][2]);
    const int n = subdivisions(a, b, c, spacing);
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
        out.points.push_back(a + u * (b - a) + v * (c - a));
        out.triangle.push_back(static_cast<int>(t));
      }
    }
  }
  return out;
}

std::vector<SdfHit> sdfHits(const SignedDistanceField& field, const Transform& field_world,
                            std::span<const Vec3> points, const Transform& points_world,
                            const SdfQuery& query) {
  return sdfHits([&field](const Vec3& p) { return field.sample(p); }, field_world, points,
                 points_world, query);
}

std::vector<SdfHit> sdfHits(const DistanceFn& field, const Transform& field_world,
                            std::span<const Vec3> points, const Transform& points_world,
                            const SdfQuery& query) {
  // Every query point in the field's frame; keep those below the distance threshold.
  const Transform to_field = field_world.inverse() * points_world;
  std::vector<SdfHit> hits;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 local = to_field.apply(points[i]);
    if (!query.bounds.contains(local)) continue;
    const SignedDistanceField::Sample s = field(local);
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
