// The step every friction model ends with (friction_models.hpp).
#include <array>

#include "sampler/models/friction_models.hpp"

namespace asperity::models {

void finishContact(Contact& c, std::span<const double> sums_a, std::span<const double> sums_b,
                   int count, const PatchGains& gains) {
  const int n = static_cast<int>(sums_a.size());
  c.covered_pixels = count;
  // Empty P: the nominal coefficient, counted as a fallback (SPEC 3).
  if (count == 0) {
    c.mu = DirectionalMu::uniform(n, static_cast<float>(gains.mu0));
    c.fallback = true;
    return;
  }
  // Eq. 8: means over P; Eq. 7 through the friction module.
  std::array<double, kMaxDirections> mean_a{}, mean_b{};
  for (int k = 0; k < n; ++k) {
    mean_a[static_cast<size_t>(k)] = sums_a[static_cast<size_t>(k)] / count;
    mean_b[static_cast<size_t>(k)] = sums_b[static_cast<size_t>(k)] / count;
  }
  c.mu = combinePatch(std::span<const double>(mean_a.data(), static_cast<size_t>(n)),
                      std::span<const double>(mean_b.data(), static_cast<size_t>(n)), gains);
  c.fallback = false;
}

}  // namespace asperity::models
