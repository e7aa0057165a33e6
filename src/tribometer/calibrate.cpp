// Calibration's fit (calibrate.hpp, fitCalibration): least squares of Eq. 7 over the measured
// rows, every parameter >= 0.
#include "asperity/tribometer/calibrate.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>

#include "asperity/error.hpp"

namespace asperity {

namespace {

constexpr const char* kNames[3] = {"k_a", "k_b", "mu0"};

// The design: per row, the coefficient of k_a, k_b and mu0 in Eq. 7.
Eigen::MatrixXd design(const ModelTerms& terms) {
  const auto rows = static_cast<Eigen::Index>(terms.block.size());
  Eigen::MatrixXd x(rows, 3);
  for (Eigen::Index i = 0; i < rows; ++i)
    x.row(i) << terms.block[static_cast<size_t>(i)], terms.plate[static_cast<size_t>(i)], 1.0;
  return x;
}

// Throws unless the free columns can be told apart: none is zero over the rows, and no
// combination of them is (their smallest singular value, columns scaled to unit length).
void checkSeparable(const Eigen::MatrixXd& x, const std::vector<int>& free) {
  std::string names;
  Eigen::MatrixXd scaled(x.rows(), static_cast<Eigen::Index>(free.size()));
  for (size_t j = 0; j < free.size(); ++j) {
    const double norm = x.col(free[j]).norm();
    if (!(norm > 1e-9))
      throw Error(std::string("calibration: ") + kNames[free[j]] +
                  " adds nothing in the measured directions (a flat texture?): fix it with --" +
                  (free[j] == 0   ? "k-a"
                   : free[j] == 1 ? "k-b"
                                  : "mu0"));
    scaled.col(static_cast<Eigen::Index>(j)) = x.col(free[j]) / norm;
    names += (names.empty() ? "" : ", ") + std::string(kNames[free[j]]);
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled);
  const auto& s = svd.singularValues();
  if (s.size() > 0 && s(s.size() - 1) < 1e-6 * s(0))
    throw Error("calibration: the measured directions cannot tell " + names +
                " apart (their terms are proportional there): fix one of them (--k-a, --k-b, "
                "--mu0) or name fewer with --fit");
}

// Least squares of y over the columns in `subset` (a bit per entry of `free`), the others 0.
// Returns the parameters (3) and whether all are >= 0; `sse` gets the sum of squared residuals.
Eigen::Vector3d solveSubset(const Eigen::MatrixXd& x, const Eigen::VectorXd& y,
                            const std::vector<int>& free, unsigned subset, bool& feasible,
                            double& sse) {
  std::vector<int> cols;
  for (size_t j = 0; j < free.size(); ++j)
    if (subset & (1u << j)) cols.push_back(free[j]);
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  if (!cols.empty()) {
    Eigen::MatrixXd xs(x.rows(), static_cast<Eigen::Index>(cols.size()));
    for (size_t j = 0; j < cols.size(); ++j) xs.col(static_cast<Eigen::Index>(j)) = x.col(cols[j]);
    const Eigen::VectorXd b = xs.colPivHouseholderQr().solve(y);
    for (size_t j = 0; j < cols.size(); ++j) p(cols[j]) = b(static_cast<Eigen::Index>(j));
  }
  feasible = p.minCoeff() >= 0.0;
  sse = (y - x * p).squaredNorm();
  return p;
}

}  // namespace

CalibrationResult fitCalibration(const Measurements& data, const ModelTerms& terms,
                                 const CalibrationSpec& spec) {
  if (terms.block.size() != data.rows.size() || terms.plate.size() != data.rows.size())
    throw Error("calibration: model terms for " + std::to_string(terms.block.size()) +
                " rows, measurements of " + std::to_string(data.rows.size()));
  // Rows no gains >= 0 can reach: below a fixed mu0.
  if (!spec.fit_mu0)
    for (const Measurement& m : data.rows)
      if (m.mu < spec.mu0)
        throw Error(data.file + ":" + std::to_string(m.line) + ": mu " + std::to_string(m.mu) +
                    " is below the fixed mu0 " + std::to_string(spec.mu0) +
                    ": no gains >= 0 fit it");
  // The free columns; the fixed ones moved to the measured side.
  const Eigen::MatrixXd x = design(terms);
  const Eigen::Vector3d given(spec.k_a, spec.k_b, spec.mu0);
  const bool fit[3] = {spec.fit_k_a, spec.fit_k_b, spec.fit_mu0};
  std::vector<int> free;
  Eigen::Vector3d fixed = Eigen::Vector3d::Zero();
  for (int j = 0; j < 3; ++j) {
    if (fit[j])
      free.push_back(j);
    else
      fixed(j) = given(j);
  }
  if (free.empty()) throw Error("calibration: nothing to fit (--fit names none, or all are fixed)");
  checkSeparable(x, free);
  Eigen::VectorXd y(x.rows());
  for (Eigen::Index i = 0; i < x.rows(); ++i) y(i) = data.rows[static_cast<size_t>(i)].mu;
  y -= x * fixed;
  // The best subset of free parameters whose least squares is >= 0 (all of them, if it is).
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  double best_sse = std::numeric_limits<double>::infinity();
  for (unsigned subset = (1u << free.size()) - 1;; --subset) {
    bool feasible = false;
    double sse = 0.0;
    const Eigen::Vector3d p = solveSubset(x, y, free, subset, feasible, sse);
    if (feasible && sse < best_sse - 1e-15) best = p, best_sse = sse;
    if (subset == 0) break;
  }
  // The fitted parameters, the model and the residual per row.
  CalibrationResult r;
  const Eigen::Vector3d p = best + fixed;
  r.k_a = p(0), r.k_b = p(1), r.mu0 = p(2);
  const Eigen::VectorXd model = x * p;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    r.model.push_back(model(i));
    r.residual.push_back(data.rows[static_cast<size_t>(i)].mu - model(i));
    sum += r.residual.back() * r.residual.back();
  }
  r.rms_residual = std::sqrt(sum / static_cast<double>(x.rows()));
  return r;
}

}  // namespace asperity
