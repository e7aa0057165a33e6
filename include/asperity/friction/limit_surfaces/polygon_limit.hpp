// Polygon limit surface (SPEC 4): the star-shaped polygon through mu_{d_k} d_k lambda_n,
// k = 0..N-1. A point outside moves to the closest point of the boundary (nearest over all
// edges: the polygon may be non-convex); a point inside stays put (O(1): the wedge from the
// angle, then one triangle test).
#pragma once

#include "asperity/friction/directions.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

struct PolygonLimit {
  DirectionalMu mu;

  static PolygonLimit fromContact(const DirectionalMu& mu, double /*mu0*/) { return {mu}; }

  // Throws asperity::Error when mu.count is outside [4, 64]. `outside` tells whether x moved.
  Vec2 project(const Vec2& x, double lambda_n) const;
  Vec2 project(const Vec2& x, double lambda_n, bool& outside) const {
    const Vec2 p = project(x, lambda_n);
    outside = p != x;
    return p;
  }
};

}  // namespace asperity
