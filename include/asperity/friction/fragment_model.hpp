// The per-fragment friction model (SPEC 2, Eqs. 3 to 6) and the patch aggregate (Eqs. 7, 8).
//
// Everything is expressed in the contact frame (t, b, n); n points from B toward A (SPEC 1).
// A fragment's meso normal m is given in that frame. For surface B (facing +n):
//   c = n.m, theta = arccos(c), m' = normalize(m - c n), mu_{d,B} = max(0, m'.d) (2/pi) tan theta
// For surface A (facing -n): c = -n.m and mu_{d,A} = max(0, -m'.d) (2/pi) tan theta.
// The ploughing term (2/pi) tan theta is clamped to mu_max.
//
// Both reduce to one form: mu_d = max(0, g.d) with the fragment's "ploughing vector"
//   g_B = P m'   and   g_A = -P m'   (P = clamped ploughing term),
// which is what the kernels store: two floats per fragment, whatever N is.
#pragma once

#include <span>
#include <vector>

#include "asperity/friction/directions.hpp"
#include "asperity/math/simd_copy.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

inline constexpr float kDefaultMuMax = 4.0f;

enum class Side { A, B };

// The clamped ploughing term (2/pi) tan(arccos(c)) for c = cos(theta); c <= 0 gives mu_max.
float ploughingTerm(float cos_theta, float mu_max = kDefaultMuMax);

// The ploughing vector g (components along t and b) of one fragment of surface `side`.
// A fragment parallel to its macro normal gives (0, 0).
Vec2f ploughingVector(const Vec3f& m_contact_frame, Side side, float mu_max = kDefaultMuMax);

// mu_{d} of one fragment (Eq. 5 / 6): max(0, g.d).
float fragmentMu(const Vec3f& m_contact_frame, Side side, const Vec2f& d,
                 float mu_max = kDefaultMuMax);

// The hot kernel: sums[k] += sum_i max(0, gx[i] dx_k + gy[i] dy_k) for every direction k.
// gx, gy have equal length; sums has directions.size() entries (asperity::Error otherwise).
// Any length and any direction count; float partial sums per chunk, flushed into double.
// `copy` picks the compiled copy of the loop (the same bits either way).
void accumulateDirectionalSums(std::span<const float> gx, std::span<const float> gy,
                               std::span<const Vec2> directions, std::span<double> sums,
                               SimdCopy copy = SimdCopy::Auto);

// Eq. 7 from per-surface means (Eq. 8): mu_d = mu0 + k_A mubar_{d,A} + k_B mubar_{d,B}.
// (Per-texel gain masks are folded into the fragments' g before averaging, with k = 1.)
struct PatchGains {
  double mu0 = 0.0;
  double k_a = 1.0;
  double k_b = 1.0;
};
// An empty span stands for a flat surface (all means 0); otherwise both have the same size,
// in [4, 64] (asperity::Error otherwise).
DirectionalMu combinePatch(std::span<const double> mean_a, std::span<const double> mean_b,
                           const PatchGains& gains);

}  // namespace asperity
