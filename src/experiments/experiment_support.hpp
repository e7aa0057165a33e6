// Private to the experiments (one file per experiment in this folder): each experiment's
// catalog entry, and the small measuring helpers the evaluations share (trajectory distances,
// tilts, series, text, the sawtooth measures).
#pragma once

#include <string>
#include <vector>

#include "experiment_outcomes.hpp"

namespace asperity::experiments {

// The catalog entries, one per file, in the paper's order (experimentCatalog lists them).
Experiment boxesOnMaterials();
Experiment sawtoothPlane();
Experiment stacking();
Experiment crawlingWorm();
Experiment sawtoothPlaneRotated();
Experiment chainBolas();
Experiment tumblingBunnies();
Experiment nutBolt();

// Table 1 of the paper: k_A, k_B, mu0, w, dt (ms), contacts, total, render, averaging (ms).
PaperRow paperRow(double k_a, double k_b, double mu0, double w, double dt_ms, int contacts,
                  double total, double patch, double averaging);

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
// " < " or " NOT < ", for explanations that show which link of an ordering failed.
std::string relation(bool holds, const char* op);

// The sawtooth scenes (plain and rotated; sawtooth_plane.cpp): displacement along each box's
// pull and its tilt.
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

}  // namespace asperity::experiments
