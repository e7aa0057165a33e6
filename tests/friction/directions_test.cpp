// Sample directions (SPEC 1) and DirectionalMu: counts, conventions, interpolation.
#include "asperity/friction/directions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// N = 4 gives t, b, -t, -b exactly (the paper's d1..d4).
TEST(SampleDirections, FourAreTheAxes) {
  const auto d = sampleDirections(4);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0], Vec2(1, 0));
  EXPECT_EQ(d[1], Vec2(0, 1));
  EXPECT_EQ(d[2], Vec2(-1, 0));
  EXPECT_EQ(d[3], Vec2(0, -1));
}

// Every count in range gives unit vectors at angles 2 pi k / N, counter-clockwise from t.
TEST(SampleDirections, AnglesAndUnitLength) {
  for (int n = kMinDirections; n <= kMaxDirections; ++n) {
    const auto d = sampleDirections(n);
    ASSERT_EQ(d.size(), static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const double angle = 2.0 * kPi * k / n;
      EXPECT_TRUE(near(d[k].x(), std::cos(angle), 0.0, 1e-12)) << n << " " << k;
      EXPECT_TRUE(near(d[k].y(), std::sin(angle), 0.0, 1e-12)) << n << " " << k;
    }
  }
}

// The shared view holds the same directions as the vector, for every count.
TEST(SampleDirections, ViewMatchesVector) {
  for (int n = kMinDirections; n <= kMaxDirections; ++n) {
    const auto v = sampleDirections(n);
    const auto view = sampleDirectionsView(n);
    ASSERT_EQ(view.size(), v.size());
    for (size_t k = 0; k < v.size(); ++k) EXPECT_EQ(view[k], v[k]);
  }
  EXPECT_THROW(sampleDirectionsView(3), Error);
  EXPECT_THROW(sampleDirectionsView(65), Error);
}

// Bad counts throw asperity::Error naming the value.
TEST(SampleDirections, RejectsBadCounts) {
  for (int n : {-1, 0, 3, 65, 1000}) {
    try {
      sampleDirections(n);
      FAIL() << "no error for " << n;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::to_string(n)), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(DirectionalMu::uniform(3, 0.5f), Error);
  EXPECT_THROW(DirectionalMu::uniform(65, 0.5f), Error);
  EXPECT_THROW(DirectionalMu{}.along(0.0), Error);
}

// uniform fills count entries; along of a uniform set on a sample direction is the value.
TEST(DirectionalMu, Uniform) {
  const DirectionalMu mu = DirectionalMu::uniform(16, 0.3f);
  EXPECT_EQ(mu.count, 16);
  for (int k = 0; k < 16; ++k) EXPECT_FLOAT_EQ(mu.mu[k], 0.3f);
  for (int k = 0; k < 16; ++k) EXPECT_DOUBLE_EQ(mu.along(2.0 * kPi * k / 16), mu.mu[k]);
}

// Between samples, along follows the straight polygon edge: for the N = 4 rhombus with
// radii r_t, r_b the edge is x / r_t + y / r_b = 1, so at angle a, r = 1 / (cos a / r_t +
// sin a / r_b).
TEST(DirectionalMu, AlongFollowsPolygonEdge) {
  DirectionalMu mu = DirectionalMu::uniform(4, 0.0f);
  mu.mu = {0.5f, 0.2f, 0.8f, 0.1f};
  EXPECT_DOUBLE_EQ(mu.along(0.0), 0.5);
  EXPECT_DOUBLE_EQ(mu.along(kPi), 0.8f);
  EXPECT_DOUBLE_EQ(mu.along(-0.5 * kPi), 0.1f);  // negative angles wrap
  EXPECT_DOUBLE_EQ(mu.along(2.5 * kPi), 0.2f);   // and so do angles past 2 pi
  for (double a : {0.1, 0.4, 0.785, 1.2, 1.5}) {
    const double expected = 1.0 / (std::cos(a) / 0.5 + std::sin(a) / double(0.2f));
    EXPECT_TRUE(near(mu.along(a), expected, 1e-6)) << a;
  }
  // A uniform set at N = 64 is nearly a circle: the chord dips by at most 1 - cos(pi / 64).
  const DirectionalMu round = DirectionalMu::uniform(64, 1.0f);
  for (double a = 0.0; a < 2.0 * kPi; a += 0.01) {
    EXPECT_LE(round.along(a), 1.0 + 1e-12);
    EXPECT_GE(round.along(a), std::cos(kPi / 64) - 1e-12);
  }
}

// A zero sample collapses both wedges beside it: the polygon's edges run through the origin.
TEST(DirectionalMu, AlongWithZeroSample) {
  DirectionalMu mu = DirectionalMu::uniform(4, 1.0f);
  mu.mu[1] = 0.0f;
  EXPECT_EQ(mu.along(0.5 * kPi), 0.0);
  EXPECT_EQ(mu.along(0.1), 0.0);
  EXPECT_EQ(mu.along(3.0), 0.0);
  EXPECT_EQ(mu.along(0.0), 1.0);
  EXPECT_TRUE(near(mu.along(-0.25 * kPi), 1.0 / std::sqrt(2.0), 1e-12));
}

}  // namespace
}  // namespace asperity
