// Which compiled copy of the hot float loops runs (src/math/simd.hpp): the AVX2 copy where the
// processor has it, or the baseline x86-64 copy. Both give the same bits. The choice is an
// option of each object or call that runs the loops (CpuSamplerOptions, ConeProvider,
// PatchConeOptions, accumulateDirectionalSums), never a process-wide switch, so that a test
// can run both copies side by side and compare.
#pragma once

namespace asperity {

enum class SimdCopy {
  Auto,      // the AVX2 copy where this build has one and the processor runs AVX2
  Baseline,  // the baseline copy always
};

}  // namespace asperity
