// The hot kernel of every sampler: per-direction sums of max(0, g.d) over a patch's fragments.
//
// Written to auto-vectorise at -O3 on baseline x86-64 (SSE2) without -ffast-math: fragments
// are stored as separate gx / gy arrays, and each direction keeps kLanes independent float
// partial sums, so the compiler may reorder the additions (it cannot reassociate one scalar
// sum). Chunks of kChunk fragments stay in L1 while all directions sweep them; each chunk's
// float partials are flushed into the caller's double sums, so large textures keep precision.
#include <algorithm>
#include <string>

#include "asperity/error.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "math/simd.hpp"

namespace asperity {

namespace {

constexpr size_t kLanes = 16;
constexpr size_t kChunk = 1024;

// Sum of max(0, gx dx + gy dy) over one chunk (at most kChunk fragments).
[[gnu::always_inline]] inline double chunkSumBody(const float* gx, const float* gy, size_t len,
                                                  float dx, float dy) {
  float acc[kLanes] = {};
  const size_t body = len - len % kLanes;
  // kLanes independent partial sums: the inner loop maps onto vector registers.
  for (size_t i = 0; i < body; i += kLanes) {
    for (size_t j = 0; j < kLanes; ++j) {
      const float v = gx[i + j] * dx + gy[i + j] * dy;
      acc[j] += v > 0.0f ? v : 0.0f;
    }
  }
  // The remainder, then the partials, in double.
  double total = 0.0;
  for (size_t i = body; i < len; ++i) {
    const float v = gx[i] * dx + gy[i] * dy;
    total += v > 0.0f ? v : 0.0f;
  }
  for (size_t j = 0; j < kLanes; ++j) total += acc[j];
  return total;
}

// Chunk outer, direction inner: the chunk is read from L1 once per direction.
[[gnu::always_inline]] inline void sweepBody(std::span<const float> gx, std::span<const float> gy,
                                             std::span<const Vec2> directions,
                                             std::span<double> sums) {
  for (size_t base = 0; base < gx.size(); base += kChunk) {
    const size_t len = std::min(kChunk, gx.size() - base);
    for (size_t k = 0; k < directions.size(); ++k) {
      const float dx = static_cast<float>(directions[k].x());
      const float dy = static_cast<float>(directions[k].y());
      sums[k] += chunkSumBody(gx.data() + base, gy.data() + base, len, dx, dy);
    }
  }
}

#if ASPERITY_AVX2_COPIES
// The AVX2 copy (math/simd.hpp): 16 partial sums in two registers.
ASPERITY_TARGET_AVX2 void sweepAvx2(std::span<const float> gx, std::span<const float> gy,
                                    std::span<const Vec2> directions, std::span<double> sums) {
  sweepBody(gx, gy, directions, sums);
}
#endif

}  // namespace

void accumulateDirectionalSums(std::span<const float> gx, std::span<const float> gy,
                               std::span<const Vec2> directions, std::span<double> sums,
                               SimdCopy copy) {
  // Shapes must match: one g per fragment, one sum per direction.
  if (gx.size() != gy.size() || sums.size() != directions.size()) {
    throw Error("accumulateDirectionalSums: sizes differ (gx " + std::to_string(gx.size()) +
                ", gy " + std::to_string(gy.size()) + ", directions " +
                std::to_string(directions.size()) + ", sums " + std::to_string(sums.size()) + ")");
  }
#if ASPERITY_AVX2_COPIES
  if (simd::avx2(copy)) return sweepAvx2(gx, gy, directions, sums);
#endif
  sweepBody(gx, gy, directions, sums);
}

}  // namespace asperity
