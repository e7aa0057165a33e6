// Sample directions in the contact plane (SPEC 1):
//   d_k = cos(2 pi k / N) t + sin(2 pi k / N) b,  k = 0..N-1.
// With N = 4 they are t, b, -t, -b (the paper's d1..d4, stored in R, G, B, A).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "asperity/math/types.hpp"

namespace asperity {

inline constexpr int kMinDirections = 4;
inline constexpr int kMaxDirections = 64;

// Components (along t, along b) of the N sample directions. Throws asperity::Error unless
// kMinDirections <= n <= kMaxDirections.
std::vector<Vec2> sampleDirections(int n);

// The same directions as a view of a table built once per process (immutable, no allocation
// per call): for per-contact code such as samplers and projections. Throws like
// sampleDirections.
std::span<const Vec2> sampleDirectionsView(int n);

// Per-direction friction coefficients mu_{d_k} of one contact (Eq. 7), k = 0..count-1.
struct DirectionalMu {
  int count = 0;
  std::array<float, kMaxDirections> mu{};

  // All directions set to the same value (isotropic). Throws for n outside [4, 64].
  static DirectionalMu uniform(int n, float value);
  // The coefficient along an arbitrary in-plane angle (radians from t toward b): the radius
  // of the star polygon whose edges interpolate linearly between neighbouring samples
  // mu_k d_k (so BoxLimit::fromDirectional and PolygonLimit agree on the axes). Exactly
  // mu_k on a sample direction. Throws asperity::Error for a count outside [4, 64].
  double along(double angle) const;
};

}  // namespace asperity
