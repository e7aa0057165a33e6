// From shapes to rasterised fragments (patch_geometry.hpp).
#include "sampler/patch_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "asperity/error.hpp"
#include "geometry/shape_mesh_internal.hpp"
#include "sampler/patch_common.hpp"
#include "sampler/patch_faces.hpp"

namespace asperity::patch {

namespace {

Material materialOf(const Shape& shape) {
  return {shape.surface.normal_map.get(), shape.surface.mask.get()};
}

void setFrame(PolygonVertex& v, const Vec3& t, const Vec3& b, const Vec3& n) {
  for (int k = 0; k < 3; ++k) {
    v.tbn[static_cast<size_t>(k)] = t[k];
    v.tbn[static_cast<size_t>(3 + k)] = b[k];
    v.tbn[static_cast<size_t>(6 + k)] = n[k];
  }
}

// A shared face corner (patch_faces.hpp) as the rasteriser's polygon vertex.
PolygonVertex polygonVertex(const FaceCorner& c) {
  PolygonVertex v;
  v.p = c.p;
  v.u = c.u;
  v.v = c.v;
  setFrame(v, c.t, c.b, c.n);
  return v;
}

// Keeps uv small (the texture repeats): subtract the first vertex's whole repeats.
void shiftUv(PolygonVertex* v, int count) {
  const double fu = std::floor(v[0].u), fv = std::floor(v[0].v);
  for (int k = 0; k < count; ++k) v[k].u -= fu, v[k].v -= fv;
}

// A polygon becomes a primitive in two steps (boundPlanar, finishPlanar), so that a box's face
// can be rejected from its corners' positions before its uv and frame are made. Corners go
// counter-clockwise seen from +n: B's front faces already are, A's are reversed.

// A new primitive bounded from its corners' positions (reordered as above); false, and none
// added, when it covers no pixel centre.
bool boundPolygon(const Volume& volume, Vec3* corners, int count, SurfaceRaster& raster) {
  if (raster.side == Side::A) std::reverse(corners, corners + count);
  raster.planars.emplace_back();
  if (boundPlanar(volume, corners, count, raster.planars.back(), raster.depth)) return true;
  raster.planars.pop_back();
  return false;
}

// The primitive boundPolygon added, finished from the same corners with their attributes, and
// rasterised.
void finishPolygon(const Volume& volume, PolygonVertex* v, int count, bool smooth,
                   const Material& material, SurfaceRaster& raster) {
  if (raster.side == Side::A) std::reverse(v, v + count);
  shiftUv(v, count);
  finishPlanar(v, count, smooth, material, raster.planars.back());
  const auto id = static_cast<int32_t>(raster.planars.size() - 1);
  rasterisePlanar(volume, raster.planars.back(), id, raster);
}

void pushPolygon(const Volume& volume, PolygonVertex* v, int count, bool smooth,
                 const Material& material, SurfaceRaster& raster) {
  std::array<Vec3, kMaxPolygonCorners> corners;
  for (int k = 0; k < count; ++k) corners[static_cast<size_t>(k)] = v[k].p;
  if (boundPolygon(volume, corners.data(), count, raster))
    finishPolygon(volume, v, count, smooth, material, raster);
}

// Whether a box face, centred at c with edge half-vectors et and eb (contact frame), surely
// misses the volume: beyond the depth clip (a decision noted in the depth margins), or more
// than a pixel beyond the footprint (where makePlanar rejects it too, at any depth); margins
// far above rounding.
bool faceMissesVolume(const Volume& volume, const Vec3& c, const Vec3& et, const Vec3& eb,
                      SurfaceRaster& raster) {
  const Vec3 reach = et.cwiseAbs() + eb.cwiseAbs();
  const double side = 0.5 * volume.width + volume.pixel;
  if (std::abs(c.x()) - reach.x() > side || std::abs(c.y()) - reach.y() > side) return true;
  return raster.depth.rejectsRange(c.z() - reach.z(), c.z() + reach.z(), volume.half_depth,
                                   1e-9 * volume.width);
}

// Whether a bounding sphere of radius `reach` about the shape's origin misses the volume (a
// miss along n is a depth clip decision).
bool sphereMissesVolume(const Volume& volume, const Placement& pl, double reach,
                        SurfaceRaster& raster) {
  const double half = 0.5 * volume.width;
  if (std::abs(pl.o.x()) > reach + half || std::abs(pl.o.y()) > reach + half) return true;
  return raster.depth.rejectsRange(pl.o.z() - reach, pl.o.z() + reach, volume.half_depth);
}

void rasteriseBox(const Volume& volume, const Shape& shape, const Placement& pl,
                  SurfaceRaster& raster) {
  const double scale = detail::textureScale(shape);
  // Quick reject: the bounding sphere misses the volume.
  if (sphereMissesVolume(volume, pl, shape.half_extents.norm(), raster)) return;
  // Each face that faces the other body and may reach the volume is a quad.
  std::array<BoxFace, 6> faces;
  const int count = facingBoxFaces(shape, pl, raster.side, faces);
  for (int f = 0; f < count; ++f) {
    const BoxFace& face = faces[static_cast<size_t>(f)];
    if (faceMissesVolume(volume, pl.m * face.centre + pl.o, pl.m * face.et, pl.m * face.eb, raster))
      continue;
    // Positions first: a face they reject (a side seen edge-on) needs no uv or frame.
    const std::array<Vec3, 4> positions = boxFacePositions(pl, face);
    std::array<Vec3, 4> bounded = positions;
    if (!boundPolygon(volume, bounded.data(), 4, raster)) continue;
    const std::array<FaceCorner, 4> corners = boxFaceCorners(shape, pl, face, scale, positions);
    PolygonVertex v[4];
    for (size_t k = 0; k < 4; ++k) v[k] = polygonVertex(corners[k]);
    finishPolygon(volume, v, 4, false, materialOf(shape), raster);
  }
}

void rasterisePlane(const Volume& volume, const Shape& shape, const Placement& pl,
                    SurfaceRaster& raster) {
  FacingPlane plane;
  if (!facingPlane(shape, pl, raster.side, plane)) return;
  const Vec3& nc = plane.normal;
  const Vec3& p0 = plane.point;
  Planar prim;
  prim.edge_count = 0;
  // Depth over the contact plane: z = p0.z - (nc.x (x - p0.x) + nc.y (y - p0.y)) / nc.z.
  prim.z = {p0.z() + (nc.x() * p0.x() + nc.y() * p0.y()) / nc.z(), -nc.x() / nc.z(),
            -nc.y() / nc.z()};
  // uv = scale (T, B) . p_local: affine in (x, y) through z(x, y); whole repeats removed.
  auto uvAffine = [&](const Vec3& axis) {
    const Vec3 g = plane.scale * (pl.m * axis);
    Affine a{g.z() * prim.z.c - g.dot(pl.o), g.x() + g.z() * prim.z.dx, g.y() + g.z() * prim.z.dy};
    a.c -= std::floor(a.c);
    return a;
  };
  prim.u = uvAffine(plane.texture.t);
  prim.v = uvAffine(plane.texture.b);
  setFloatUv(prim);
  const Vec3 &tc = plane.t, &bc = plane.b;
  for (int k = 0; k < 3; ++k) {
    prim.tbn[static_cast<size_t>(k)].c = tc[k];
    prim.tbn[static_cast<size_t>(3 + k)].c = bc[k];
    prim.tbn[static_cast<size_t>(6 + k)].c = nc[k];
  }
  prim.frame.col(0) = tc.cast<float>();
  prim.frame.col(1) = bc.cast<float>();
  prim.frame.col(2) = nc.cast<float>();
  prim.i0 = prim.j0 = 0;
  prim.i1 = prim.j1 = volume.resolution - 1;
  prim.material = materialOf(shape);
  raster.planars.push_back(prim);
  rasterisePlanar(volume, raster.planars.back(), static_cast<int32_t>(raster.planars.size() - 1),
                  raster);
}

void rasteriseCurvedShape(const Volume& volume, const Shape& shape, const Placement& pl,
                          SurfaceRaster& raster) {
  // Bounding sphere of the shape about its origin; reject when it misses the volume.
  const double reach = shape.type == ShapeType::Sphere
                           ? shape.radius
                           : std::hypot(shape.radius, shape.half_height) + shape.radius;
  if (sphereMissesVolume(volume, pl, reach, raster)) return;
  raster.depth.forget();  // the ray casts' margins are not tracked
  Curved prim;
  prim.shape = &shape;
  prim.to_local = pl.m.transpose();
  prim.origin_local = -(prim.to_local * pl.o);
  pixelRange(volume, pl.o.x() - reach, pl.o.x() + reach, prim.i0, prim.i1);
  pixelRange(volume, pl.o.y() - reach, pl.o.y() + reach, prim.j0, prim.j1);
  prim.material = materialOf(shape);
  raster.curveds.push_back(prim);
  rasteriseCurved(volume, raster.curveds.back(), static_cast<int32_t>(raster.curveds.size() - 1),
                  raster);
}

void rasteriseMesh(const Volume& volume, const Shape& shape, const Placement& pl, MeshCache& meshes,
                   GeometryScratch& scratch, SurfaceRaster& raster) {
  const CachedMesh& cached = meshes.get(shape);
  raster.depth.forget();  // the query below depends on the depth clip
  // The volume's box in the shape frame (padded), then the triangles whose boxes overlap it.
  Aabb box = volumeBoxInShape(volume, pl);
  const float pad = 1e-6f * static_cast<float>(volume.width);
  box.lo.array() -= pad;
  box.hi.array() += pad;
  scratch.triangles.clear();
  cached.bvh.query(box, scratch.triangles);
  // Each triangle facing the other body, in the contact frame with its attributes.
  const Material material = materialOf(shape);
  for (int index : scratch.triangles) {
    const std::array<FaceCorner, 3> corners = meshTriangleCorners(cached.mesh, index, pl);
    if (!triangleFacesOther(raster.side, corners)) continue;
    PolygonVertex v[3];
    for (size_t k = 0; k < 3; ++k) v[k] = polygonVertex(corners[k]);
    pushPolygon(volume, v, 3, cached.smooth, material, raster);
  }
}

// Spheres, capsules and cylinders: the CPU sampler ray-casts them, the GL sampler meshes them.
bool isCurved(ShapeType type) {
  return type == ShapeType::Sphere || type == ShapeType::Capsule || type == ShapeType::Cylinder;
}

}  // namespace

const CachedMesh& MeshCache::get(const Shape& shape) {
  const bool curved = isCurved(shape.type);
  if (!curved && !shape.mesh) throw Error("patch sampler: mesh shape without mesh data");
  const Key key{curved ? nullptr : shape.mesh.get(), static_cast<int>(shape.type),
                curved ? shape.radius : 0.0,         curved ? shape.half_height : 0.0,
                shape.surface.texture_size,          shape.surface.texture_rotation};
  auto it = entries_.find(key);
  if (it != entries_.end()) return *it->second;
  // First use: triangulate with uv and frames, then the tree.
  auto entry = std::make_unique<CachedMesh>();
  ShapeMeshOptions options;
  options.segments = kCurvedSegments;
  options.rings = kCurvedRings;
  entry->mesh = buildShapeMesh(shape, options);
  entry->bvh = TriangleBvh(entry->mesh.positions, entry->mesh.triangles);
  entry->smooth = curved || (shape.type == ShapeType::TriangleMesh && !shape.mesh->uvs.empty());
  entry->keep_alive = shape.mesh;
  return *entries_.emplace(key, std::move(entry)).first->second;
}

void prepareMeshes(MeshCache& meshes, std::span<const Body> bodies, const Contact& contact,
                   bool meshed_curves) {
  for (const Side side : {Side::A, Side::B}) {
    const ShapeRange range = shapesOf(bodies, contact, side);
    for (int k = range.first; k < range.last; ++k) {
      const Shape& shape = range.body->shapes[static_cast<size_t>(k)];
      const bool meshed =
          shape.type == ShapeType::TriangleMesh || shape.type == ShapeType::ConvexHull;
      if (meshed || (meshed_curves && isCurved(shape.type))) meshes.get(shape);
    }
  }
}

void rasteriseShape(const Volume& volume, const Shape& shape, const Transform& pose,
                    MeshCache& meshes, GeometryScratch& scratch, SurfaceRaster& raster) {
  const Placement pl = place(volume, pose);
  switch (shape.type) {
    case ShapeType::Box:
      rasteriseBox(volume, shape, pl, raster);
      break;
    case ShapeType::Plane:
      rasterisePlane(volume, shape, pl, raster);
      break;
    case ShapeType::Sphere:
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
      rasteriseCurvedShape(volume, shape, pl, raster);
      break;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      rasteriseMesh(volume, shape, pl, meshes, scratch, raster);
      break;
  }
}

}  // namespace asperity::patch
