// The paper's box limit surface (Eq. 9, SPEC 4): lambda_t in [-mu_{-t} ln, mu_{+t} ln], lambda_b
// likewise, from the coefficients along +t, +b, -t and -b.
#pragma once

#include <algorithm>

#include "asperity/friction/directions.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

struct BoxLimit {
  double mu_pos_t = 0.0, mu_pos_b = 0.0, mu_neg_t = 0.0, mu_neg_b = 0.0;

  // Reads +t, +b, -t, -b from a contact's coefficients: k = 0, N/4, N/2, 3N/4, or
  // DirectionalMu::along when N % 4 != 0. Throws for a count outside [4, 64].
  static BoxLimit fromDirectional(const DirectionalMu& mu);
  static BoxLimit fromContact(const DirectionalMu& mu, double /*mu0*/) {
    return fromDirectional(mu);
  }

  // The closest admissible impulse (a clamp per axis); `outside` tells whether x moved.
  Vec2 project(const Vec2& x, double lambda_n, bool& outside) const {
    outside = true;
    if (!(lambda_n > 0.0)) return Vec2::Zero();
    const double t =
        std::clamp(x.x(), -std::max(0.0, mu_neg_t) * lambda_n, std::max(0.0, mu_pos_t) * lambda_n);
    const double b =
        std::clamp(x.y(), -std::max(0.0, mu_neg_b) * lambda_n, std::max(0.0, mu_pos_b) * lambda_n);
    outside = t != x.x() || b != x.y();
    return Vec2(t, b);
  }
  Vec2 project(const Vec2& x, double lambda_n) const {
    bool outside = false;
    return project(x, lambda_n, outside);
  }
};

}  // namespace asperity
