// Calibration's fit: known gains recovered from synthetic measurements (the model's own numbers,
// and the tribometer's mu_model) within 2 %, within 10 % with 5 % noise; fixed parameters stay;
// every parameter >= 0; and errors naming the row or the parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "asperity/tribometer/calibrate.hpp"
#include "support/test_support.hpp"
#include "tribometer/tribometer_test_support.hpp"

namespace asperity {
namespace {

using test::errorOf;
using test::near;
using test::tribometerPair;

// A sawtooth block across a sawtooth plate: their terms differ enough over the directions to
// tell k_a, k_b and mu0 apart.
class Calibration : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    surfaces_ = new TribometerSurfaces(tribometerPair("gen:sawtooth:2:axis=v", "gen:sawtooth:1"));
    for (int k = 0; k < 16; ++k) angles_.push_back(22.5 * k);
    terms_ = new ModelTerms(modelTerms(*surfaces_, settings(), angles_, ModelKind::Sampler));
  }
  static void TearDownTestSuite() {
    delete surfaces_;
    delete terms_;
  }
  // Two tracks per direction (the terms are a mean over them: more only smooth them).
  static TribometerSettings settings() {
    TribometerSettings s = test::dragOnly(16, 0.0);
    s.tracks = 2;
    s.threads = 0;
    return s;
  }
  // Rows of mu = mu0 + k_a A + k_b B in every direction, `repeats` times over, each times
  // (1 + noise N(0, 1)) from a generator seeded with `seed` (Box-Muller written out: portable).
  static Measurements synthetic(double k_a, double k_b, double mu0, double noise, int repeats,
                                uint64_t seed = 7) {
    std::mt19937_64 rng(seed);
    const auto uniform = [&] {
      return (static_cast<double>(rng() >> 11) + 1.0) / 9007199254740993.0;
    };
    Measurements m;
    m.file = "synthetic.csv";
    for (int r = 0; r < repeats; ++r)
      for (size_t k = 0; k < angles_.size(); ++k) {
        const double n = std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * kPi * uniform());
        const double mu = mu0 + k_a * terms_->block[k] + k_b * terms_->plate[k];
        m.rows.push_back({static_cast<int>(m.rows.size()) + 2, angles_[k], mu * (1.0 + noise * n)});
      }
    return m;
  }
  // The terms of `m`'s rows (the directions repeat).
  static ModelTerms termsOf(const Measurements& m) {
    ModelTerms t;
    for (size_t i = 0; i < m.rows.size(); ++i) {
      t.block.push_back(terms_->block[i % angles_.size()]);
      t.plate.push_back(terms_->plate[i % angles_.size()]);
    }
    return t;
  }

  static TribometerSurfaces* surfaces_;
  static std::vector<double> angles_;
  static ModelTerms* terms_;
};
TribometerSurfaces* Calibration::surfaces_ = nullptr;
std::vector<double> Calibration::angles_;
ModelTerms* Calibration::terms_ = nullptr;

TEST_F(Calibration, RecoversKnownGainsFromTheModelsNumbers) {
  const Measurements m = synthetic(1.5, 0.8, 0.3, 0.0, 1);
  const CalibrationResult r = fitCalibration(m, termsOf(m), {});
  EXPECT_TRUE(near(r.k_a, 1.5, 0.02));
  EXPECT_TRUE(near(r.k_b, 0.8, 0.02));
  EXPECT_TRUE(near(r.mu0, 0.3, 0.02));
  EXPECT_LT(r.rms_residual, 1e-9);
}

TEST_F(Calibration, RecoversKnownGainsFromTheTribometersMuModel) {
  // The drag test's mean coefficients at k_a 1.5, k_b 0.8, mu0 0.3, fitted against the
  // unit-gain terms.
  TribometerSurfaces gained = *surfaces_;
  gained.block.gain = 1.5, gained.plate.gain = 0.8;
  TribometerSettings s = settings();
  s.friction.mu0 = 0.3;
  Measurements m;
  m.file = "tribometer";
  for (double a : angles_) m.rows.push_back({0, a, runDragTest(gained, s, a).mu_model});
  const CalibrationResult r = fitCalibration(m, *terms_, {});
  EXPECT_TRUE(near(r.k_a, 1.5, 0.02)) << r.k_a;
  EXPECT_TRUE(near(r.k_b, 0.8, 0.02)) << r.k_b;
  EXPECT_TRUE(near(r.mu0, 0.3, 0.02)) << r.mu0;
}

