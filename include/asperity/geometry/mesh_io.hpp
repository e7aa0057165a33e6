// Triangle meshes from Wavefront OBJ files, and their simplification for collision.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "asperity/geometry/shape.hpp"

namespace asperity {

// Loads an OBJ file (polygons are triangulated), scaling positions by `scale`. UVs are kept
// per vertex: an OBJ vertex used with two different UVs becomes two vertices. `uvs` is empty
// when the file has no texture coordinates. Throws Error naming the file when it is missing,
// malformed, has an index out of range or has no faces.
// `object` keeps only the OBJ objects or groups (`o` / `g`) of that name; empty keeps all.
std::shared_ptr<TriangleMeshData> loadObjMesh(const std::string& path, double scale = 1.0,
                                              const std::string& object = "");

// A simplified copy with at most `target_triangles` triangles (meshoptimizer's edge-collapse
// simplifier, then its sloppy one if that cannot get there), unused vertices removed, UVs
// kept. Pairs of triangles folded onto the same three vertices are dropped, so a closed mesh
// stays closed (as the signed-distance collision path needs). Throws Error when
// target_triangles is 0. A mesh already small enough is copied.
std::shared_ptr<TriangleMeshData> simplifyMesh(const TriangleMeshData& mesh,
                                               size_t target_triangles);

}  // namespace asperity
