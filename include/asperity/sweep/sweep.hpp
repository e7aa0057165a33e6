// Ensembles of runs (`asperity sweep`, asperity.sweep in Python): one scene, some of its
// numbers varied per sample, every sample an independent world run for the same time.
//
// A variation is `PATH=SPEC`: PATH is a JSON pointer into the scene file, where a `*` segment
// stands for every element of an array (`/bodies/*/linear_velocity/0`); SPEC is
// `uniform(a,b)`, `normal(m,s)`, `choice(v1,v2,...)` or `grid(a,b,n)`. One value is drawn per
// variation and sample and written to every path the variation matches. Sample i of seed S
// draws from its own generator seeded by (S, i, variation), so it gives the same bytes
// whatever the thread count or the order samples run in. Grids enumerate their n values in
// mixed radix over the sample index (the first grid varies fastest).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/types.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity {

// The part of a sweep's description an error concerns. The library names them in its own
// words (variation, measure, samples, seconds, threads); a front end names its own option for
// each (the CLI: --vary, --measure, --samples, --seconds, --threads).
enum class SweepField { Vary, Measures, Samples, Seconds, Threads };

// A sweep's description rejected. what() reads "WORD SUBJECT: PROBLEM", e.g.
// "variation '/a=beta(1,2)': unknown distribution 'beta' (available: ...)" or
// "samples: must be in 1..100000000, got 0" (no subject for a number).
class SweepError : public Error {
 public:
  SweepError(SweepField field, std::string subject, std::string problem);

  SweepField field() const { return field_; }
  // The culprit as written ("'/a=beta(1,2)'", "/bodies/*/x", "'volume:box'"); empty for a number.
  const std::string& subject() const { return subject_; }
  const std::string& problem() const { return problem_; }
  // The message with the field called `name` instead (e.g. "--vary '/a=beta(1,2)': ...").
  std::string messageNaming(const std::string& name) const;

 private:
  SweepField field_;
  std::string subject_, problem_;
};

enum class Distribution { Uniform, Normal, Choice, Grid };

struct Variation {
  std::string path;  // as written, `*` segments unexpanded
  Distribution distribution = Distribution::Uniform;
  std::vector<double> args;  // uniform: a, b; normal: mean, sd; choice: values; grid: a, b, n
};

// Parses "PATH=SPEC". Throws SweepError (SweepField::Vary) "variation 'TEXT': what is wrong".
Variation parseVariation(const std::string& text);
// Parses SPEC for PATH. Throws like parseVariation.
Variation parseVariation(const std::string& path, const std::string& spec);

// The JSON pointers a path matches in `scene` (every `*` expanded, in array order). Throws
// SweepError (SweepField::Vary) "variation PATH: ..." when a segment is missing or a match is
// not a number.
std::vector<std::string> expandPath(const nlohmann::json& scene, const std::string& path);

// Built-in measures, named "KIND:BODY": distance (m the body frame's origin moved from its
// start), speed (m/s of that origin at the end), angle (deg turned from the start), height (z
// at the end, m).
inline constexpr const char* kMeasureKinds[] = {"distance", "speed", "angle", "height"};

struct SweepDesc {
  std::string scene_json;  // the scene file's text (JSON)
  std::string scene_file;  // for messages; relative paths resolve against its folder
  std::vector<Variation> vary;
  int64_t samples = 1;
  uint64_t seed = 1;
  double seconds = 1.0;               // simulated per sample
  std::vector<std::string> measures;  // "KIND:BODY"
};

// One finished sample.
struct SampleResult {
  int64_t index = 0;
  std::vector<double> values;  // one per variation
  // Every body in scene order, as `asperity run`'s CSV: the pose of the frame the scene wrote
  // (x, y, z, qw, qx, qy, qz), the velocity of its origin and the angular velocity.
  std::vector<Transform> poses;
  std::vector<Vec3> linear_velocities;
  std::vector<Vec3> angular_velocities;
  std::vector<double> measures;  // one per SweepDesc::measures
  uint64_t state_hash = 0;
};

