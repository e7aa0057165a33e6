// Hot float loops compiled twice, for AVX2 and for baseline x86-64, the better one chosen when
// the program starts (GCC's target_clones: an ifunc). Neither clone may use fused
// multiply-adds (target "avx2" enables none), and each vector lane takes the operations of the
// scalar code, so both clones give the same bits: the golden hashes hold on either.
//
// GCC on x86-64 only. The sanitizer build (clang; an ifunc resolver would also run before the
// sanitizers' runtime starts) thus runs the baseline code against the same golden hashes.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define ASPERITY_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define ASPERITY_AVX2_CLONES
#endif
