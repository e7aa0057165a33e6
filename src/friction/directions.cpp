// Sample directions (SPEC 1) and the per-direction coefficients of one contact.
#include "asperity/friction/directions.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// Rejects a direction count outside [kMinDirections, kMaxDirections], naming the value.
void checkDirectionCount(int n, const char* what) {
  if (n < kMinDirections || n > kMaxDirections) {
    throw Error(std::string(what) + ": direction count " + std::to_string(n) + " is outside [" +
                std::to_string(kMinDirections) + ", " + std::to_string(kMaxDirections) + "]");
  }
}

// SPEC 1: d_k = cos(2 pi k / N) t + sin(2 pi k / N) b, with t, b, -t, -b exact when
// N % 4 == 0 (so that N = 4 reproduces the box exactly).
Vec2 computeDirection(int k, int n) {
  if (n % 4 == 0 && k % (n / 4) == 0) {
    static constexpr double kAxes[4][2] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    const int q = k / (n / 4);
    return Vec2(kAxes[q][0], kAxes[q][1]);
  }
  const double angle = 2.0 * kPi * k / n;
  return Vec2(std::cos(angle), std::sin(angle));
}

// Every direction set for N in [kMinDirections, kMaxDirections], built on first use.
using DirectionRow = std::array<Vec2, kMaxDirections>;
const std::array<DirectionRow, kMaxDirections + 1>& directionTable() {
  static const std::array<DirectionRow, kMaxDirections + 1> table = [] {
    std::array<DirectionRow, kMaxDirections + 1> t{};
    for (int count = kMinDirections; count <= kMaxDirections; ++count) {
      for (int i = 0; i < count; ++i) {
        t[static_cast<size_t>(count)][static_cast<size_t>(i)] = computeDirection(i, count);
      }
    }
    return t;
  }();
  return table;
}

}  // namespace

std::span<const Vec2> sampleDirectionsView(int n) {
  checkDirectionCount(n, "sampleDirections");
  return std::span<const Vec2>(directionTable()[static_cast<size_t>(n)].data(),
                               static_cast<size_t>(n));
}

std::vector<Vec2> sampleDirections(int n) {
  const std::span<const Vec2> view = sampleDirectionsView(n);
  return std::vector<Vec2>(view.begin(), view.end());
}

DirectionalMu DirectionalMu::uniform(int n, float value) {
  checkDirectionCount(n, "DirectionalMu::uniform");
  DirectionalMu out;
  out.count = n;
  for (int k = 0; k < n; ++k) out.mu[static_cast<size_t>(k)] = value;
  return out;
}

double DirectionalMu::along(double angle) const {
  checkDirectionCount(count, "DirectionalMu::along");
  // Locate the wedge [theta_k, theta_k+1] holding the angle, in units of the wedge width.
  const double two_pi = 2.0 * kPi;
  double wrapped = std::fmod(angle, two_pi);
  if (wrapped < 0.0) wrapped += two_pi;
  const double pos = wrapped * count / two_pi;
  const double nearest = std::round(pos);
  // On a sample direction (up to rounding) the coefficient is the sample itself.
  if (std::abs(pos - nearest) < 1e-9) {
    return mu[static_cast<size_t>(static_cast<int>(nearest) % count)];
  }
  const int k = static_cast<int>(std::floor(pos)) % count;
  const double r0 = std::max(0.0, static_cast<double>(mu[static_cast<size_t>(k)]));
  const double r1 = std::max(0.0, static_cast<double>(mu[static_cast<size_t>((k + 1) % count)]));
  // Radius of the polygon edge from r0 d_k to r1 d_k+1 along the ray: with a the angle from
  // d_k and w the wedge width, r = r0 r1 sin w / (r0 sin a + r1 sin(w - a)).
  const double width = two_pi / count;
  const double a = (pos - std::floor(pos)) * width;
  const double denom = r0 * std::sin(a) + r1 * std::sin(width - a);
  if (denom <= 0.0) return 0.0;
  return r0 * r1 * std::sin(width) / denom;
}

}  // namespace asperity
