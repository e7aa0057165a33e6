// `asperity run SCENE.json`: load a scene, step it, and write the trajectory (CSV), per-step
// statistics (JSON) and the final state hash. Deterministic: the same scene and binary give a
// byte-identical CSV.
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/run_loop.hpp"
#include "asperity/world/state_check.hpp"
#include "asperity/world/state_file.hpp"
#include "cli_common.hpp"

namespace asperity::cli {
namespace {

struct RunOptions {
  std::string scene;
  std::optional<int64_t> steps;
  std::optional<double> seconds;
  std::string out;
  int64_t every = 1;
  std::string stats;
  std::string friction;  // empty: the scene's
  std::string frame;
  std::string sampler;
  std::optional<int> directions;        // N
  std::optional<double> patch_width;    // w (m)
  std::optional<int> patch_resolution;  // R
  std::optional<int> threads;           // worker threads of a step (0 = every core)
  bool hash = false;
  std::string save_state;                  // checkpoint written at the end (and periodically)
  std::string load_state;                  // checkpoint the run continues from
  std::optional<double> checkpoint_every;  // s of simulated time between checkpoints
};

// Appends the shortest text that reads back to the same double.
void appendNumber(std::string& line, double x) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), x);
  line.append(buffer, r.ptr);
}

// One CSV row per body: the pose of the body frame written in the scene (not the centre of
// mass), the velocity of that frame's origin, and the angular velocity (world frame).
void appendRows(std::string& text, const World& world, int64_t step) {
  for (const Body& b : world.bodies()) {
    const Transform pose = b.descriptionPose();
    const Vec3 v = b.linear_velocity + b.angular_velocity.cross(pose.position - b.pose.position);
    text += std::to_string(step);
    text += ',';
    appendNumber(text, world.time());
    text += ',' + b.name;
    const double values[] = {pose.position.x(),
                             pose.position.y(),
                             pose.position.z(),
                             pose.rotation.w(),
                             pose.rotation.x(),
                             pose.rotation.y(),
                             pose.rotation.z(),
                             v.x(),
                             v.y(),
                             v.z(),
                             b.angular_velocity.x(),
                             b.angular_velocity.y(),
                             b.angular_velocity.z()};
    for (double x : values) {
      text += ',';
      appendNumber(text, x);
    }
    text += '\n';
  }
}

nlohmann::ordered_json statsJson(const RunOptions& opt, const SceneDesc& scene, const World& world,
                                 const ProfileSums& sums, int64_t steps, double wall_s) {
  nlohmann::ordered_json j;
  j["scene"] = opt.scene;
  j["steps"] = steps;
  j["dt"] = world.settings().dt;
  j["simulated_time"] = world.time();
  j["wall_time_s"] = wall_s;
  j["bodies"] = world.bodies().size();
  j["sampler"] = scene.friction_provider;
  j["threads"] = world.settings().threads;
  // The collision set-up before the first step (World::prepare), once.
  j["prepare_ms"] = sums.prepare_ms;
  // Per-step averages (ms for the stages, as StepProfile).
  nlohmann::ordered_json per_step;
  for (const auto& [name, value] : sums.means()) per_step[name] = value;
  j["per_step"] = per_step;
  j["max_contacts"] = sums.max_contacts;
  char hash[17];
  std::snprintf(hash, sizeof(hash), "%016llx", static_cast<unsigned long long>(world.stateHash()));
  j["state_hash"] = hash;
  return j;
}

