// Which copy of the hot loops runs (simd.hpp).
#include "math/simd.hpp"

#include <atomic>

namespace asperity::simd {

namespace {
std::atomic<bool> forced_baseline{false};
}  // namespace

bool avx2() {
#if ASPERITY_AVX2_COPIES
  static const bool has = __builtin_cpu_supports("avx2");
  return has && !forced_baseline.load(std::memory_order_relaxed);
#else
  return false;
#endif
}

void forceBaseline(bool on) {
  forced_baseline.store(on, std::memory_order_relaxed);
}

}  // namespace asperity::simd