TEST_F(Calibration, WithinTenPercentWithFivePercentNoise) {
  // 20 sets of 16 directions, each measurement off by 5 % (one standard deviation): each
  // parameter's root-mean-square error over the sets is within 10 % (4 to 6 %), the worst set's
  // within 15 % (12 %).
  double square[3] = {0.0, 0.0, 0.0};
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Measurements m = synthetic(1.5, 0.8, 0.3, 0.05, 1, seed);
    const CalibrationResult r = fitCalibration(m, termsOf(m), {});
    const double error[3] = {r.k_a / 1.5 - 1.0, r.k_b / 0.8 - 1.0, r.mu0 / 0.3 - 1.0};
    for (int j = 0; j < 3; ++j) {
      square[j] += error[j] * error[j];
      EXPECT_LT(std::abs(error[j]), 0.15) << "set " << seed << ", parameter " << j;
    }
  }
  for (int j = 0; j < 3; ++j) EXPECT_LT(std::sqrt(square[j] / 20.0), 0.10) << "parameter " << j;
}

TEST_F(Calibration, FixedParametersStay) {
  const Measurements m = synthetic(1.5, 0.8, 0.3, 0.0, 1);
  CalibrationSpec spec;
  spec.fit_k_a = false;
  spec.k_a = 1.5;
  const CalibrationResult r = fitCalibration(m, termsOf(m), spec);
  EXPECT_DOUBLE_EQ(r.k_a, 1.5);
  EXPECT_TRUE(near(r.k_b, 0.8, 1e-6));
  EXPECT_TRUE(near(r.mu0, 0.3, 1e-6));
  ASSERT_EQ(r.residual.size(), m.rows.size());
}

TEST_F(Calibration, EveryParameterIsAtLeastZero) {
  // Friction that falls where the textures rise: the best non-negative fit is mu0 alone.
  Measurements m = synthetic(0.0, 0.0, 0.5, 0.0, 1);
  for (size_t k = 0; k < m.rows.size(); ++k) m.rows[k].mu -= 0.3 * terms_->plate[k];
  const CalibrationResult r = fitCalibration(m, termsOf(m), {});
  EXPECT_GE(r.k_a, 0.0);
  EXPECT_GE(r.k_b, 0.0);
  EXPECT_GE(r.mu0, 0.0);
  EXPECT_DOUBLE_EQ(r.k_b, 0.0);
}

TEST_F(Calibration, ARowBelowAFixedMu0IsAnErrorNamingIt) {
  Measurements m = synthetic(1.5, 0.8, 0.3, 0.0, 1);
  m.rows[3].mu = 0.1;
  CalibrationSpec spec;
  spec.fit_mu0 = false;
  spec.mu0 = 0.3;
  const std::string e = errorOf([&] { fitCalibration(m, termsOf(m), spec); });
  EXPECT_NE(e.find("synthetic.csv:5: mu 0.1"), std::string::npos) << e;
  EXPECT_NE(e.find("fixed mu0"), std::string::npos) << e;
}

TEST(CalibrationErrors, ParametersTheDataCannotTellApart) {
  Measurements m;
  m.file = "m.csv";
  for (int k = 0; k < 4; ++k) m.rows.push_back({k + 2, 90.0 * k, 0.3});
  // A flat block adds nothing: k_a cannot be fitted.
  const ModelTerms flat_block{{0, 0, 0, 0}, {0.1, 0.2, 0.1, 0.2}};
  EXPECT_NE(errorOf([&] { fitCalibration(m, flat_block, {}); }).find("k_a adds nothing"),
            std::string::npos);
  // Terms the same in every direction cannot be told from mu0.
  const ModelTerms even{{0.1, 0.1, 0.1, 0.1}, {0.1, 0.2, 0.1, 0.2}};
  const std::string e = errorOf([&] { fitCalibration(m, even, {}); });
  EXPECT_NE(e.find("cannot tell k_a, k_b, mu0 apart"), std::string::npos) << e;
  CalibrationSpec none;
  none.fit_k_a = none.fit_k_b = none.fit_mu0 = false;
  EXPECT_NE(errorOf([&] { fitCalibration(m, even, none); }).find("nothing to fit"),
            std::string::npos);
}

}  // namespace
}  // namespace asperity
