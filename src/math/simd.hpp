// Hot float loops compiled twice, for AVX2 and for baseline x86-64, the AVX2 copy taken where
// the processor has it. Neither copy may use fused multiply-adds (target "avx2" enables none)
// and each vector lane takes the operations of the scalar code, so both give the same bits:
// tests/math/simd_test.cpp runs scenes both ways and compares their state hashes.
//
// A function `f` is written once as an always-inlined `fBody`; ASPERITY_TARGET_AVX2 marks the
// copy `fAvx2` that calls it, compiled with AVX2 through the inlining, and `f` picks one with
// simd::avx2(copy), `copy` being its caller's option (asperity/math/simd_copy.hpp) carried down
// the calls. GCC on x86-64 only (elsewhere, and in the clang sanitizer build, `f` is the body
// alone).
#pragma once

#include "asperity/math/simd_copy.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define ASPERITY_AVX2_COPIES 1
#define ASPERITY_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define ASPERITY_AVX2_COPIES 0
#endif

namespace asperity::simd {

// Whether this build has the AVX2 copies and the processor runs AVX2.
bool avx2Available();
// Whether `copy` runs the AVX2 copies: Auto where they are available, Baseline never.
inline bool avx2(SimdCopy copy) {
  return copy == SimdCopy::Auto && avx2Available();
}

}  // namespace asperity::simd
