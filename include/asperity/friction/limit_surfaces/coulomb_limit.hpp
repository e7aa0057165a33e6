// Coulomb limit surface (SPEC 4): the isotropic disc of radius mu0 lambda_n, mu0 alone.
#pragma once

#include <algorithm>
#include <cmath>

#include "asperity/friction/directions.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

struct CoulombLimit {
  double mu = 0.0;

  // From a contact: the disc ignores the sampled coefficients and uses mu0.
  static CoulombLimit fromContact(const DirectionalMu& /*mu*/, double mu0) { return {mu0}; }

  // The closest admissible impulse; `outside` tells whether x had to move (the contact slides).
  Vec2 project(const Vec2& x, double lambda_n, bool& outside) const {
    outside = true;
    if (!(lambda_n > 0.0)) return Vec2::Zero();
    // Inside test on squares: no square root for sticking contacts (the common case).
    const double radius = std::max(0.0, mu) * lambda_n;
    const double norm2 = x.squaredNorm();
    outside = norm2 > radius * radius;
    if (!outside) return x;
    return x * (radius / std::sqrt(norm2));
  }
  Vec2 project(const Vec2& x, double lambda_n) const {
    bool outside = false;
    return project(x, lambda_n, outside);
  }
};

}  // namespace asperity
