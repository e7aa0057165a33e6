// Private to the experiments: the catalog entries (experiment_evaluations.cpp) and the small
// measuring helpers the evaluations share (trajectory distances, tilts, series, text).
#pragma once

#include <string>
#include <vector>

#include "experiment_outcomes.hpp"

namespace asperity::experiments {

// Every experiment with its scenes, Table 1 rows and evaluation, in the paper's order.
std::vector<Experiment> experimentEntries();

// Horizontal (x, y) distance between the first and last sample.
double horizontalTravel(const std::vector<Transform>& poses);
// Angle (degrees) between the body's z axis in the first sample and in sample i.
double tiltDegrees(const std::vector<Transform>& poses, size_t i);
// The series y(t) = f(sample index) over a recording's times.
template <class F>
Series makeSeries(const std::string& label, const std::vector<double>& time, F f) {
  Series s;
  s.label = label;
  for (size_t i = 0; i < time.size(); ++i) {
    s.x.push_back(time[i]);
    s.y.push_back(f(i));
  }
  return s;
}
// A number with three significant digits, for explanations ("0.623").
std::string num(double x);

// The sawtooth scenes (plain and rotated): displacement along each box's pull and its tilt.
inline constexpr double kStickDistance = 0.05;  // m: less is "stuck"
inline constexpr double kSlideDistance = 0.1;   // m: more is "sliding"
inline constexpr double kToppleDegrees = 30.0;  // deg: more is "toppled"
struct SawtoothMeasures {
  std::vector<double> along_pull[3];  // box_along, box_ramp, box_steep (m)
  std::vector<double> tilt[3];        // deg
  double final(int box) const { return along_pull[box].back(); }
  double maxTilt(int box) const;
  bool steepHolds() const;  // steep box moved < kStickDistance or toppled
  bool ordered() const;     // along > ramp > steep and the steep box held
  std::string describe() const;
};
SawtoothMeasures measureSawtooth(const Recording& rec);

// Evaluations in experiment_evaluations_more.cpp.
Outcome evaluateChainBolas(const Experiment& e, const RunOptions& options);
Outcome evaluateSawtoothRotated(const Experiment& e, const RunOptions& options);
// Evaluations in experiment_evaluations_mesh.cpp.
Outcome evaluateBunnies(const Experiment& e, const RunOptions& options);
Outcome evaluateNutBolt(const Experiment& e, const RunOptions& options);

}  // namespace asperity::experiments
