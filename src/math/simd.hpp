// Hot float loops compiled twice, for AVX2 and for baseline x86-64, the AVX2 copy taken where
// the processor has it. Neither copy may use fused multiply-adds (target "avx2" enables none)
// and each vector lane takes the operations of the scalar code, so both give the same bits:
// tests/math/simd_test.cpp runs scenes both ways and compares their state hashes.
//
// A function `f` is written once as an always-inlined `fBody`; ASPERITY_TARGET_AVX2 marks the
// copy `fAvx2` that calls it, compiled with AVX2 through the inlining, and `f` picks one with
// simd::avx2(). GCC on x86-64 only (elsewhere, and in the clang sanitizer build, `f` is the
// body alone).
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define ASPERITY_AVX2_COPIES 1
#define ASPERITY_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define ASPERITY_AVX2_COPIES 0
#endif

namespace asperity::simd {

// Whether the AVX2 copies run: the processor has AVX2 and forceBaseline(true) is not in effect.
bool avx2();
// Runs the baseline copies even where AVX2 is there (tests compare the two; not thread-safe
// against steps running at the same time).
void forceBaseline(bool on);

}  // namespace asperity::simd
