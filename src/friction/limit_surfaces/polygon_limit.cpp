// The polygon limit surface's projection (SPEC 4). It runs in every PGS iteration: no
// allocation, and O(1) for points that are already inside.
#include "asperity/friction/limit_surfaces/polygon_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// 2D cross product (z component).
double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The coefficient mu_k scaled by lambda_n (negative coefficients count as 0).
double radius(const DirectionalMu& mu, int k, double lambda_n) {
  return std::max(0.0, static_cast<double>(mu.mu[static_cast<size_t>(k % mu.count)])) * lambda_n;
}

// Closest point to x on the segment [p, q].
Vec2 closestOnSegment(const Vec2& x, const Vec2& p, const Vec2& q) {
  const Vec2 e = q - p;
  const double len2 = e.squaredNorm();
  if (len2 <= 0.0) return p;
  const double s = std::clamp((x - p).dot(e) / len2, 0.0, 1.0);
  return p + s * e;
}

// O(1) membership: find the wedge [d_k, d_k+1] from the angle, then test the triangle
// (0, r0 d_k, r1 d_k+1). With x = a d_k + c d_k+1 (a, c >= 0) it is inside iff
// a r1 + c r0 <= r0 r1, a <= r0 and c <= r1 (the last two matter when r0 or r1 is 0).
bool insideStar(const DirectionalMu& mu, std::span<const Vec2> dirs, const Vec2& x,
                double lambda_n) {
  const int n = mu.count;
  double angle = std::atan2(x.y(), x.x());
  if (angle < 0.0) angle += 2.0 * kPi;
  if (!(angle >= 0.0)) angle = 0.0;  // NaN input: keep the index valid, NaN flows through.
  const int k = std::clamp(static_cast<int>(angle * n / (2.0 * kPi)), 0, n - 1);
  const Vec2& d0 = dirs[static_cast<size_t>(k)];
  const Vec2& d1 = dirs[static_cast<size_t>((k + 1) % n)];
  const double sin_w = cross(d0, d1);
  const double a = cross(x, d1) / sin_w;
  const double c = cross(d0, x) / sin_w;
  const double r0 = radius(mu, k, lambda_n), r1 = radius(mu, k + 1, lambda_n);
  return a * r1 + c * r0 <= r0 * r1 && a <= r0 && c <= r1;
}

// The closest point of the boundary, over every edge (the polygon may be non-convex).
Vec2 closestBoundaryPoint(const DirectionalMu& mu, std::span<const Vec2> dirs, const Vec2& x,
                          double lambda_n) {
  Vec2 best = Vec2::Zero();
  double best_dist = std::numeric_limits<double>::infinity();
  Vec2 p = radius(mu, 0, lambda_n) * dirs[0];
  for (int e = 0; e < mu.count; ++e) {
    const int next = (e + 1) % mu.count;
    const Vec2 q = radius(mu, next, lambda_n) * dirs[static_cast<size_t>(next)];
    const Vec2 candidate = closestOnSegment(x, p, q);
    const double dist = (candidate - x).squaredNorm();
    if (dist < best_dist) {
      best_dist = dist;
      best = candidate;
    }
    p = q;
  }
  return best;
}

}  // namespace

Vec2 PolygonLimit::project(const Vec2& lambda_tb, double lambda_n) const {
  // A default-constructed DirectionalMu (count 0) is a caller's bug: say so.
  if (mu.count < kMinDirections || mu.count > kMaxDirections) {
    throw Error("PolygonLimit::project: direction count " + std::to_string(mu.count) +
                " is outside [" + std::to_string(kMinDirections) + ", " +
                std::to_string(kMaxDirections) + "]");
  }
  const std::span<const Vec2> dirs = sampleDirectionsView(mu.count);
  if (!(lambda_n > 0.0)) return Vec2::Zero();
  // SPEC 4, polygon: inside stays put, outside goes to the closest boundary point.
  if (insideStar(mu, dirs, lambda_tb, lambda_n)) return lambda_tb;
  return closestBoundaryPoint(mu, dirs, lambda_tb, lambda_n);
}

}  // namespace asperity