// A bar on stderr, only for a terminal and only once the run has taken a second.
class Progress {
 public:
  explicit Progress(int64_t total) : total_(total), enabled_(::isatty(STDERR_FILENO) == 1) {}
  void update(int64_t done) {
    if (!enabled_) return;
    const double elapsed = seconds();
    if (elapsed < 1.0 || elapsed - last_ < 0.1) return;
    last_ = elapsed;
    const int width = 40;
    const int filled = static_cast<int>(width * done / std::max<int64_t>(total_, 1));
    std::fprintf(stderr, "\r[%s%s] %3d%%  step %lld/%lld", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(),
                 static_cast<int>(100 * done / std::max<int64_t>(total_, 1)),
                 static_cast<long long>(done), static_cast<long long>(total_));
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\r%s\r", std::string(72, ' ').c_str());
  }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  int64_t total_;
  bool enabled_;
  bool shown_ = false;
  double last_ = 0.0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The scene with the command line's overrides applied.
SceneDesc loadWithOverrides(const RunOptions& opt, const FrictionProviders& providers) {
  SceneDesc scene = loadScene(opt.scene);
  if (!opt.friction.empty())
    scene.settings.limit_surface =
        parseName<LimitSurfaceKind>(opt.friction, kLimitSurfaceNames, "--friction");
  if (!opt.frame.empty())
    scene.settings.frame.mode = parseName<FrameMode>(opt.frame, kFrameModeNames, "--frame");
  if (!opt.sampler.empty()) {
    checkSampler(providers, opt.sampler);
    scene.friction_provider = opt.sampler;
  }
  FrictionSettings& friction = scene.settings.friction;
  if (opt.directions) friction.directions = *opt.directions;
  if (opt.patch_width) friction.patch_width = *opt.patch_width;
  if (opt.patch_resolution) friction.patch_resolution = *opt.patch_resolution;
  if (opt.threads) scene.settings.threads = *opt.threads;
  return scene;
}

// Number of steps: --steps, else ceil(--seconds / dt), else one simulated second.
int64_t stepCount(const RunOptions& opt, double dt) {
  if (opt.steps) return *opt.steps;
  return stepsFor(opt.seconds ? *opt.seconds : 1.0, dt, "--seconds");
}

// An output file's error, named by its option: "--out /dev/full: write failed: ...".
template <typename F>
void writing(const char* option, F&& write) {
  try {
    write();
  } catch (const Error& e) {
    throw Error(std::string(option) + " " + e.what());
  }
}

// The trajectory, written as the run goes: each recorded step's rows with one write(2), so a
// killed run leaves a CSV of whole rows up to the last step it recorded.
class Trajectory {
 public:
  explicit Trajectory(const RunOptions& opt) : every_(opt.every) {
    if (opt.out.empty()) return;
    writing("--out", [&] { file_ = std::make_unique<RecordFile>(opt.out); });
    rows_ = "step,time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n";
  }
  // Steps are counted by the world, so a run continued from a checkpoint records the steps
  // and rows that one uninterrupted run would.
  void record(const World& world, bool always) {
    if (!file_ || (!always && world.stepCount() % every_ != 0)) return;
    appendRows(rows_, world, world.stepCount());
    writing("--out", [&] { file_->append(rows_); });
    rows_.clear();
  }
  void finish() {
    if (file_) writing("--out", [&] { file_->sync(); });
  }

 private:
  int64_t every_;
  std::unique_ptr<RecordFile> file_;
  std::string rows_;
};

// Checkpoints: --save-state at the end and, with --checkpoint-every, each time that much
// simulated time has passed since the run began (each written atomically).
class Checkpoints {
 public:
  Checkpoints(const RunOptions& opt, const SceneDesc& scene)
      : path_(opt.save_state),
        scene_id_(opt.save_state.empty() && opt.load_state.empty() ? 0 : sceneStateId(scene)) {
    if (opt.checkpoint_every)
      period_ = std::max<int64_t>(
          1, stepsFor(*opt.checkpoint_every, scene.settings.dt, "--checkpoint-every"));
  }
  void load(World& world, const std::string& path) const { loadStateFile(world, path, scene_id_); }
  void after(const World& world, int64_t step) const {
    if (period_ > 0 && step % period_ == 0) save(world);
  }
  void save(const World& world) const {
    if (!path_.empty()) writing("--save-state", [&] { saveStateFile(world, path_, scene_id_); });
  }

