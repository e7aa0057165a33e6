// Grid signed distance field of a closed triangle mesh (see signed_distance_field.hpp).
#include "collision/signed_distance_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// Twice the signed area of (0,0)-(x1,y1)-(x2,y2), with a symbolic tie-break so that a ray
// through an edge or a vertex is counted by exactly one of the triangles sharing it.
int orientation(double x1, double y1, double x2, double y2, double& twice_area) {
  twice_area = y1 * x2 - x1 * y2;
  if (twice_area > 0) return 1;
  if (twice_area < 0) return -1;
  if (y2 > y1) return 1;
  if (y2 < y1) return -1;
  if (x1 > x2) return 1;
  if (x1 < x2) return -1;
  return 0;
}

// Whether (x0, y0) lies in the 2D triangle; on success a, b, c are its barycentric weights.
bool pointInTriangle2d(double x0, double y0, double x1, double y1, double x2, double y2, double x3,
                       double y3, double& a, double& b, double& c) {
  x1 -= x0, x2 -= x0, x3 -= x0;
  y1 -= y0, y2 -= y0, y3 -= y0;
  const int sign_a = orientation(x2, y2, x3, y3, a);
  if (sign_a == 0) return false;
  if (orientation(x3, y3, x1, y1, b) != sign_a) return false;
  if (orientation(x1, y1, x2, y2, c) != sign_a) return false;
  const double sum = a + b + c;
  a /= sum, b /= sum, c /= sum;
  return true;
}

double triangleDistance(const Vec3& p, const TriangleMeshData& mesh, int t) {
  const auto& tri = mesh.triangles[static_cast<size_t>(t)];
  const Vec3 q = closestPointOnTriangle(p, mesh.vertices[static_cast<size_t>(tri[0])],
                                        mesh.vertices[static_cast<size_t>(tri[1])],
                                        mesh.vertices[static_cast<size_t>(tri[2])]);
  return (p - q).norm();
}

}  // namespace

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Voronoi regions of the vertices, then the edges, then the face (Ericson 5.1.5).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

std::vector<std::array<int, 3>> weldedTriangles(const TriangleMeshData& mesh) {
  // One index per distinct position (exact equality): loaders split vertices at UV seams.
  std::map<std::array<double, 3>, int> first;
  std::vector<int> weld(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    weld[v] = first.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(v)).first->second;
  }
  std::vector<std::array<int, 3>> out;
  out.reserve(mesh.triangles.size());
  for (const auto& tri : mesh.triangles) {
    std::array<int, 3> w{};
    for (size_t c = 0; c < 3; ++c) {
      const int v = tri[c];
      w[c] = v >= 0 && static_cast<size_t>(v) < weld.size() ? weld[static_cast<size_t>(v)] : v;
    }
    out.push_back(w);
  }
  return out;
}

bool isClosedMesh(const TriangleMeshData& mesh) {
  // Count each undirected edge of the welded mesh; a closed 2-manifold uses every edge twice.
  if (mesh.triangles.empty()) return false;
  std::map<std::pair<int, int>, int> edges;
  for (const auto& tri : weldedTriangles(mesh)) {
    for (int e = 0; e < 3; ++e) {
      const int u = tri[static_cast<size_t>(e)], v = tri[static_cast<size_t>((e + 1) % 3)];
      ++edges[{std::min(u, v), std::max(u, v)}];
    }
  }
  return std::all_of(edges.begin(), edges.end(), [](const auto& e) { return e.second == 2; });
}

std::shared_ptr<const SignedDistanceField> SignedDistanceField::build(const TriangleMeshData& mesh,
                                                                      int resolution, int padding) {
  if (mesh.triangles.empty() || mesh.vertices.empty()) {
    throw Error("signed distance field: mesh '" + mesh.source_file + "' has no triangles");
  }
  if (resolution < 4) {
    throw Error("signed distance field: resolution " + std::to_string(resolution) + " is below 4");
  }
  // Grid: the mesh's box, `resolution` cells along its longest side, padded on every side.
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  auto field = std::make_shared<SignedDistanceField>();
  field->dx_ = (hi - lo).maxCoeff() / resolution;
  if (!(field->dx_ > 0)) throw Error("signed distance field: mesh has zero extent");
  // A small irrational shift keeps grid rows off the mesh's vertices and edges.
  field->origin_ = lo - Vec3::Constant((padding + 0.0137) * field->dx_);
  for (int a = 0; a < 3; ++a) {
    field->n_[a] = static_cast<int>(std::ceil((hi[a] - lo[a]) / field->dx_)) + 2 * padding + 2;
  }
  const size_t count = static_cast<size_t>(field->n_[0]) * static_cast<size_t>(field->n_[1]) *
                       static_cast<size_t>(field->n_[2]);
  field->phi_.assign(count, (field->n_[0] + field->n_[1] + field->n_[2]) * field->dx_);
  field->closest_.assign(count, -1);

  // Exact band, then two rounds of the eight sweep orders, then the signs.
  field->computeBand(mesh, 1);
  std::vector<int> crossings(count, 0);
  field->countCrossings(mesh, crossings);
  Tried tried(count);
  for (int pass = 0; pass < 2; ++pass) {
    field->sweep(mesh, tried, +1, +1, +1), field->sweep(mesh, tried, -1, -1, -1);
    field->sweep(mesh, tried, +1, +1, -1), field->sweep(mesh, tried, -1, -1, +1);
    field->sweep(mesh, tried, +1, -1, +1), field->sweep(mesh, tried, -1, +1, -1);
    field->sweep(mesh, tried, +1, -1, -1), field->sweep(mesh, tried, -1, +1, +1);
  }
  field->applySigns(crossings);
  return field;
}

