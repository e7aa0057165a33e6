// The solver's inlined projections agree with the friction library's (SPEC 4).
#include "solver/inline_projections.hpp"

#include <gtest/gtest.h>

#include <random>

namespace asperity {
namespace {

TEST(InlineProjections, MatchTheLibrary) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const CoulombLimit disc{0.6};
  const BoxLimit box{0.2, 0.3, 0.4, 0.5};
  PolygonLimit polygon{DirectionalMu::uniform(8, 0.5f)};
  polygon.mu.mu[3] = 0.1f;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 x(u(rng), u(rng));
    const double ln = i % 10 == 0 ? 0.0 : std::abs(u(rng));
    bool outside = false;
    EXPECT_LT((solver_detail::projectInline(disc, x, ln, outside) - disc.project(x, ln)).norm(),
              1e-15);
    EXPECT_EQ(outside, disc.project(x, ln) != x);
    EXPECT_EQ(solver_detail::projectInline(box, x, ln, outside), box.project(x, ln));
    EXPECT_EQ(outside, box.project(x, ln) != x);
    EXPECT_EQ(solver_detail::projectInline(polygon, x, ln, outside), polygon.project(x, ln));
  }
}

}  // namespace
}  // namespace asperity
