// The distance joint's time-varying length (the crawling worm's muscles).
#include "asperity/dynamics/joint.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace asperity {
namespace {

TEST(Joint, DistanceLengthFollowsTheCosine) {
  JointDesc j;
  j.type = JointType::Distance;
  j.rest_length = 0.3;
  j.amplitude = 0.05;
  j.frequency = 2.0;
  j.phase = 0.5;
  for (const double t : {0.0, 0.1, 0.37, 1.0}) {
    EXPECT_TRUE(test::near(distanceJointLength(j, t),
                           0.3 + 0.05 * std::cos(2 * kPi * 2.0 * t + 0.5), 1e-15));
  }
  j.amplitude = 0.0;
  EXPECT_EQ(distanceJointLength(j, 12.3), 0.3);
}

}  // namespace
}  // namespace asperity
