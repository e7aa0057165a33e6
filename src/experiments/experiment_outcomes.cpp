// Running the experiments' scenes and recording them, and the catalog. Each experiment, with its
// paper's Table 1 rows and its measurements, lives in a file of its own in this folder.
#include "experiment_outcomes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/world/run_loop.hpp"
#include "experiment_support.hpp"

namespace asperity::experiments {

double Outcome::value(const std::string& name) const {
  for (const Measure& m : measures)
    if (m.name == name) return m.value;
  throw Error("experiment '" + id + "': no measure named '" + name + "'");
}

const std::vector<Transform>& Recording::of(const std::string& name) const {
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i] == name) return poses[i];
  throw Error("recording: body '" + name + "' was not recorded");
}

namespace {

// Per-step means from the run's sums, and the state it ended in.
void finishProfile(RunProfile& p, const World& world) {
  const ProfileSums& s = p.sums;
  const double n = static_cast<double>(std::max<int64_t>(s.steps, 1));
  p.contacts = s.contacts / n;
  p.fallbacks = s.fallbacks / n;
  p.total_ms = s.total_ms / n;
  p.patch_ms = s.patch_ms / n;
  p.averaging_ms = s.averaging_ms / n;
  p.solve_ms = s.meanMs(Stage::Solve);
  p.prepare_ms = s.prepare_ms;
  p.state_hash = world.stateHash();
}

// The profile's fixed fields from the scene.
RunProfile startProfile(const std::string& file, const SceneDesc& scene, double seconds) {
  RunProfile p;
  p.scene = std::filesystem::path(file).filename().string();
  p.sampler = scene.friction_provider;
  p.dt = scene.settings.dt;
  p.mu0 = scene.settings.friction.mu0;
  p.patch_width = scene.settings.friction.patch_width;
  // Gains k of Eq. 7: moving bodies' surfaces are the paper's A, the fixed ones its B.
  for (const BodyDesc& b : scene.bodies)
    for (const Shape& shape : b.shapes) {
      double& k = b.type == BodyType::Dynamic ? p.k_a : p.k_b;
      k = std::max(k, shape.surface.gain);
    }
  p.steps = stepsFor(seconds, scene.settings.dt);
  p.threads = scene.settings.threads;
  return p;
}

}  // namespace

SceneDesc loadExperimentScene(const std::string& file, const RunOptions& options) {
  return loadScene((std::filesystem::path(options.scenes_dir) / file).string());
}

Recording simulate(const std::string& file, double seconds, const RunOptions& options,
                   const std::vector<std::string>& bodies, std::optional<FrameMode> frame) {
  return simulate(loadExperimentScene(file, options), file, seconds, options, bodies, frame);
}

Recording simulate(SceneDesc scene, const std::string& file, double seconds,
                   const RunOptions& options, const std::vector<std::string>& bodies,
                   std::optional<FrameMode> frame) {
  const std::string path = (std::filesystem::path(options.scenes_dir) / file).string();
  if (!options.sampler.empty()) scene.friction_provider = options.sampler;
  if (options.threads) scene.settings.threads = *options.threads;
  if (frame) scene.settings.frame.mode = *frame;
  Recording rec;
  rec.world = instantiate(scene, InstantiateOptions{options.providers});
  rec.profile = startProfile(file, scene, seconds);
  // Which bodies: the named ones (checked), else every dynamic body.
  std::vector<BodyId> ids;
  for (const std::string& name : bodies) {
    const BodyId id = rec.world->findBody(name);
    if (id == kNoBody) throw Error(path + ": experiment needs a body named '" + name + "'");
    ids.push_back(id);
  }
  if (bodies.empty())
    for (BodyId id = 0; id < rec.world->bodies().size(); ++id)
      if (rec.world->body(id).isDynamic()) ids.push_back(id);
  for (BodyId id : ids) rec.bodies.push_back(rec.world->body(id).name);
  rec.poses.resize(ids.size());
  // Sample 0 is the initial state; then every record_every steps and the last step.
  const int every = std::max(1, options.record_every);
  auto record = [&] {
    rec.time.push_back(rec.world->time());
    for (size_t i = 0; i < ids.size(); ++i) rec.poses[i].push_back(rec.world->body(ids[i]).pose);
  };
  record();
  rec.profile.wall_s = runSteps(*rec.world, rec.profile.steps, &rec.profile.sums, [&](int64_t i) {
    if (i % every == 0 || i == rec.profile.steps) record();
  });
  finishProfile(rec.profile, *rec.world);
  return rec;
}

RunProfile profileScene(const std::string& path, double seconds, const std::string& sampler,
                        const FrictionProviders& providers, std::optional<int> threads) {
  SceneDesc scene = loadScene(path);
  if (!sampler.empty()) scene.friction_provider = sampler;
  if (threads) scene.settings.threads = *threads;
  std::unique_ptr<World> world = instantiate(scene, InstantiateOptions{providers});
  RunProfile p = startProfile(path, scene, seconds);
  p.wall_s = runSteps(*world, p.steps, &p.sums);
  finishProfile(p, *world);
  return p;
}

const std::vector<Experiment>& experimentCatalog() {
  static const std::vector<Experiment> catalog = {
      boxesOnMaterials(),     sawtoothPlane(), stacking(),        crawlingWorm(),
      sawtoothPlaneRotated(), chainBolas(),    tumblingBunnies(), nutBolt()};
  return catalog;
}

const Experiment& findExperiment(const std::string& id) {
  std::string known;
  for (const Experiment& e : experimentCatalog()) {
    if (e.id == id) return e;
    known += (known.empty() ? "" : ", ") + e.id;
  }
  throw Error("unknown experiment '" + id + "' (known: " + known + ")");
}

std::vector<std::string> catalogScenePaths(const std::string& scenes_dir) {
  std::vector<std::string> paths;
  for (const Experiment& e : experimentCatalog())
    for (const SceneRun& run : e.scenes)
      paths.push_back((std::filesystem::path(scenes_dir) / run.file).string());
  return paths;
}

TableRow benchScene(const std::string& path, const std::string& sampler,
                    const FrictionProviders& providers, std::optional<int> threads) {
  // The experiment that owns this file name gives the duration, title and paper row.
  const std::string file = std::filesystem::path(path).filename().string();
  TableRow row;
  row.title = file;
  double seconds = 1.0;
  for (const Experiment& e : experimentCatalog())
    for (const SceneRun& run : e.scenes)
      if (run.file == file) {
        row.title = e.title + " (" + file + ")";
        row.paper = run.paper;
        seconds = run.seconds;
      }
  row.ours = profileScene(path, seconds, sampler, providers, threads);
  return row;
}

Outcome runExperiment(const std::string& id, const RunOptions& options) {
  const Experiment& e = findExperiment(id);
  Outcome out = e.run(e, options);
  out.id = e.id;
  return out;
}

}  // namespace asperity::experiments
