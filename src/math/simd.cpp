// Whether the AVX2 copies of the hot loops can run (simd.hpp).
#include "math/simd.hpp"

namespace asperity::simd {

bool avx2Available() {
#if ASPERITY_AVX2_COPIES
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

}  // namespace asperity::simd
