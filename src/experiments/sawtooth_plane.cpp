// Sawtooth plane (Sec. 5.2, Fig. 12): boxes dragged along the ridges, up the gentle ramps and
// against the steep faces. Also the sawtooth measures the rotated variant shares.
#include <algorithm>
#include <string>

#include "asperity/error.hpp"

#include "experiment_support.hpp"

namespace asperity::experiments {

namespace {

const PaperRow kSawRow = paperRow(4, 1, 0.2, 0.02, 10, 4, 2.7, 0.2, 2.3);

// Sawtooth plane (Sec. 5.2, Fig. 12): glides along the ridges, slides up the ramps, sticks
// (or topples) against the steep faces.
Outcome evaluateSawtooth(const Experiment& e, const RunOptions& options) {
  const SceneRun& run = e.scenes.at(0);
  Recording rec = simulate(run.file, run.seconds, options, {"box_along", "box_ramp", "box_steep"});
  const SawtoothMeasures m = measureSawtooth(rec);
  Outcome out;
  out.profiles.push_back(rec.profile);
  const char* labels[3] = {"along", "ramp", "steep"};
  Plot travel{"Displacement along the pull", "time (s)", "displacement (m)", {}};
  Plot tilt{"Tilt of the boxes", "time (s)", "tilt (deg)", {}};
  for (int i = 0; i < 3; ++i) {
    out.measures.push_back({std::string("travel_") + labels[i], m.final(i), "m"});
    travel.series.push_back(
        makeSeries(labels[i], rec.time, [&](size_t k) { return m.along_pull[i][k]; }));
    tilt.series.push_back(makeSeries(labels[i], rec.time, [&](size_t k) { return m.tilt[i][k]; }));
  }
  out.measures.push_back({"tilt_steep_max", m.maxTilt(2), "deg"});
  out.plots = {travel, tilt};
  // along > ramp > steep, the steep box stuck or toppled, the other two sliding.
  const bool slide = m.final(1) > kSlideDistance;
  out.passed = m.ordered() && slide;
  out.explanation = m.describe() + (m.ordered() ? ": along > ramp > steep" : ": order broken") +
                    (m.steepHolds() ? ", steep box held" : ", steep box slid") +
                    (slide ? ", ramp box slid" : ", ramp box did not slide");
  return out;
}

}  // namespace

// The sawtooth boxes: displacement along each box's pull (its spring's target velocity).
SawtoothMeasures measureSawtooth(const Recording& rec) {
  SawtoothMeasures m;
  const World& world = *rec.world;
  const char* names[3] = {"box_along", "box_ramp", "box_steep"};
  for (int i = 0; i < 3; ++i) {
    const BodyId id = world.findBody(names[i]);
    Vec3 pull = Vec3::Zero();
    for (const SpringDesc& s : world.springs())
      if (s.body == id) pull = s.target_velocity.normalized();
    if (pull.isZero()) throw Error(std::string("sawtooth scene: no spring pulls ") + names[i]);
    const auto& p = rec.of(names[i]);
    for (size_t k = 0; k < p.size(); ++k) {
      m.along_pull[i].push_back((p[k].position - p[0].position).dot(pull));
      m.tilt[i].push_back(tiltDegrees(p, k));
    }
  }
  return m;
}

bool SawtoothMeasures::ordered() const {
  return final(0) > final(1) && final(1) > final(2) && steepHolds();
}

bool SawtoothMeasures::steepHolds() const {
  return final(2) < kStickDistance || maxTilt(2) > kToppleDegrees;
}

double SawtoothMeasures::maxTilt(int box) const {
  double t = 0.0;
  for (double x : tilt[box]) t = std::max(t, x);
  return t;
}

std::string SawtoothMeasures::describe() const {
  return "along " + num(final(0)) + " m, ramp " + num(final(1)) + " m, steep " + num(final(2)) +
         " m (tilt " + num(maxTilt(2)) + " deg)";
}

Experiment sawtoothPlane() {
  return {"sawtooth_plane",
          "Sawtooth plane",
          "Sec. 5.2, Fig. 12: a box dragged by a spring glides along the ridges, slides "
          "against the gentle ramps, and sticks (or topples) against the steep faces.",
          "displacement along > ramp > steep; the steep box sticks or topples, the ramp "
          "box slides",
          {{"sawtooth_plane.json", 3.0, kSawRow}},
          evaluateSawtooth};
}

}  // namespace asperity::experiments