Vec3 SignedDistanceField::node(int i, int j, int k) const {
  return origin_ + dx_ * Vec3(i, j, k);
}

void SignedDistanceField::computeBand(const TriangleMeshData& mesh, int band) {
  // Exact distances on the nodes of each triangle's box grown by `band` cells.
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    Vec3 lo = mesh.vertices[static_cast<size_t>(tri[0])], hi = lo;
    for (int c = 1; c < 3; ++c) {
      lo = lo.cwiseMin(mesh.vertices[static_cast<size_t>(tri[static_cast<size_t>(c)])]);
      hi = hi.cwiseMax(mesh.vertices[static_cast<size_t>(tri[static_cast<size_t>(c)])]);
    }
    int i0[3], i1[3];
    for (int a = 0; a < 3; ++a) {
      i0[a] =
          std::clamp(static_cast<int>(std::floor((lo[a] - origin_[a]) / dx_)) - band, 0, n_[a] - 1);
      i1[a] =
          std::clamp(static_cast<int>(std::ceil((hi[a] - origin_[a]) / dx_)) + band, 0, n_[a] - 1);
    }
    for (int k = i0[2]; k <= i1[2]; ++k) {
      for (int j = i0[1]; j <= i1[1]; ++j) {
        for (int i = i0[0]; i <= i1[0]; ++i) {
          const double d = triangleDistance(node(i, j, k), mesh, static_cast<int>(t));
          const size_t n = index(i, j, k);
          if (d < phi_[n]) phi_[n] = d, closest_[n] = static_cast<int>(t);
        }
      }
    }
  }
}

void SignedDistanceField::countCrossings(const TriangleMeshData& mesh,
                                         std::vector<int>& crossings) const {
  // Each triangle crossed by the +x ray of grid row (j, k) marks the first node past it.
  for (const auto& tri : mesh.triangles) {
    Vec3 f[3];
    for (int c = 0; c < 3; ++c) {
      f[c] = (mesh.vertices[static_cast<size_t>(tri[static_cast<size_t>(c)])] - origin_) / dx_;
    }
    const int j0 = std::clamp(static_cast<int>(std::ceil(std::min({f[0].y(), f[1].y(), f[2].y()}))),
                              0, n_[1] - 1);
    const int j1 = std::clamp(
        static_cast<int>(std::floor(std::max({f[0].y(), f[1].y(), f[2].y()}))), 0, n_[1] - 1);
    const int k0 = std::clamp(static_cast<int>(std::ceil(std::min({f[0].z(), f[1].z(), f[2].z()}))),
                              0, n_[2] - 1);
    const int k1 = std::clamp(
        static_cast<int>(std::floor(std::max({f[0].z(), f[1].z(), f[2].z()}))), 0, n_[2] - 1);
    for (int k = k0; k <= k1; ++k) {
      for (int j = j0; j <= j1; ++j) {
        double a = 0, b = 0, c = 0;
        if (!pointInTriangle2d(j, k, f[0].y(), f[0].z(), f[1].y(), f[1].z(), f[2].y(), f[2].z(), a,
                               b, c)) {
          continue;
        }
        const double fi = a * f[0].x() + b * f[1].x() + c * f[2].x();
        const int i = static_cast<int>(std::ceil(fi));
        if (i < 0) {
          ++crossings[index(0, j, k)];
        } else if (i < n_[0]) {
          ++crossings[index(i, j, k)];
        }
      }
    }
  }
}

SignedDistanceField::Tried::Tried(size_t nodes) : ids_(nodes * kPerNode, -1), next_(nodes, 0) {}