// The plan of a sweep, checked: paths expanded, measures resolved, body names read.
class Sweep {
 public:
  // Throws SweepError for a bad variation, path, sample count, time or measure, and
  // asperity::Error for a scene that does not parse or load.
  explicit Sweep(SweepDesc desc);

  const SweepDesc& desc() const { return desc_; }
  const std::vector<std::string>& bodyNames() const { return body_names_; }
  // The values sample `index` takes, one per variation (no world is built).
  std::vector<double> values(int64_t index) const;
  // The scene's JSON with sample `index`'s values written at every pointer its variations
  // match: what run() builds the sample's world from (asperity::Batch builds its worlds so too).
  nlohmann::json sceneJson(int64_t index) const;
  // Builds the scene with sample `index`'s values, runs it for desc().seconds and records it.
  // Throws asperity::Error naming the sample when the varied scene is invalid.
  SampleResult run(int64_t index) const;
  // Runs the given samples (all when empty) on `threads` threads of a oneTBB pool (0 = every
  // core); results come back in the order of `indices`, identical for any thread count.
  // Throws SweepError (SweepField::Threads) for a negative thread count.
  std::vector<SampleResult> runAll(int threads, std::span<const int64_t> indices = {}) const;
  // Runs samples first .. samples - 1 on `threads` threads (0 = every core), taken in index
  // order, and hands each result to `emit` in index order as soon as it and every lower one
  // are done (`emit` runs on one thread at a time). When a sample fails, the ones below it
  // are still handed over, then its error is thrown (the lowest failing index's).
  void runInOrder(int threads, int64_t first,
                  const std::function<void(const SampleResult&)>& emit) const;

  // Column names of the table: sample, the variations' paths, each body's
  // NAME.x .. NAME.qz, the measures, state_hash.
  std::vector<std::string> columns() const;
  // The table as CSV (header, then one row per result; numbers in shortest round-trip form).
  std::string csv(std::span<const SampleResult> results) const;
  // Its header line and one result's row, each ending in a newline.
  std::string csvHeader() const;
  std::string csvRow(const SampleResult& result) const;

 private:
  SweepDesc desc_;
  std::shared_ptr<const nlohmann::json> scene_;     // desc_.scene_json parsed
  std::vector<std::vector<std::string>> pointers_;  // per variation, its expanded pointers
  std::vector<std::string> body_names_;
  std::vector<std::pair<int, size_t>> measures_;  // (kind index, body index)
  // Textures and meshes loaded once and shared by every sample's world.
  std::shared_ptr<SceneResources> resources_ = std::make_shared<SceneResources>();
  int64_t steps_ = 0;
};

// A sweep written to a CSV file as it runs (`asperity sweep --out`, Python's sweep(out=)):
// the header first, then each sample's row as soon as it and every lower one are done, each
// row one write, so a process killed at any moment leaves a valid CSV of every sample it
// finished, in order. Beside a regular file, PATH.sweep (the journal) describes the sweep
// while it runs and is removed when it ends; `resume` continues a killed sweep from the rows
// the file holds and gives the bytes of an uninterrupted run, for any thread count.
struct SweepFileOptions {
  std::string path;
  int threads = 0;      // 0 = every core
  bool resume = false;  // continue the sweep the file and its journal hold
};
// A results file or its journal that cannot be written, read or resumed; what() names the file.
class SweepFileError : public Error {
 public:
  using Error::Error;
};
// The journal's path for a results file, and what it holds for a sweep while the sweep runs
// (JSON: the scene file and a hash of its text, the variations, samples, seed, seconds and
// measures).
std::string sweepJournalPath(const std::string& path);
std::string sweepJournal(const Sweep& sweep);
// Runs the sweep into options.path; returns how many samples ran now (0: a resumed file was
// complete). Throws SweepFileError naming the file: it cannot be written, or (resume) it or
// its journal belongs to another sweep, is missing, or is not this sweep's table; and what
// Sweep::runInOrder throws for a failing sample, after the rows below it are written.
int64_t runSweepToFile(const Sweep& sweep, const SweepFileOptions& options);

}  // namespace asperity
