// Limit surfaces (SPEC 4): the set of admissible tangential impulses (lambda_t, lambda_b) on A
// for a given normal impulse lambda_n >= 0. Each is a small value type with a projection that
// the PGS solver calls in every iteration, so they are cheap and allocation-free.
//
// Convention (SPEC 1): mu_d bounds the friction on A along d: f.d <= mu_d lambda_n.
// Every projection returns (0, 0) for lambda_n <= 0 (or NaN) and treats negative
// coefficients as 0. None allocates; a point already inside is returned unchanged.
#pragma once

#include "asperity/friction/directions.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

enum class LimitSurfaceKind { Coulomb, Box, Polygon };
inline constexpr std::pair<const char*, LimitSurfaceKind> kLimitSurfaceNames[] = {
    {"coulomb", LimitSurfaceKind::Coulomb},
    {"box", LimitSurfaceKind::Box},
    {"polygon", LimitSurfaceKind::Polygon}};

// Isotropic Coulomb disc of radius mu lambda_n.
struct CoulombLimit {
  double mu = 0.0;
  Vec2 project(const Vec2& lambda_tb, double lambda_n) const;
};

// The paper's box (Eq. 9): lambda_t in [-mu_neg_t ln, mu_pos_t ln], same for b.
struct BoxLimit {
  double mu_pos_t = 0.0, mu_pos_b = 0.0, mu_neg_t = 0.0, mu_neg_b = 0.0;
  // Reads +t, +b, -t, -b from a contact's coefficients: k = 0, N/4, N/2, 3N/4, or
  // DirectionalMu::along when N % 4 != 0. Throws for a count outside [4, 64].
  static BoxLimit fromDirectional(const DirectionalMu& mu);
  Vec2 project(const Vec2& lambda_tb, double lambda_n) const;
};

// The star-shaped polygon through mu_{d_k} d_k lambda_n, k = 0..N-1. A point outside moves to
// the closest point of the boundary (nearest over all edges: the polygon may be non-convex);
// a point inside stays put (O(1): the wedge from the angle, then one triangle test).
// project throws asperity::Error when mu.count is outside [4, 64].
struct PolygonLimit {
  DirectionalMu mu;
  Vec2 project(const Vec2& lambda_tb, double lambda_n) const;
};

}  // namespace asperity