 private:
  std::string path_;
  uint64_t scene_id_;
  int64_t period_ = 0;
};

void runScene(const RunOptions& opt) {
  // Scenes and --sampler may name every sampler of the tool ("gl" included).
  const FrictionProviders providers = frictionProviders();
  const SceneDesc scene = loadWithOverrides(opt, providers);
  std::unique_ptr<World> world = instantiate(scene, {providers});
  printWarnings(*world);
  // Parameters that cannot be simulated stably are named before the run (it may still work).
  for (const std::string& warning : stabilityWarnings(*world))
    std::fprintf(stderr, "asperity: warning: %s: %s\n", opt.scene.c_str(), warning.c_str());
  const Checkpoints checkpoints(opt, scene);
  if (!opt.load_state.empty()) checkpoints.load(*world, opt.load_state);
  const int64_t steps = stepCount(opt, scene.settings.dt);
  // The starting state first; then every K-th step.
  Trajectory trajectory(opt);
  trajectory.record(*world, true);
  ProfileSums sums;
  Progress progress(steps);
  const double wall_s = runSteps(*world, steps, &sums, [&](int64_t i) {
    trajectory.record(*world, false);
    checkpoints.after(*world, i);
    progress.update(i);
  });
  progress.finish();
  // Outputs: the trajectory, the checkpoint, the statistics, and the hash or a one-line
  // summary on stdout.
  trajectory.finish();
  checkpoints.save(*world);
  if (!opt.stats.empty())
    writing("--stats", [&] {
      writeFileAtomically(opt.stats,
                          statsJson(opt, scene, *world, sums, steps, wall_s).dump(2) + "\n");
    });
  if (opt.hash) {
    std::printf("%016llx\n", static_cast<unsigned long long>(world->stateHash()));
  } else {
    std::printf("%s: %lld steps, %g s simulated, %zu bodies, %.3f s wall, %.3f ms/step\n",
                opt.scene.c_str(), static_cast<long long>(steps), world->time(),
                world->bodies().size(), wall_s,
                steps > 0 ? sums.total_ms / static_cast<double>(steps) : 0.0);
  }
}

}  // namespace

void registerRunCommand(CLI::App& app) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand("run", "Simulate a scene file; write trajectory and stats");
  sub->add_option("SCENE", opt->scene, "Scene file (JSON, docs/scene-format.md)")->required();

  // How long.
  auto* steps = sub->add_option("--steps", opt->steps, "Number of steps")
                    ->check(CLI::Range(int64_t{0}, kMaxSteps));
  auto* seconds = sub->add_option("--seconds", opt->seconds,
                                  "Simulated time (s); default 1 s when --steps is not given")
                      ->check(positiveNumber());
  steps->excludes(seconds);

  // Outputs.
  sub->add_option("--out", opt->out, "Trajectory CSV: step,time,body,x,y,z,qw,qx,qy,qz,v,w");
  sub->add_option("--every", opt->every, "Record every K-th step in the CSV")
      ->check(CLI::Range(int64_t{1}, kMaxSteps))
      ->capture_default_str();
  sub->add_option("--stats", opt->stats, "Per-step averages (contacts, stage times) as JSON");
  sub->add_flag("--hash", opt->hash, "Print the final state hash (16 hex digits)");
  sub->add_option("--save-state", opt->save_state,
                  "Checkpoint file of the final state (binary; docs/checkpoints.md)");
  sub->add_option("--load-state", opt->load_state,
                  "Continue from a checkpoint of this scene (--seconds/--steps: how much more)")
      ->check(CLI::ExistingFile);
  sub->add_option("--checkpoint-every", opt->checkpoint_every,
                  "Also write --save-state each time this much simulated time has passed (s)")
      ->check(positiveNumber())
      ->needs(sub->get_option("--save-state"));

  // Overrides of the scene's settings.
  sub->add_option("--friction", opt->friction, "Limit surface: coulomb, box or polygon")
      ->check(CLI::IsMember(namesOf<LimitSurfaceKind>(kLimitSurfaceNames)));
  sub->add_option("--frame", opt->frame, "Contact frame: world, body, auto or texture")
      ->check(CLI::IsMember(namesOf<FrameMode>(kFrameModeNames)));
  sub->add_option(
      "--sampler", opt->sampler,
      "Friction provider replacing the scene's friction_provider (constant, cone, cpu, ...)");
  sub->add_option("--directions", opt->directions, "Sample directions N (SPEC 1)")
      ->check(settingRange("directions", friction_range::directions));
  sub->add_option("--patch-width", opt->patch_width, "Patch width w (m, SPEC 3)")
      ->check(settingRange("patch_width", friction_range::patch_width));
  sub->add_option("--threads", opt->threads,
                  "Worker threads of a step (0 = every core); the results do not change")
      ->check(CLI::Range(0, kMaxThreads));
  sub->add_option("--patch-res", opt->patch_resolution, "Patch resolution R (pixels per side)")
      ->check(settingRange("patch_resolution", friction_range::patch_resolution));

  sub->callback([opt] { runScene(*opt); });
}

}  // namespace asperity::cli
