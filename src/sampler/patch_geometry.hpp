// From a body's shapes to the rasteriser's primitives (patch_raster.hpp): box faces as quads
// clipped analytically, planes as one edgeless primitive, spheres, capsules and cylinders by
// ray casting (their exact surface, as the collision stage sees it), convex hulls and triangle
// meshes through a BVH query of their cached shape mesh.
#pragma once

#include <map>
#include <memory>
#include <span>
#include <tuple>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "geometry/bvh.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity::patch {

// A mesh shape's triangles with uv and frames, and its BVH; built once per (mesh data, mapping).
struct CachedMesh {
  ShapeMesh mesh;
  TriangleBvh bvh;
  bool smooth = false;  // per-vertex frames interpolated (meshes with their own UVs)
  std::shared_ptr<const TriangleMeshData> keep_alive;
};

// Tessellation of curved shapes when they are meshed (segments around, rings pole to pole).
// 1024 around keeps a chord within r (pi / 1024)^2 / 2 of the exact surface that the CPU
// sampler ray-casts (0.1 um on a 4 mm bolt, against 1.5 um with 256, enough to move a pixel
// centre across a thin depth clip).
inline constexpr int kCurvedSegments = 1024;
inline constexpr int kCurvedRings = 128;

// Shape meshes by mesh data and mapping; also tessellated spheres, capsules and cylinders.
// get() builds a missing entry: threads may share a cache only for shapes already in it.
class MeshCache {
 public:
  const CachedMesh& get(const Shape& shape);
  size_t size() const { return entries_.size(); }

 private:
  // Mesh data (null for curved shapes), type, radius, half height, texture size, rotation.
  using Key = std::tuple<const TriangleMeshData*, int, double, double, double, double>;
  std::map<Key, std::unique_ptr<CachedMesh>> entries_;
};

// Builds, on the calling thread, every cached mesh that sampling `contact` looks up: mesh and
// hull shapes, and with `meshed_curves` (the GL sampler draws them as triangles) spheres,
// capsules and cylinders too. Threads may then share the cache.
void prepareMeshes(MeshCache& meshes, std::span<const Body> bodies, const Contact& contact,
                   bool meshed_curves);

// Scratch reused between contacts (no allocation per contact once warm).
struct GeometryScratch {
  std::vector<int> triangles;
};

// Rasterises the parts of `shape` (placed at `pose` in the world) that lie in the volume into
// `raster`, keeping only fragments whose geometric normal faces the other body.
void rasteriseShape(const Volume& volume, const Shape& shape, const Transform& pose,
                    MeshCache& meshes, GeometryScratch& scratch, SurfaceRaster& raster);

}  // namespace asperity::patch
