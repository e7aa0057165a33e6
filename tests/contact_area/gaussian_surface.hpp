// Gaussian random height maps of known rms slope for the contact-area tests.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "asperity/math/types.hpp"
#include "asperity/texture/height_map.hpp"

namespace asperity::test {

// An isotropic Gaussian random surface: `modes` cosines with random phases and directions,
// wavelengths between `shortest` and `longest` texels (whole periods across the map, so it
// tiles), scaled to rms slope `slope`. Sums of many independent cosines are Gaussian; the rms
// slope is exact: sum of a_k^2 |k|^2 / 2.
inline HeightMap gaussianSurface(int n, double size, double slope, unsigned seed, double shortest = 6.0,
                          double longest = 48.0, int modes = 160) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  struct Mode {
    int kx, ky;
    double amp, phase;
  };
  std::vector<Mode> picked;
  double slope_sq = 0.0;
  while (static_cast<int>(picked.size()) < modes) {
    const int kx = static_cast<int>(std::lround((unit(rng) * 2 - 1) * n / shortest));
    const int ky = static_cast<int>(std::lround(unit(rng) * n / shortest));
    const double k = std::hypot(kx, ky);  // cycles per map
    if (k < n / longest || k > n / shortest) continue;
    // Amplitude falling as 1/k: a rough spectrum with most slope at short wavelengths.
    const double amp = 1.0 / k;
    const double wavenumber = 2 * kPi * k / size;
    slope_sq += 0.5 * amp * amp * wavenumber * wavenumber;
    picked.push_back({kx, ky, amp, 2 * kPi * unit(rng)});
  }
  const double scale = slope / std::sqrt(slope_sq);
  HeightMap map(n, n);
  for (const Mode& m : picked) {
    // Row by row: cos(a + b) = cos a cos b - sin a sin b keeps it to one cos per texel and mode.
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double arg = 2 * kPi * (m.kx * i + m.ky * j) / n + m.phase;
        map.at(i, j) += static_cast<float>(scale * m.amp * std::cos(arg));
      }
    }
  }
  return map;
}

}  // namespace asperity::test
