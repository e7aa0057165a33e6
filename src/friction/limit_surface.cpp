// Limit surfaces (SPEC 4, Eq. 9): projections of a tangential impulse onto the admissible set.
// They run in every PGS iteration: no allocation, and O(1) for points that are already inside.
#include "asperity/friction/limit_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// 2D cross product (z component).
double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Direction d_k (SPEC 1), exact on the axes when N % 4 == 0 so that N = 4 matches the box.
Vec2 computeDirection(int k, int n) {
  if (n % 4 == 0 && k % (n / 4) == 0) {
    static constexpr double kAxes[4][2] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    const int q = k / (n / 4);
    return Vec2(kAxes[q][0], kAxes[q][1]);
  }
  const double angle = 2.0 * kPi * k / n;
  return Vec2(std::cos(angle), std::sin(angle));
}

// d_k from a table built once for every N (the projections must not call sin/cos per edge).
const Vec2& direction(int k, int n) {
  using Row = std::array<Vec2, kMaxDirections>;
  static const std::array<Row, kMaxDirections + 1> table = [] {
    std::array<Row, kMaxDirections + 1> t{};
    for (int count = kMinDirections; count <= kMaxDirections; ++count) {
      for (int i = 0; i < count; ++i) {
        t[static_cast<size_t>(count)][static_cast<size_t>(i)] = computeDirection(i, count);
      }
    }
    return t;
  }();
  return table[static_cast<size_t>(n)][static_cast<size_t>(k)];
}

// The polygon's vertex mu_k d_k scaled by lambda_n (negative coefficients count as 0).
Vec2 vertex(const DirectionalMu& mu, int k, double lambda_n) {
  const int idx = k % mu.count;
  const double radius = std::max(0.0, static_cast<double>(mu.mu[static_cast<size_t>(idx)]));
  return radius * lambda_n * direction(idx, mu.count);
}

// Closest point to x on the segment [p, q].
Vec2 closestOnSegment(const Vec2& x, const Vec2& p, const Vec2& q) {
  const Vec2 e = q - p;
  const double len2 = e.squaredNorm();
  if (len2 <= 0.0) return p;
  const double s = std::clamp((x - p).dot(e) / len2, 0.0, 1.0);
  return p + s * e;
}

}  // namespace

Vec2 CoulombLimit::project(const Vec2& lambda_tb, double lambda_n) const {
  // No normal impulse, no friction.
  if (!(lambda_n > 0.0)) return Vec2::Zero();
  // Scale back onto the disc of radius mu lambda_n when outside.
  const double radius = std::max(0.0, mu) * lambda_n;
  const double norm = lambda_tb.norm();
  if (norm <= radius) return lambda_tb;
  return lambda_tb * (radius / norm);
}

BoxLimit BoxLimit::fromDirectional(const DirectionalMu& mu) {
  BoxLimit box;
  // On the axes the samples are k = 0, N/4, N/2, 3N/4; otherwise use the polygon's radius.
  if (mu.count >= kMinDirections && mu.count <= kMaxDirections && mu.count % 4 == 0) {
    const size_t q = static_cast<size_t>(mu.count / 4);
    box.mu_pos_t = mu.mu[0];
    box.mu_pos_b = mu.mu[q];
    box.mu_neg_t = mu.mu[2 * q];
    box.mu_neg_b = mu.mu[3 * q];
    return box;
  }
  box.mu_pos_t = mu.along(0.0);
  box.mu_pos_b = mu.along(0.5 * kPi);
  box.mu_neg_t = mu.along(kPi);
  box.mu_neg_b = mu.along(1.5 * kPi);
  return box;
}

Vec2 BoxLimit::project(const Vec2& lambda_tb, double lambda_n) const {
  if (!(lambda_n > 0.0)) return Vec2::Zero();
  // Eq. 9 (SPEC signs): lambda_t in [-mu_{-t} ln, mu_{+t} ln], lambda_b likewise.
  const double t = std::clamp(lambda_tb.x(), -std::max(0.0, mu_neg_t) * lambda_n,
                              std::max(0.0, mu_pos_t) * lambda_n);
  const double b = std::clamp(lambda_tb.y(), -std::max(0.0, mu_neg_b) * lambda_n,
                              std::max(0.0, mu_pos_b) * lambda_n);
  return Vec2(t, b);
}

Vec2 PolygonLimit::project(const Vec2& lambda_tb, double lambda_n) const {
  const int n = mu.count;
  if (n < kMinDirections || n > kMaxDirections) {
    throw Error("PolygonLimit::project: direction count " + std::to_string(n) +
                " is outside [4, 64]");
  }
  if (!(lambda_n > 0.0)) return Vec2::Zero();
  // The wedge between d_k and d_k+1 that holds the point, from its angle.
  double angle = std::atan2(lambda_tb.y(), lambda_tb.x());
  if (angle < 0.0) angle += 2.0 * kPi;
  if (!(angle >= 0.0)) angle = 0.0;  // NaN input: keep the index valid, NaN flows through.
  const int k = std::clamp(static_cast<int>(angle * n / (2.0 * kPi)), 0, n - 1);
  const Vec2& d0 = direction(k, n);
  const Vec2& d1 = direction((k + 1) % n, n);
  // x = a d_k + c d_k+1 with a, c >= 0; inside the triangle (0, r0 d_k, r1 d_k+1) iff
  // a r1 + c r0 <= r0 r1 with a <= r0 and c <= r1 (the last two matter when r0 or r1 is 0).
  const double sin_w = cross(d0, d1);
  const double a = cross(lambda_tb, d1) / sin_w;
  const double c = cross(d0, lambda_tb) / sin_w;
  const double r0 = std::max(0.0, static_cast<double>(mu.mu[static_cast<size_t>(k)])) * lambda_n;
  const double r1 =
      std::max(0.0, static_cast<double>(mu.mu[static_cast<size_t>((k + 1) % n)])) * lambda_n;
  if (a * r1 + c * r0 <= r0 * r1 && a <= r0 && c <= r1) return lambda_tb;
  // Outside: the closest point over every edge (the polygon may be non-convex).
  Vec2 best = Vec2::Zero();
  double best_dist = std::numeric_limits<double>::infinity();
  Vec2 p = vertex(mu, 0, lambda_n);
  for (int e = 0; e < n; ++e) {
    const Vec2 q = vertex(mu, e + 1, lambda_n);
    const Vec2 candidate = closestOnSegment(lambda_tb, p, q);
    const double dist = (candidate - lambda_tb).squaredNorm();
    if (dist < best_dist) {
      best_dist = dist;
      best = candidate;
    }
    p = q;
  }
  return best;
}

}  // namespace asperity
