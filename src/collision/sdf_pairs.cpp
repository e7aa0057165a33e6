// Signed-distance pairs (see sdf_pairs.hpp).
#include "collision/sdf_pairs.hpp"

#include <algorithm>
#include <limits>

#include "asperity/geometry/shape_mesh.hpp"
#include "collision/contact_geometry.hpp"
#include "collision/primitive_distance.hpp"

namespace asperity::collision_detail {

namespace {

// Query points per shape (bounds the cost per pair and call).
constexpr size_t kMaxSurfaceSamples = 50000;

// The largest extent of a shape: sample spacing and grid cells are this / resolution.
double largestExtent(const Shape& s) {
  switch (s.type) {
    case ShapeType::Box:
      return 2 * s.half_extents.maxCoeff();
    case ShapeType::Sphere:
      return 2 * s.radius;
    case ShapeType::Capsule:
      return 2 * (s.radius + s.half_height);
    case ShapeType::Cylinder:
      return 2 * std::max(s.radius, s.half_height);
    default:
      break;
  }
  if (!s.mesh || s.mesh->vertices.empty()) return 0.0;
  Vec3 lo = s.mesh->vertices.front(), hi = lo;
  for (const Vec3& v : s.mesh->vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return (hi - lo).maxCoeff();
}

// The box around a primitive grown by `grow` on every side (shape frame).
Eigen::AlignedBox3d primitiveBounds(const Shape& s, double grow) {
  Vec3 h = Vec3::Zero();
  if (s.type == ShapeType::Box) h = s.half_extents;
  if (s.type == ShapeType::Sphere) h = Vec3::Constant(s.radius);
  if (s.type == ShapeType::Capsule) h = Vec3(s.radius, s.radius, s.radius + s.half_height);
  if (s.type == ShapeType::Cylinder) h = Vec3(s.radius, s.radius, s.half_height);
  h.array() += grow;
  return Eigen::AlignedBox3d(-h, h);
}

// A primitive's surface as triangles (the renderer's tessellation, in double).
TriangleMeshData primitiveMesh(const Shape& shape) {
  const ShapeMesh m = buildShapeMesh(shape);
  TriangleMeshData out;
  for (const Vec3f& p : m.positions) out.vertices.push_back(p.cast<double>());
  out.triangles = m.triangles;
  return out;
}

}  // namespace

bool isSdfPair(const ShapeRecord& x, const ShapeRecord& y) {
  const auto concave = [](const ShapeRecord& r) {
    return r.closed_mesh && r.body_type == BodyType::Dynamic;
  };
  const auto partner = [](const ShapeRecord& r) {
    return r.closed_mesh || hasPrimitiveDistance(r.shape.type);
  };
  return (concave(x) && partner(y)) || (concave(y) && partner(x));
}

void SdfResources::reset(const CollisionSettings& settings) {
  if (settings.sdf_resolution != settings_.sdf_resolution) fields_.clear();
  settings_ = settings;
  samples_.clear();
}

const SignedDistanceField& SdfResources::field(const ShapeRecord& r) {
  auto& f = fields_[r.shape.mesh];
  if (!f) f = SignedDistanceField::build(*r.shape.mesh, settings_.sdf_resolution);
  return *f;
}

const SurfaceSamples& SdfResources::samples(const ShapeRecord& r) {
  const auto key = std::make_pair(r.body, r.index);
  auto found = samples_.find(key);
  if (found != samples_.end()) return found->second;
  // Spacing: the size of a grid cell of this shape.
  const double spacing = largestExtent(r.shape) / settings_.sdf_resolution;
  SurfaceSamples s = r.closed_mesh
                         ? surfaceSamples(*r.shape.mesh, spacing, kMaxSurfaceSamples)
                         : surfaceSamples(primitiveMesh(r.shape), spacing, kMaxSurfaceSamples);
  // Triangles of a primitive's tessellation are no features of it.
  if (!r.closed_mesh) std::fill(s.triangle.begin(), s.triangle.end(), -1);
  return samples_.emplace(key, std::move(s)).first->second;
}

namespace {

// Contacts of `query`'s sample points inside `field`'s shape.
void queryContacts(const ShapeRecord& field, const ShapeRecord& query, bool field_is_a,
                   const CollisionSettings& settings, SdfResources& res,
                   std::vector<Contact>& out) {
  // The field: grid for meshes, exact for primitives; spacing and reach in its cells.
  const SignedDistanceField* grid = field.closed_mesh ? &res.field(field) : nullptr;
  const double cell =
      grid ? grid->cellSize() : largestExtent(field.shape) / settings.sdf_resolution;
  SdfQuery q;
  q.max_distance =
      settings.report_gaps ? (settings.contact_margin > 0 ? settings.contact_margin : cell) : 0.0;
  q.max_hits = settings.sdf_max_contacts;
  q.min_spacing = settings.sdf_min_spacing * cell;
  if (grid) {
    const Vec3 span = cell * Vec3(grid->nodes(0) - 1, grid->nodes(1) - 1, grid->nodes(2) - 1);
    q.bounds = Eigen::AlignedBox3d(grid->origin(), grid->origin() + span);
  } else {
    q.bounds = primitiveBounds(field.shape, std::max(q.max_distance, 0.0));
  }
  const FieldDistance distance =
      grid ? FieldDistance::grid(*grid) : FieldDistance::primitive(field.shape, q.max_distance);
  const SurfaceSamples& samples = res.samples(query);
  const ShapeRecord& ra = field_is_a ? field : query;
  const ShapeRecord& rb = field_is_a ? query : field;
  for (const SdfHit& h : sdfHits(distance, field.world, samples.points, query.world, q,
                                 res.hitBuffers(), &samples.blocks)) {
    // The query point is the deepest of its shape; the field gives the nearest surface point.
    Contact c;
    c.body_a = ra.body, c.body_b = rb.body;
    c.shape_a = ra.index, c.shape_b = rb.index;
    const int query_triangle = samples.triangle[static_cast<size_t>(h.vertex)];
    c.witness_a = field_is_a ? h.surface : h.point;
    c.witness_b = field_is_a ? h.point : h.surface;
    c.normal = field_is_a ? Vec3(-h.outward) : h.outward;
    c.feature_a = field_is_a ? h.triangle : query_triangle;
    c.feature_b = field_is_a ? query_triangle : h.triangle;
    // Primitive witnesses onto their exact surfaces, box faces, phi (SPEC 1).
    finishContact(c, ra.shape, ra.world, rb.shape, rb.world);
    if (c.phi < 0 && !settings.report_gaps) continue;
    // Keyed by the query point and the direction of the query.
    c.key = contactKey(
        c, (static_cast<uint64_t>(h.vertex) << 1 | (field_is_a ? 1u : 0u)) | kSdfPointTag);
    out.push_back(c);
  }
}

}  // namespace

void sdfPairContacts(const ShapeRecord& x, const ShapeRecord& y, const CollisionSettings& settings,
                     SdfResources& resources, std::vector<Contact>& out) {
  // Each side's samples against the other's distance.
  const bool x_is_a = isA(x, y);
  queryContacts(x, y, x_is_a, settings, resources, out);
  queryContacts(y, x, !x_is_a, settings, resources, out);
}

}  // namespace asperity::collision_detail
