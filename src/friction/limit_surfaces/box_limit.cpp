// The box limit surface's construction from sampled coefficients (Eq. 9, SPEC 4).
#include "asperity/friction/limit_surfaces/box_limit.hpp"

namespace asperity {

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

}  // namespace asperity
