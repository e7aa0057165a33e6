// A contact's surfaces as triangles in the contact frame, for samplers that rasterise on a GPU
// (SPEC 3): the front-facing parts of each shape near the viewing volume, with uv and tangent
// frame per vertex. Box faces and planes are exact; spheres, capsules and cylinders come from a
// fine tessellation (the CPU sampler ray-casts them instead); meshes and hulls via their BVH.
#pragma once

#include <memory>
#include <vector>

#include "sampler/patch_geometry.hpp"

namespace asperity::patch {

// One vertex: contact-frame position (relative to the contact point), uv in repeats (whole
// repeats removed per triangle), the tangent frame (contact frame), and the exact coverage
// test of the source triangle, the same on its three vertices: up to three edges (a, b, c,
// inclusive) with inside at a x + b y + c > 0, or == 0 when inclusive (the CPU sampler's
// top-left rule, evaluated per pixel centre instead of by the rasteriser's fixed-point snap);
// (0, 0, 1, 1) where no edge applies (quad diagonals, planes, mesh triangles).
struct PatchVertex {
  float p[3];
  float uv[2];
  float t[3];
  float b[3];
  float n[3];
  float edges[3][4];
};

// Appends the triangles of `shape` at `pose` that face the other body (geometric normal along
// +n for B, -n for A) and may touch the volume. Triangles keep their winding as seen from
// outside the shape.
void collectTriangles(const Volume& volume, const Shape& shape, const Transform& pose, Side side,
                      MeshCache& meshes, GeometryScratch& scratch, std::vector<PatchVertex>& out);

}  // namespace asperity::patch
