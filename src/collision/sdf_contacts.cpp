// Signed-distance contacts (see sdf_contacts.hpp).
#include "collision/sdf_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "math/lanes.hpp"

namespace asperity::collision_detail {

namespace {

// Subdivisions of a triangle so that its longest edge is cut into pieces below `spacing`.
int subdivisions(const Vec3& a, const Vec3& b, const Vec3& c, double spacing) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return std::max(1, static_cast<int>(std::ceil(longest / spacing)));
}

// A point's Morton code: 10 bits per axis over the box `all`, bits interleaved.
uint32_t mortonCode(const Vec3& p, const Eigen::AlignedBox3d& all) {
  const Vec3 size = all.sizes().cwiseMax(1e-300);
  uint32_t code = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double unit = (p[axis] - all.min()[axis]) / size[axis];
    const double scaled = std::isfinite(unit) ? std::clamp(unit * 1023.0, 0.0, 1023.0) : 0.0;
    const auto cell = static_cast<uint32_t>(scaled);
    for (int bit = 0; bit < 10; ++bit) code |= ((cell >> bit) & 1u) << (3 * bit + axis);
  }
  return code;
}

// Whether every point of a block (its box `box` in the points' frame) is certainly unseen by
// the query: its moved box misses the bounds, or its bounding sphere lies beyond the field's
// reach. Both are grown by far more than the rounding of moving one point, so that no point
// that the exact test would keep is skipped. `abs_rotation`: |to_field's rotation matrix|.
bool unseenBlock(const Eigen::AlignedBox3d& box, const Transform& to_field,
                 const Mat3& abs_rotation, const SdfQuery& query, const FieldDistance& field) {
  const Vec3 centre = to_field.apply(box.center());
  const Vec3 half = abs_rotation * (0.5 * box.sizes());
  const double pad = 1e-9 * (1.0 + centre.cwiseAbs().maxCoeff() + half.maxCoeff());
  const Vec3 reach = half.array() + pad;
  const bool misses = ((centre + reach).array() < query.bounds.min().array()).any() ||
                      ((centre - reach).array() > query.bounds.max().array()).any();
  return misses || field.beyond(centre, 0.5 * box.sizes().norm() + pad);
}

}  // namespace

SampleBlocks sampleBlocks(const std::vector<Vec3>& points) {
  SampleBlocks blocks;
  if (points.empty()) return blocks;
  Eigen::AlignedBox3d all(points.front());
  for (const Vec3& p : points) all.extend(p);
  std::vector<std::pair<uint32_t, int>> keyed;
  for (size_t i = 0; i < points.size(); ++i)
    keyed.emplace_back(mortonCode(points[i], all), static_cast<int>(i));
  std::sort(keyed.begin(), keyed.end());
  for (const auto& [code, index] : keyed) {
    blocks.order.push_back(index);
    blocks.points.push_back(points[static_cast<size_t>(index)]);
  }
  for (size_t first = 0; first < points.size(); first += kSampleBlock) {
    Eigen::AlignedBox3d box(blocks.points[first]);
    for (size_t j = first; j < std::min(points.size(), first + kSampleBlock); ++j)
      box.extend(blocks.points[j]);
    blocks.bounds.push_back(box);
  }
  return blocks;
}

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
  out.blocks = sampleBlocks(out.points);
  return out;
}

namespace {

// The point tests of one sdfHits call: a point inside the bounds and not beyond the reach
// (decided in the lanes) becomes a hit when the field puts it below the distance threshold.
class HitTests {
 public:
  HitTests(const FieldDistance& field, const Transform& field_world, const Transform& to_field,
           const SdfQuery& query, std::vector<SdfHit>& hits)
      : field_(field),
        field_world_(field_world),
        query_(query),
        hits_(hits),
        to_field2_(to_field),
        bounds2_(query.bounds) {}

  // Points [first, end), moved two at a time (the bits of to_field.apply); index(j) is the
  // query index of point j. Most points are outside the bounds or beyond a primitive's reach:
  // decided in the lanes, they never leave them.
  template <class Index>
  void testRange(const Vec3* pts, size_t first, size_t end, const Index& index) {
    for (size_t j = first; j < end; j += 2) {
      const size_t k = std::min(j + 1, end - 1);  // an odd last point fills both lanes
      const lanes::Lanes3 local = to_field2_.apply(lanes::of(pts[j], pts[k]));
      const lanes::Mask skip = bounds2_.outside(local) | field_.beyond(local);
      if (lanes::all(skip)) continue;
      if (!skip[0]) test(lanes::lane(local, 0), index(j));
      if (k != j && !skip[1]) test(lanes::lane(local, 1), index(k));
    }
  }

 private:
  // One point in the field's frame, kept when below the distance threshold.
  void test(const Vec3& local, size_t i) {
    const SignedDistanceField::Sample s = field_(local, query_.max_distance);
    if (!s.inside_grid || s.distance >= query_.max_distance) return;
    SdfHit hit;
    hit.vertex = static_cast<int>(i);
    hit.triangle = s.triangle;
    hit.distance = s.distance;
    hit.point = field_world_.apply(local);
    hit.outward = field_world_.rotation * s.gradient;
    // The nearest surface point lies along the gradient by the distance.
    hit.surface = field_world_.apply(local - s.distance * s.gradient);
    hits_.push_back(hit);
  }

  const FieldDistance& field_;
  const Transform& field_world_;
  const SdfQuery& query_;
  std::vector<SdfHit>& hits_;
  const lanes::Transform2 to_field2_;
  const lanes::Box2 bounds2_;
};

// Deepest first, then greedily drop hits too close to a kept one (buffers.hits into kept).
const std::vector<SdfHit>& keepSpreadHits(const SdfQuery& query, SdfHitBuffers& buffers) {
  std::vector<SdfHit>& hits = buffers.hits;
  std::sort(hits.begin(), hits.end(), [](const SdfHit& a, const SdfHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.vertex < b.vertex;
  });
  std::vector<SdfHit>& kept = buffers.kept;
  kept.clear();
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

}  // namespace

const std::vector<SdfHit>& sdfHits(const FieldDistance& field, const Transform& field_world,
                                   std::span<const Vec3> points, const Transform& points_world,
                                   const SdfQuery& query, SdfHitBuffers& buffers,
                                   const SampleBlocks* blocks) {
  // Every query point in the field's frame; keep those below the distance threshold.
  const Transform to_field = field_world.inverse() * points_world;
  buffers.hits.clear();
  HitTests tests(field, field_world, to_field, query, buffers.hits);
  if (blocks == nullptr) {
    tests.testRange(points.data(), 0, points.size(), [](size_t j) { return j; });
  } else {
    // The visiting order does not matter: the hits are sorted below.
    const Mat3 abs_rotation = to_field.rotation.toRotationMatrix().cwiseAbs();
    const auto order = [&](size_t j) { return static_cast<size_t>(blocks->order[j]); };
    for (size_t b = 0; b < blocks->bounds.size(); ++b) {
      if (unseenBlock(blocks->bounds[b], to_field, abs_rotation, query, field)) continue;
      const size_t end = std::min(points.size(), (b + 1) * kSampleBlock);
      tests.testRange(blocks->points.data(), b * kSampleBlock, end, order);
    }
  }
  return keepSpreadHits(query, buffers);
}

}  // namespace asperity::collision_detail
