// The directional kernel against a naive loop over fragmentMu.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// Random fragments on both sides, several sizes (across the kernel's lane and chunk
// boundaries) and direction counts: the sums match a double-precision naive loop.
TEST(DirectionalKernel, MatchesNaiveLoop) {
  std::mt19937 rng(1234);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  for (int n : {4, 5, 16, 64}) {
    const auto dirs = sampleDirections(n);
    for (size_t count : {size_t{0}, size_t{1}, size_t{15}, size_t{17}, size_t{256}, size_t{3001}}) {
      std::vector<float> gx(count), gy(count);
      std::vector<double> naive(dirs.size(), 0.0);
      for (size_t i = 0; i < count; ++i) {
        const Vec3f m = Vec3f(normal(rng), normal(rng), 2.0f * normal(rng)).normalized();
        const Side side = i % 2 == 0 ? Side::A : Side::B;
        const Vec2f g = ploughingVector(m, side);
        gx[i] = g.x();
        gy[i] = g.y();
        for (size_t k = 0; k < dirs.size(); ++k) {
          naive[k] += fragmentMu(m, side, dirs[k].cast<float>());
        }
      }
      // The kernel adds onto what is already in sums.
      std::vector<double> sums(dirs.size(), 1.0);
      accumulateDirectionalSums(gx, gy, dirs, sums);
      for (size_t k = 0; k < dirs.size(); ++k) {
        EXPECT_TRUE(near(sums[k], naive[k] + 1.0, 1e-5)) << n << " " << count << " " << k;
      }
    }
  }
}

// A single fragment gives exactly max(0, g.d) per direction.
TEST(DirectionalKernel, SingleFragment) {
  const std::vector<float> gx = {0.5f}, gy = {-0.25f};
  const auto dirs = sampleDirections(4);
  std::vector<double> sums(4, 0.0);
  accumulateDirectionalSums(gx, gy, dirs, sums);
  EXPECT_DOUBLE_EQ(sums[0], 0.5);
  EXPECT_DOUBLE_EQ(sums[1], 0.0);
  EXPECT_DOUBLE_EQ(sums[2], 0.0);
  EXPECT_DOUBLE_EQ(sums[3], 0.25);
}

// Mismatched spans throw.
TEST(DirectionalKernel, RejectsMismatchedSizes) {
  const std::vector<float> two(2, 0.0f), three(3, 0.0f);
  const auto dirs = sampleDirections(4);
  std::vector<double> sums(4, 0.0), short_sums(3, 0.0);
  EXPECT_THROW(accumulateDirectionalSums(two, three, dirs, sums), Error);
  EXPECT_THROW(accumulateDirectionalSums(two, two, dirs, short_sums), Error);
}

}  // namespace
}  // namespace asperity
