// Crawling worm (Sec. 5.2, video): sawtooth-textured boxes joined by pulsing distance joints.
#include <algorithm>
#include <string>

#include "experiment_support.hpp"

namespace asperity::experiments {

namespace {

const PaperRow kWormRow = paperRow(1, 1, 0.1, 0.01, 10, 94, 6.3, 0.76, 1.9);

// Centre of mass of worm_0..worm_5 (equal boxes), x over the samples.
std::vector<double> wormCentre(const Recording& rec) {
  std::vector<double> x(rec.time.size(), 0.0);
  for (const auto& poses : rec.poses)
    for (size_t k = 0; k < poses.size(); ++k)
      x[k] += poses[k].position.x() / static_cast<double>(rec.poses.size());
  return x;
}

// Crawling worm (Sec. 5.2): a net crawl, forward, or backward with the texture turned 180 deg.
// Steady: every period of the joints (1 s) after the first advances the right way.
Outcome evaluateWorm(const Experiment& e, const RunOptions& options) {
  Outcome out;
  out.passed = true;
  Plot plot{"Worm's centre of mass", "time (s)", "x - x(0) (m)", {}};
  for (const SceneRun& run : e.scenes) {
    const bool reversed = run.file.find("reversed") != std::string::npos;
    const double sign = reversed ? -1.0 : 1.0;
    std::vector<std::string> bodies;
    for (int i = 0; i < 6; ++i) bodies.push_back("worm_" + std::to_string(i));
    Recording rec = simulate(run.file, run.seconds, options, bodies);
    out.profiles.push_back(rec.profile);
    const std::vector<double> x = wormCentre(rec);
    const std::string label = reversed ? "reversed" : "forward";
    plot.series.push_back(makeSeries(label, rec.time, [&](size_t k) { return x[k] - x[0]; }));
    // Advance over each whole period after the first (the joints' frequency is 1 Hz).
    double worst = 1e30;
    for (double t = 1.0; t + 1.0 <= rec.time.back() + 1e-9; t += 1.0) {
      size_t i0 = 0, i1 = 0;
      while (i0 + 1 < rec.time.size() && rec.time[i0] < t - 1e-9) ++i0;
      while (i1 + 1 < rec.time.size() && rec.time[i1] < t + 1.0 - 1e-9) ++i1;
      worst = std::min(worst, sign * (x[i1] - x[i0]));
    }
    const double advance = x.back() - x.front();
    out.measures.push_back({"advance_" + label, advance, "m"});
    out.measures.push_back({"least_period_" + label, worst, "m"});
    const bool ok = sign * advance > 0.0 && worst > 0.0;
    out.passed = out.passed && ok;
    out.explanation += (out.explanation.empty() ? "" : "; ") + label + ": centre moved " +
                       num(advance) + " m in " + num(rec.time.back()) + " s, least per period " +
                       num(worst) + " m" + (ok ? "" : " (NOT a steady crawl that way)");
  }
  out.plots.push_back(plot);
  return out;
}

}  // namespace

Experiment crawlingWorm() {
  return {"crawling_worm",
          "Crawling worm",
          "Sec. 5.2 (video): sawtooth-textured boxes joined by distance joints whose "
          "length follows a cosine inch forward.",
          "the centre of mass advances every period; with the texture turned 180 degrees "
          "the worm crawls the other way",
          {{"crawling_worm.json", 6.0, kWormRow}, {"crawling_worm_reversed.json", 6.0, kWormRow}},
          evaluateWorm};
}

}  // namespace asperity::experiments
