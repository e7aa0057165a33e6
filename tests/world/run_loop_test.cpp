// The run loop every front end shares: steps from seconds, and stepping with the profile summed.
#include "asperity/world/run_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/world/builders.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

TEST(RunLoop, StepsForCoversTheTimeAndCountsAHairUnderAsWhole) {
  EXPECT_EQ(stepsFor(1.0, 0.01), 100);
  EXPECT_EQ(stepsFor(1.005, 0.01), 101);  // a part step is a whole one
  EXPECT_EQ(stepsFor(0.3, 0.1), 3);       // 0.3 / 0.1 = 2.9999999999999996
  EXPECT_EQ(stepsFor(0.0, 0.01), 0);
}

using test::errorOf;

TEST(RunLoop, StepsForRejectsTimesItCannotRunAndNamesTheOption) {
  EXPECT_EQ(errorOf([] { stepsFor(-1.0, 0.01, "--seconds"); }),
            "--seconds: must be a finite number >= 0");
  EXPECT_EQ(errorOf([] { stepsFor(std::nan(""), 0.01); }), "seconds: must be a finite number >= 0");
  EXPECT_NE(
      errorOf([] { stepsFor(1e8, 0.01, "--seconds"); }).find("--seconds: more than 1e9 steps"),
      std::string::npos);
}

TEST(RunLoop, RunStepsStepsSumsAndReportsEveryStep) {
  World world;
  world.createBody(boxDesc("cube", Vec3::Constant(0.1), {}));
  ProfileSums sums;
  std::vector<int64_t> seen;
  runSteps(world, 5, &sums, [&](int64_t i) {
    seen.push_back(i);
    EXPECT_EQ(world.stepCount(), i);  // called after step i
  });
  EXPECT_EQ(seen, (std::vector<int64_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(sums.steps, 5);
  EXPECT_DOUBLE_EQ(world.time(), 5 * world.settings().dt);
}

TEST(RunLoop, RunStepsGivesTheSameStateAsSteppingByHand) {
  auto make = [] {
    auto w = std::make_unique<World>();
    BodyDesc d = boxDesc("cube", Vec3::Constant(0.1), {});
    d.linear_velocity = Vec3(1.0, 0.5, 2.0);
    w->createBody(d);
    return w;
  };
  auto a = make(), b = make();
  runSteps(*a, 40);
  for (int i = 0; i < 40; ++i) b->step();
  EXPECT_EQ(a->stateHash(), b->stateHash());
}

}  // namespace
}  // namespace asperity
