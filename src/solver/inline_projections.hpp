// Inlined copies of the limit-surface projections (friction/limit_surface.hpp) for the PGS
// inner loop: the same projections as CoulombLimit::project and BoxLimit::project (tests check
// they agree to rounding), but visible to the compiler so the hot loop makes no calls. They
// also report whether the point was outside (the contact slides). The polygon keeps the
// library call: its projection is the expensive part either way.
#pragma once

#include <algorithm>
#include <cmath>

#include "asperity/friction/limit_surface.hpp"

namespace asperity::solver_detail {

// Disc of radius mu lambda_n (SPEC 4, Coulomb).
inline Vec2 projectInline(const CoulombLimit& limit, const Vec2& x, double lambda_n,
                          bool& outside) {
  outside = true;
  if (!(lambda_n > 0.0)) return Vec2::Zero();
  // Inside test on squares: no square root for sticking contacts (the common case).
  const double radius = std::max(0.0, limit.mu) * lambda_n;
  const double norm2 = x.squaredNorm();
  outside = norm2 > radius * radius;
  if (!outside) return x;
  return x * (radius / std::sqrt(norm2));
}

// Box [-mu_{-t} ln, mu_{+t} ln] x [-mu_{-b} ln, mu_{+b} ln] (Eq. 9 with SPEC signs).
inline Vec2 projectInline(const BoxLimit& limit, const Vec2& x, double lambda_n, bool& outside) {
  outside = true;
  if (!(lambda_n > 0.0)) return Vec2::Zero();
  const double t = std::clamp(x.x(), -std::max(0.0, limit.mu_neg_t) * lambda_n,
                              std::max(0.0, limit.mu_pos_t) * lambda_n);
  const double b = std::clamp(x.y(), -std::max(0.0, limit.mu_neg_b) * lambda_n,
                              std::max(0.0, limit.mu_pos_b) * lambda_n);
  outside = t != x.x() || b != x.y();
  return Vec2(t, b);
}

// Star polygon through mu_k d_k lambda_n: the library's projection.
inline Vec2 projectInline(const PolygonLimit& limit, const Vec2& x, double lambda_n,
                          bool& outside) {
  const Vec2 p = limit.project(x, lambda_n);
  outside = p != x;
  return p;
}

}  // namespace asperity::solver_detail
