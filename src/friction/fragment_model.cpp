// The per-fragment friction model (SPEC 2, Eqs. 3 to 6) and the patch aggregate (Eq. 7).
#include "asperity/friction/fragment_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

namespace {

constexpr float kTwoOverPi = static_cast<float>(2.0 / kPi);

}  // namespace

float ploughingTerm(float cos_theta, float mu_max) {
  // Facing away (or NaN) counts as the steepest facet (SPEC 2).
  if (!(cos_theta > 0.0f)) return mu_max;
  // Eq. 6: (2/pi) tan(arccos c) = (2/pi) sqrt(1 - c^2) / c, without arccos near c = 1.
  const float sine = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float term = kTwoOverPi * sine / cos_theta;
  return std::min(term, mu_max);
}

Vec2f ploughingVector(const Vec3f& m, Side side, float mu_max) {
  // Surface B faces +n and keeps m' as is; A faces -n and flips both c and the direction.
  const float sign = side == Side::B ? 1.0f : -1.0f;
  const float height = sign * m.z();
  const Vec2f tangential(m.x(), m.y());
  const float radius = tangential.norm();
  // Unclamped, P m' = (2/pi) (|m_tb| / c) (m_tb / |m_tb|) = (2/pi) m_tb / c: stable as c -> 1
  // and independent of |m|. A fragment parallel to the macro normal lands here with 0.
  if (height > 0.0f && kTwoOverPi * radius <= mu_max * height) {
    return (sign * kTwoOverPi / height) * tangential;
  }
  // Clamped (steep or facing away): mu_max along m'. Recompute |m_tb| in double in case the
  // float squares underflowed (squares of floats are exact in double: no hypot call needed).
  const double x = m.x(), y = m.y();
  const double exact_radius = std::sqrt(x * x + y * y);
  if (!(exact_radius > 0.0)) return Vec2f::Zero();
  const double scale = sign * static_cast<double>(mu_max) / exact_radius;
  return Vec2f(static_cast<float>(scale * m.x()), static_cast<float>(scale * m.y()));
}

float fragmentMu(const Vec3f& m, Side side, const Vec2f& d, float mu_max) {
  // Eqs. 5 and 6: mu_d = max(0, g.d).
  return std::max(0.0f, ploughingVector(m, side, mu_max).dot(d));
}

DirectionalMu combinePatch(std::span<const double> mean_a, std::span<const double> mean_b,
                           const PatchGains& gains) {
  // An empty span stands for a flat surface (all means 0).
  const size_t n = std::max(mean_a.size(), mean_b.size());
  if ((!mean_a.empty() && mean_a.size() != n) || (!mean_b.empty() && mean_b.size() != n)) {
    throw Error("combinePatch: mean_a has " + std::to_string(mean_a.size()) +
                " directions but mean_b has " + std::to_string(mean_b.size()));
  }
  DirectionalMu out = DirectionalMu::uniform(static_cast<int>(n), 0.0f);
  // Eq. 7: mu_d = mu0 + k_A mubar_{d,A} + k_B mubar_{d,B}.
  for (size_t k = 0; k < n; ++k) {
    const double a = mean_a.empty() ? 0.0 : mean_a[k];
    const double b = mean_b.empty() ? 0.0 : mean_b[k];
    out.mu[k] = static_cast<float>(gains.mu0 + gains.k_a * a + gains.k_b * b);
  }
  return out;
}

}  // namespace asperity
