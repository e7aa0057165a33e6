// The sawtooth plane turned 45 degrees (Sec. 5.5) under the three frame modes.
#include <string>

#include "experiment_support.hpp"

namespace asperity::experiments {

namespace {

// Sec. 5.5: the sawtooth planes turned 45 degrees about z. Frames from the world axis sample
// the limit surface diagonally to the ridges (nearly isotropic); frames from the sliding
// velocity (auto) or from the texture recover the unrotated ordering.
Outcome evaluateSawtoothRotated(const Experiment& e, const RunOptions& options) {
  const SceneRun& run = e.scenes.at(0);
  const std::pair<const char*, FrameMode> modes[3] = {
      {"world", FrameMode::World}, {"auto", FrameMode::Auto}, {"texture", FrameMode::Texture}};
  Outcome out;
  Plot travel{
      "Displacement along the pull, planes turned 45 deg", "time (s)", "displacement (m)", {}};
  const char* labels[3] = {"along", "ramp", "steep"};
  bool ordered[3] = {false, false, false};
  for (int m = 0; m < 3; ++m) {
    Recording rec = simulate(run.file, run.seconds, options, {"box_along", "box_ramp", "box_steep"},
                             modes[m].second);
    out.profiles.push_back(rec.profile);
    const SawtoothMeasures s = measureSawtooth(rec);
    ordered[m] = s.ordered() && s.final(1) > kSlideDistance;
    for (int i = 0; i < 3; ++i) {
      const std::string name = std::string(modes[m].first) + "_" + labels[i];
      out.measures.push_back({name, s.final(i), "m"});
      // The plot shows the three boxes under auto and world frames.
      if (m < 2)
        travel.series.push_back(
            makeSeries(name, rec.time, [&](size_t k) { return s.along_pull[i][k]; }));
    }
    out.explanation += (out.explanation.empty() ? "" : "; ") + std::string(modes[m].first) + ": " +
                       s.describe() + (ordered[m] ? " (ordered)" : " (NOT ordered)");
  }
  out.plots.push_back(travel);
  // auto and texture recover along > ramp > steep; world does not.
  out.passed = ordered[1] && ordered[2] && !ordered[0];
  return out;
}

}  // namespace

Experiment sawtoothPlaneRotated() {
  return {"sawtooth_plane_rotated",
          "Sawtooth plane turned 45 degrees (frame modes)",
          "Sec. 5.5: with the sawtooth plane turned 45 degrees about the vertical, frames "
          "aligned with the world axes make the friction nearly isotropic; frames aligned "
          "automatically with the sliding direction show the anisotropy and asymmetry.",
          "with --frame auto and --frame texture: along > ramp > steep (steep held, ramp "
          "sliding); with --frame world that ordering is lost",
          {{"sawtooth_plane_rotated.json", 3.0, std::nullopt}},
          evaluateSawtoothRotated};
}

}  // namespace asperity::experiments
