// The paper's experiments (Sec. 5, SPEC 7) as scenes whose outcomes are measured: each
// experiment loads its scene files from scenes/, steps them through the scene library
// (loadScene, instantiate, World::step), records the trajectories that tell its story, and
// returns the measured numbers with pass or fail and a one-line explanation. `asperity bench`
// and `asperity report` (apps/cli) and tests/experiments use it; docs/experiments.md lists the
// experiments, their parameters and outcomes.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "asperity/scene/friction_providers.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/world.hpp"

namespace asperity::experiments {

// One row of the paper's Table 1 (its parameters and its GTX 1650 / i9 timings per step).
struct PaperRow {
  double k_a = 0.0;
  double k_b = 0.0;
  double mu0 = 0.0;
  double w = 0.0;      // patch width (m)
  double dt_ms = 0.0;  // time step (ms)
  int contacts = 0;    // average number of contacts
  double total_ms = 0.0;
  double patch_ms = 0.0;      // contact patch render
  double averaging_ms = 0.0;  // compute average coefficients
};

// Per-step averages of StepProfile over one run of one scene.
struct RunProfile {
  std::string scene;  // file name
  std::string sampler;
  int64_t steps = 0;
  double dt = 0.0;  // s
  double mu0 = 0.0;
  double patch_width = 0.0;  // m
  double k_a = 0.0;          // largest gain on a dynamic body's surface
  double k_b = 0.0;          // largest gain on a static or kinematic body's surface
  int threads = 1;
  // Per-step means of the stages (ProfileSums), set when the run ends.
  double contacts = 0.0;
  double fallbacks = 0.0;
  double total_ms = 0.0;
  double patch_ms = 0.0;
  double averaging_ms = 0.0;
  double solve_ms = 0.0;
  double prepare_ms = 0.0;  // World::prepare before the first step (once, not per step)
  double wall_s = 0.0;
  ProfileSums sums;
  uint64_t state_hash = 0;  // of the world at the end of the run
};

// A curve of a plot: y over x (time, usually); or, with `dots`, separate points (a map).
struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  bool dots = false;
};

struct Plot {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Series> series;
};

// A table of results, e.g. one row per jittered run: cells are already formatted text.
struct Table {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

// A measured number, e.g. {"slide_concrete", 0.62, "m"}.
struct Measure {
  std::string name;
  double value = 0.0;
  std::string unit;
};

struct Outcome {
  std::string id;
  bool passed = false;
  std::string explanation;  // one line, with the numbers that decide it
  std::vector<Measure> measures;
  std::vector<Plot> plots;
  std::vector<Table> tables;
  std::vector<RunProfile> profiles;  // one per scene run
  // The measure called `name`; throws asperity::Error when there is none.
  double value(const std::string& name) const;
};

struct RunOptions {
  std::string scenes_dir = "scenes";  // folder holding the experiments' scene files
  std::string sampler;                // friction sampler override ("" = the scenes')
  std::optional<int> threads;         // worker threads override (WorldSettings::threads)
  int record_every = 1;               // steps between recorded samples of the plots
  // The samplers the scenes and `sampler` may name (a front end adds "gl" when it has it).
  FrictionProviders providers = FrictionProviders::builtIn();
};

// A scene file with the simulated time its outcome needs, and the paper's Table 1 row.
struct SceneRun {
  SceneRun(std::string file_, double seconds_, std::optional<PaperRow> paper_ = {},
           std::optional<double> frame_at_ = {})
      : file(std::move(file_)), seconds(seconds_), paper(paper_), frame_at(frame_at_) {}
  std::string file;  // relative to RunOptions::scenes_dir
  double seconds = 1.0;
  std::optional<PaperRow> paper;
  std::optional<double> frame_at;  // s, the report's rendered frame (default: half-way)
};

struct Experiment {
  std::string id;        // e.g. "boxes_on_materials"
  std::string title;     // e.g. "Boxes on four materials"
  std::string paper;     // what the paper shows (Sec. 5)
  std::string expected;  // the outcome that is measured and tested
  std::vector<SceneRun> scenes;
  std::function<Outcome(const Experiment&, const RunOptions&)> run;
};

// Every experiment, in the paper's order.
const std::vector<Experiment>& experimentCatalog();
// The experiment with this id; throws asperity::Error listing the known ids otherwise.
const Experiment& findExperiment(const std::string& id);
// Runs the experiment's scenes and measures its outcome (exceptions: asperity::Error from the
// scene library, naming the file).
Outcome runExperiment(const std::string& id, const RunOptions& options = {});

// Trajectories of the named bodies (centre of mass poses), recorded every options.record_every
// steps, and the run's profile.
struct Recording {
  std::vector<double> time;
  std::vector<std::string> bodies;
  std::vector<std::vector<Transform>> poses;  // [body][sample]
  RunProfile profile;
  std::unique_ptr<World> world;  // the world at the end of the run
  // Samples of body `name`; throws asperity::Error for a body that was not recorded.
  const std::vector<Transform>& of(const std::string& name) const;
};

// Loads scenes_dir/file, applies the sampler override (and frame override when given), runs it
// for `seconds` and records `bodies` (empty: every dynamic body).
Recording simulate(const std::string& file, double seconds, const RunOptions& options,
                   const std::vector<std::string>& bodies = {},
                   std::optional<FrameMode> frame = std::nullopt);
// The same for a scene already loaded (and perhaps changed) by the caller; `file` names it in
// the profile and in messages.
Recording simulate(SceneDesc scene, const std::string& file, double seconds,
                   const RunOptions& options, const std::vector<std::string>& bodies = {},
                   std::optional<FrameMode> frame = std::nullopt);
// scenes_dir/file loaded (asperity::Error naming the path when it cannot be).
SceneDesc loadExperimentScene(const std::string& file, const RunOptions& options);

// Runs one scene for `seconds` (no recording) and returns its per-step profile.
// `threads` overrides the scene's WorldSettings::threads.
RunProfile profileScene(const std::string& path, double seconds, const std::string& sampler,
                        const FrictionProviders& providers = FrictionProviders::builtIn(),
                        std::optional<int> threads = std::nullopt);

// One row of our Table 1: a scene's parameters and per-step timings beside the paper's.
struct TableRow {
  std::string title;  // the experiment's title (and variant), or the file name
  RunProfile ours;
  std::optional<PaperRow> paper;
};
// Runs a scene file as Table 1 does: for its experiment's duration (1 s if it belongs to none).
TableRow benchScene(const std::string& path, const std::string& sampler,
                    const FrictionProviders& providers = FrictionProviders::builtIn(),
                    std::optional<int> threads = std::nullopt);
// Every experiment scene of the catalog, from scenes_dir.
std::vector<std::string> catalogScenePaths(const std::string& scenes_dir);

}  // namespace asperity::experiments
