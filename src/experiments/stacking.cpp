// Stacking (Sec. 5.3, Fig. 14): an impulse on the second cube of stacks of three materials.
#include <cmath>
#include <string>

#include "experiment_support.hpp"

namespace asperity::experiments {

namespace {

const PaperRow kStackRow = paperRow(1, 1, 0.2, 0.02, 10, 123, 33.1, 1.8, 2.3);

// Stacking (Sec. 5.3, Fig. 14): the second cube from the bottom of each stack is hit by the
// same impulse; acrylic shoots out, PVC moves least. Both directions.
Outcome evaluateStacking(const Experiment& e, const RunOptions& options) {
  Outcome out;
  out.passed = true;
  const char* stacks[3] = {"acrylic", "oak", "pvc"};
  for (const SceneRun& run : e.scenes) {
    const std::string dir = run.file.find("forward") != std::string::npos ? "forward" : "sideways";
    Recording rec = simulate(run.file, run.seconds, options, {"acrylic_1", "oak_1", "pvc_1"});
    out.profiles.push_back(rec.profile);
    Plot plot{
        "Second cube's displacement, " + dir + " impulse", "time (s)", "displacement (m)", {}};
    double d[3];
    for (int i = 0; i < 3; ++i) {
      const auto& p = rec.of(std::string(stacks[i]) + "_1");
      d[i] = horizontalTravel(p);
      out.measures.push_back({dir + "_" + stacks[i], d[i], "m"});
      plot.series.push_back(makeSeries(stacks[i], rec.time, [&](size_t k) {
        return std::hypot(p[k].position.x() - p[0].position.x(),
                          p[k].position.y() - p[0].position.y());
      }));
    }
    out.plots.push_back(plot);
    const bool a = d[0] > d[1], b = d[1] > d[2];
    out.passed = out.passed && a && b;
    out.explanation += (out.explanation.empty() ? "" : "; ") + dir + ": acrylic " + num(d[0]) +
                       " m" + relation(a, ">") + "oak " + num(d[1]) + " m" + relation(b, ">") +
                       "PVC " + num(d[2]) + " m";
  }
  return out;
}

}  // namespace

Experiment stacking() {
  return {"stacking",
          "Stacking of boxes",
          "Sec. 5.3, Fig. 14: an impulse on the second cube from the bottom of stacks of "
          "acrylic, oak and cut PVC cubes shoots the acrylic cube out and moves the PVC "
          "cube least, sideways and forward.",
          "displacement of acrylic_1 > oak_1 > pvc_1, for both impulse directions",
          {{"stacking.json", 2.0, kStackRow}, {"stacking_forward.json", 2.0, kStackRow}},
          evaluateStacking};
}

}  // namespace asperity::experiments
