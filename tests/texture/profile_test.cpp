// Periodic slope profiles: heights, point slopes and box-filtered slopes.
#include "texture/profile.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

TEST(PeriodicProfile, TriangleHeightsAndSlopes) {
  // Up 1 per texel for 4 texels, down 1 for 4: a triangle of height 4, period 8.
  const texgen::PeriodicProfile p({{4.0, 1.0}, {4.0, -1.0}});
  EXPECT_EQ(p.period(), 8.0);
  EXPECT_TRUE(near(p.height(2.0), 2.0, 0.0, 1e-12));
  EXPECT_TRUE(near(p.height(6.0), 2.0, 0.0, 1e-12));
  EXPECT_TRUE(near(p.height(8.0 * 5 + 3.0), 3.0, 0.0, 1e-12));
  EXPECT_TRUE(near(p.height(-1.0), 1.0, 0.0, 1e-12));
  EXPECT_EQ(p.slope(1.0), 1.0);
  EXPECT_EQ(p.slope(5.0), -1.0);
  EXPECT_EQ(p.slope(-1.0), -1.0);
}

TEST(PeriodicProfile, BoxFilteredSlopeAveragesOverTheWindow) {
  const texgen::PeriodicProfile p({{4.0, 1.0}, {4.0, -1.0}});
  // A window of 2 centred on the crest sees +1 and -1 equally.
  EXPECT_TRUE(near(p.slope(4.0, 2.0), 0.0, 0.0, 1e-12));
  // Half a texel of each around x = 4.25 with window 1: 0.25 up, 0.75 down.
  EXPECT_TRUE(near(p.slope(4.25, 1.0), -0.5, 0.0, 1e-12));
  // A whole period averages to the net rise: zero here.
  EXPECT_TRUE(near(p.slope(1.3, 8.0), 0.0, 0.0, 1e-12));
}

TEST(PeriodicProfile, NetRiseIsAllowed) {
  // Facets that no height field has: 3 texels at +1, 1 texel at -1 (net +2 per period).
  const texgen::PeriodicProfile p({{3.0, 1.0}, {1.0, -1.0}});
  EXPECT_TRUE(near(p.height(4.0), 2.0, 0.0, 1e-12));
  EXPECT_TRUE(near(p.height(9.0), 5.0, 0.0, 1e-12));
  EXPECT_TRUE(near(p.slope(2.0, 4.0), 0.5, 0.0, 1e-12));
}

}  // namespace
}  // namespace asperity