void SignedDistanceField::sweep(const TriangleMeshData& mesh, Tried& tried, int di, int dj,
                                int dk) {
  // Each node tries the closest triangles of its seven upwind neighbours, skipping those it
  // tried lately, in this sweep or an earlier one: phi only falls, so a second try of a
  // triangle cannot lower it (neighbours often share a triangle, and sweeps meet the same ones).
  const int i_begin = di > 0 ? 1 : n_[0] - 2, i_end = di > 0 ? n_[0] : -1;
  const int j_begin = dj > 0 ? 1 : n_[1] - 2, j_end = dj > 0 ? n_[1] : -1;
  const int k_begin = dk > 0 ? 1 : n_[2] - 2, k_end = dk > 0 ? n_[2] : -1;
  const std::ptrdiff_t row = n_[0], slice = static_cast<std::ptrdiff_t>(n_[0]) * n_[1];
  std::ptrdiff_t upwind[7];
  for (int m = 1; m < 8; ++m) {
    upwind[m - 1] = -((m & 1) ? di : 0) - ((m & 2) ? dj * row : 0) - ((m & 4) ? dk * slice : 0);
  }
  for (int k = k_begin; k != k_end; k += dk) {
    for (int j = j_begin; j != j_end; j += dj) {
      auto n = static_cast<std::ptrdiff_t>(index(i_begin, j, k));
      for (int i = i_begin; i != i_end; i += di, n += di) {
        const Vec3 x = node(i, j, k);
        int own = closest_[static_cast<size_t>(n)];
        double best = phi_[static_cast<size_t>(n)];
        for (const std::ptrdiff_t offset : upwind) {
          const int t = closest_[static_cast<size_t>(n + offset)];
          if (t < 0 || t == own || !tried.insert(static_cast<size_t>(n), t)) continue;
          const double d = triangleDistance(x, mesh, t);
          if (d < best) best = d, own = t;
        }
        phi_[static_cast<size_t>(n)] = best;
        closest_[static_cast<size_t>(n)] = own;
      }
    }
  }
}

void SignedDistanceField::applySigns(const std::vector<int>& crossings) {
  // Odd parity of crossings before a node along +x: the node is inside.
  for (int k = 0; k < n_[2]; ++k) {
    for (int j = 0; j < n_[1]; ++j) {
      int total = 0;
      for (int i = 0; i < n_[0]; ++i) {
        total += crossings[index(i, j, k)];
        if (total % 2 == 1) phi_[index(i, j, k)] = -phi_[index(i, j, k)];
      }
    }
  }
}

SignedDistanceField::Sample SignedDistanceField::sample(const Vec3& p, double below) const {
  Sample out;
  // Cell containing p and the local coordinates in it.
  const Vec3 f = (p - origin_) / dx_;
  int c[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    if (!(f[a] >= 0) || f[a] > n_[a] - 1) return out;
    c[a] = std::min(static_cast<int>(f[a]), n_[a] - 2);
    w[a] = f[a] - c[a];
  }
  // Trilinear value and its analytic gradient.
  double v[2][2][2];
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dxi = 0; dxi < 2; ++dxi)
        v[dz][dy][dxi] = phi_[index(c[0] + dxi, c[1] + dy, c[2] + dz)];
  const double x = w[0], y = w[1], z = w[2];
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double v00 = lerp(v[0][0][0], v[0][0][1], x), v10 = lerp(v[0][1][0], v[0][1][1], x);
  const double v01 = lerp(v[1][0][0], v[1][0][1], x), v11 = lerp(v[1][1][0], v[1][1][1], x);
  const double v0 = lerp(v00, v10, y), v1 = lerp(v01, v11, y);
  out.distance = lerp(v0, v1, z);
  out.inside_grid = true;
  if (!(out.distance < below)) return out;
  const double gx = lerp(lerp(v[0][0][1] - v[0][0][0], v[0][1][1] - v[0][1][0], y),
                         lerp(v[1][0][1] - v[1][0][0], v[1][1][1] - v[1][1][0], y), z);
  const double gy = lerp(v10 - v00, v11 - v01, z);
  const double gz = v1 - v0;
  const Vec3 g(gx, gy, gz);
  out.gradient = g.norm() > 0 ? Vec3(g.normalized()) : Vec3(Vec3::UnitZ());
  // Closest triangle of the nearest node.
  const int ni = c[0] + (x > 0.5 ? 1 : 0), nj = c[1] + (y > 0.5 ? 1 : 0),
            nk = c[2] + (z > 0.5 ? 1 : 0);
  out.triangle = closest_[index(ni, nj, nk)];
  return out;
}

}  // namespace asperity
