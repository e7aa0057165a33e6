// Measurements for calibration: the three kinds of CSV, each row's coefficient, and one test per
// kind of bad row, each error naming the file and the line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asperity/tribometer/calibrate.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::errorOf;
using test::near;

TEST(Measurements, CoefficientsAsMeasured) {
  const Measurements m =
      parseMeasurements("# oak on steel\nangle_deg,mu\n0,0.4\n\n 90 , 0.55 \n", "m.csv");
  EXPECT_EQ(m.kind, MeasurementKind::Mu);
  ASSERT_EQ(m.rows.size(), 2u);
  EXPECT_EQ(m.rows[1].line, 5);
  EXPECT_DOUBLE_EQ(m.rows[1].angle_deg, 90.0);
  EXPECT_DOUBLE_EQ(m.rows[1].mu, 0.55);
}

TEST(Measurements, TiltAnglesAreTheTangents) {
  const Measurements m = parseMeasurements("angle_deg,tilt_deg\n45,30\n", "t.csv");
  EXPECT_EQ(m.kind, MeasurementKind::TiltAngle);
  EXPECT_TRUE(near(m.rows[0].mu, std::tan(kPi / 6.0), 1e-12));
}

TEST(Measurements, SlidesDecelerateAtMuG) {
  // From 2 m/s a block stops in 0.5 m at mu = v^2 / (2 g d) = 4 / 9.81.
  const Measurements m = parseMeasurements("angle_deg,speed,distance\n0,2,0.5\n", "s.csv", 9.81);
  EXPECT_EQ(m.kind, MeasurementKind::SlideDistance);
  EXPECT_TRUE(near(m.rows[0].mu, 4.0 / 9.81, 1e-12));
}

TEST(Measurements, BadRowsAreErrorsNamingTheLine) {
  const auto error = [](const std::string& text) {
    return errorOf([&] { parseMeasurements(text, "m.csv"); });
  };
  EXPECT_NE(error("angle,friction\n0,1\n").find("m.csv:1: expected the header"), std::string::npos);
  EXPECT_NE(error("angle_deg,mu\n0,nan\n").find("m.csv:2: mu must be a finite number"),
            std::string::npos);
  EXPECT_NE(error("angle_deg,mu\n0,0.3\n0,-0.1\n").find("m.csv:3: mu must be >= 0"),
            std::string::npos);
  EXPECT_NE(error("angle_deg,mu\n0,0.3x\n").find("m.csv:2"), std::string::npos);
  EXPECT_NE(error("angle_deg,mu\n0\n").find("m.csv:2: expected 2 values"), std::string::npos);
  EXPECT_NE(error("angle_deg,tilt_deg\n0,90\n").find("m.csv:2: tilt_deg"), std::string::npos);
  EXPECT_NE(error("angle_deg,speed,distance\n0,1,0\n").find("m.csv:2: distance"),
            std::string::npos);
  EXPECT_NE(error("angle_deg,speed,distance\n0,-1,1\n").find("m.csv:2: speed"), std::string::npos);
  EXPECT_NE(error("angle_deg,mu\n").find("no measurements"), std::string::npos);
  // Rows that would give friction without bound, as given or as their slide or tilt implies.
  EXPECT_NE(error("angle_deg,mu\n0,0.3\n90,1e300\n").find("m.csv:3: the row gives mu = 1e+300"),
            std::string::npos);
  EXPECT_NE(error("angle_deg,speed,distance\n0,1e200,1\n").find("m.csv:2: the row gives mu"),
            std::string::npos);
  EXPECT_NE(error("angle_deg,tilt_deg\n0,89.999\n").find("more than 100"), std::string::npos);
  EXPECT_NE(errorOf([] { readMeasurements("missing.csv"); }).find("missing.csv"),
            std::string::npos);
}

}  // namespace
}  // namespace asperity
