// A signed distance field on a regular grid, built from a closed triangle mesh: the contact
// path for concave meshes (a nut's bore on a bolt) that convex narrowphases cannot see.
//
// Convention: distance < 0 inside the mesh, > 0 outside; the gradient is the outward normal.
// Built as in Bridson's level-set construction: exact point-triangle distances in a narrow
// band around each triangle, closest triangles propagated by fast sweeping, and the sign from
// the parity of ray crossings along +x. Values are trilinearly interpolated between nodes.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

// The triangles re-indexed so that vertices at exactly equal positions share one index (the
// first of them): the topology of a mesh whose vertices are split at UV or normal seams.
std::vector<std::array<int, 3>> weldedTriangles(const TriangleMeshData& mesh);

// True when every edge of the welded mesh (weldedTriangles) is shared by exactly two
// triangles: the mesh bounds a volume, UV seams or not.
bool isClosedMesh(const TriangleMeshData& mesh);

class SignedDistanceField {
 public:
  struct Sample {
    double distance = 0.0;          // m, < 0 inside
    Vec3 gradient = Vec3::UnitZ();  // unit outward normal (mesh frame)
    int triangle = -1;              // closest triangle of the nearest grid node
    bool inside_grid = false;       // false: p is outside the grid, nothing else is set
  };

  // Builds the field in the mesh's frame; `resolution` cells span the longest side of the
  // mesh's bounding box, plus a padding of `padding` cells on every side. Throws Error when
  // the mesh is empty or resolution < 4.
  static std::shared_ptr<const SignedDistanceField> build(const TriangleMeshData& mesh,
                                                          int resolution, int padding = 3);

  // Trilinear value and its gradient at p (mesh frame). A distance at or above `below` comes
  // alone (gradient and triangle left unset): the queries discard such points, most of them.
  Sample sample(const Vec3& p, double below = std::numeric_limits<double>::infinity()) const;
  double cellSize() const { return dx_; }
  const Vec3& origin() const { return origin_; }
  int nodes(int axis) const { return n_[axis]; }
  // Value stored at a grid node.
  double nodeValue(int i, int j, int k) const { return phi_[index(i, j, k)]; }

 private:
  size_t index(int i, int j, int k) const {
    return static_cast<size_t>(i) +
           static_cast<size_t>(n_[0]) *
               (static_cast<size_t>(j) + static_cast<size_t>(n_[1]) * static_cast<size_t>(k));
  }
  void computeBand(const TriangleMeshData& mesh, int band);
  void countCrossings(const TriangleMeshData& mesh, std::vector<int>& crossings) const;
  // The triangles each node tried lately in the sweeps (a ring of kPerNode ids per node).
  class Tried {
   public:
    explicit Tried(size_t nodes);
    // False when the node tried the triangle lately; else remembers it.
    bool insert(size_t node, int triangle) {
      int* ids = &ids_[node * kPerNode];
      for (size_t k = 0; k < kPerNode; ++k)
        if (ids[k] == triangle) return false;
      ids[next_[node]] = triangle;
      next_[node] = static_cast<uint8_t>((next_[node] + 1) % kPerNode);
      return true;
    }

   private:
    static constexpr size_t kPerNode = 4;
    std::vector<int> ids_;
    std::vector<uint8_t> next_;
  };
  void sweep(const TriangleMeshData& mesh, Tried& tried, int di, int dj, int dk);
  void applySigns(const std::vector<int>& crossings);
  Vec3 node(int i, int j, int k) const;

  Vec3 origin_ = Vec3::Zero();
  double dx_ = 1.0;
  int n_[3] = {0, 0, 0};
  std::vector<double> phi_;
  std::vector<int> closest_;
};

// Closest point to p on triangle (a, b, c).
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace asperity
