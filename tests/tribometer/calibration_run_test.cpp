// A whole calibration: which parameters are free (named, or those not given), the fixed ones'
// values, and a scene written only with values a scene can hold. The run itself:
// tests/cli/calibrate_command_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "asperity/tribometer/calibrate.hpp"
#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::errorOf;

TEST(CalibrationRun, FreeAreTheNamedOrTheNotGiven) {
  TribometerSurfaces s = test::tribometerPair("flat", "flat", 2.0, 3.0);
  TribometerSettings settings;
  settings.friction.mu0 = 0.25;
  TribometerSource source;
  source.k_a = 2.0;
  CalibrationSpec spec = calibrationSpec(source, {}, s, settings);
  EXPECT_FALSE(spec.fit_k_a);
  EXPECT_TRUE(spec.fit_k_b && spec.fit_mu0);
  EXPECT_DOUBLE_EQ(spec.k_a, 2.0);
  spec = calibrationSpec(TribometerSource{}, {"mu0"}, s, settings);
  EXPECT_FALSE(spec.fit_k_a || spec.fit_k_b);
  EXPECT_TRUE(spec.fit_mu0);
  EXPECT_DOUBLE_EQ(spec.k_b, 3.0);
  EXPECT_DOUBLE_EQ(spec.mu0, 0.25);
}

TEST(CalibrationRun, BadFitListsAreErrors) {
  const TribometerSurfaces s = test::tribometerPair("flat", "flat");
  TribometerSource source;
  source.mu0 = 0.2;
  EXPECT_NE(errorOf([&] { calibrationSpec(source, {"k_z"}, s, {}); }).find("'k_z'"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { calibrationSpec(source, {"mu0"}, s, {}); }).find("--fit mu0"),
            std::string::npos);
}

TEST(CalibrationRun, NoSceneWithValuesItCannotHold) {
  CalibrationRun run;
  run.result.k_b = 2e4;
  const std::string e = errorOf([&] { writeCalibratedScene(run, {}, "unused.json"); });
  EXPECT_NE(e.find("outside what a scene holds"), std::string::npos) << e;
}

}  // namespace
}  // namespace asperity
