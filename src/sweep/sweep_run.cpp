// Running a sweep: each sample builds its own scene and world, runs it on a oneTBB pool and
// records final poses, measures and the state hash; the table is written as CSV.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numeric>

#include "asperity/error.hpp"
#include "asperity/scene/friction_providers.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/sweep/sweep.hpp"
#include "asperity/world/run_loop.hpp"

namespace asperity {
namespace {

// "KIND:BODY" as (kind index, body index). Throws naming the measure.
std::pair<int, size_t> resolveMeasure(const std::string& name,
                                      const std::vector<std::string>& bodies) {
  const size_t colon = name.find(':');
  const std::string kind = name.substr(0, colon);
  int k = 0;
  while (k < 4 && kind != kMeasureKinds[k]) ++k;
  if (colon == std::string::npos || k == 4)
    throw SweepError(SweepField::Measures, "'" + name + "'",
                     "expected KIND:BODY with KIND one of distance, speed, angle, height");
  const std::string body = name.substr(colon + 1);
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i] == body) return {k, i};
  throw SweepError(SweepField::Measures, "'" + name + "'",
                   "the scene has no body named '" + body + "'");
}

// The value of one built-in measure from the start and end of a run.
double measure(int kind, const Transform& start, const Transform& end, const Vec3& velocity) {
  switch (kind) {
    case 0:
      return (end.position - start.position).norm();
    case 1:
      return velocity.norm();
    case 2:
      return start.rotation.angularDistance(end.rotation) * 180.0 / kPi;
    default:
      return end.position.z();
  }
}

// Appends the shortest text that reads back to the same double.
void appendNumber(std::string& line, double x) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), x);
  line.append(buffer, r.ptr);
}

// The scene's JSON text parsed; a parse error names the file.
std::shared_ptr<const nlohmann::json> parseSceneText(const SweepDesc& desc) {
  try {
    return std::make_shared<const nlohmann::json>(nlohmann::json::parse(desc.scene_json));
  } catch (const nlohmann::json::exception& e) {
    throw Error(desc.scene_file + ": not valid JSON: " + e.what());
  }
}

}  // namespace

Sweep::Sweep(SweepDesc desc) : desc_(std::move(desc)) {
  // Counts and time first, then every path against the unmodified scene.
  if (desc_.samples < 1 || desc_.samples > 100000000)
    throw SweepError(SweepField::Samples, "",
                     "must be in 1..100000000, got " + std::to_string(desc_.samples));
  if (!std::isfinite(desc_.seconds) || desc_.seconds < 0.0)
    throw SweepError(SweepField::Seconds, "", "must be a finite number >= 0");
  scene_ = parseSceneText(desc_);
  for (const Variation& v : desc_.vary) pointers_.push_back(expandPath(*scene_, v.path));
  // The scene itself must load; its bodies name the pose columns and the measures.
  const SceneDesc scene = parseScene(*scene_, desc_.scene_file);
  // Pool threads have no OpenGL context: only the core's samplers run in a sweep.
  const FrictionProviders core = FrictionProviders::builtIn();
  if (!core.has(scene.friction_provider)) {
    std::string list;
    for (const std::string& name : core.names()) list += (list.empty() ? "" : ", ") + name;
    throw Error(desc_.scene_file + ": sampler \"" + scene.friction_provider +
                "\" cannot run in a sweep (available: " + list + ")");
  }
  for (const BodyDesc& b : scene.bodies) body_names_.push_back(b.name);
  for (const std::string& m : desc_.measures) measures_.push_back(resolveMeasure(m, body_names_));
  steps_ = stepsFor(desc_.seconds, scene.settings.dt, "seconds");
}

nlohmann::json Sweep::sceneJson(int64_t index) const {
  // The scene with this sample's values written at every matching pointer.
  const std::vector<double> drawn = values(index);
  nlohmann::json json = *scene_;
  for (size_t j = 0; j < pointers_.size(); ++j)
    for (const std::string& p : pointers_[j]) json[nlohmann::json::json_pointer(p)] = drawn[j];
  return json;
}

SampleResult Sweep::run(int64_t index) const {
  SampleResult r;
  r.index = index;
  r.values = values(index);
  std::unique_ptr<World> world;
  try {
    InstantiateOptions options;
    options.resources = resources_;
    world = instantiate(parseScene(sceneJson(index), desc_.scene_file), options);
  } catch (const Error& e) {
    throw Error("sample " + std::to_string(index) + ": " + e.what());
  }
  // Start poses for the measures, then the run.
  std::vector<Transform> start;
  for (const Body& b : world->bodies()) start.push_back(b.descriptionPose());
  runSteps(*world, steps_);
  // Final state in the CSV's frame: the description frame's origin and its velocity.
  for (const Body& b : world->bodies()) {
    const Transform pose = b.descriptionPose();
    r.poses.push_back(pose);
    r.linear_velocities.push_back(b.linear_velocity +
                                  b.angular_velocity.cross(pose.position - b.pose.position));
    r.angular_velocities.push_back(b.angular_velocity);
  }
  for (const auto& [kind, body] : measures_)
    r.measures.push_back(measure(kind, start[body], r.poses[body], r.linear_velocities[body]));
  r.state_hash = world->stateHash();
  return r;
}

std::vector<SampleResult> Sweep::runAll(int threads, std::span<const int64_t> indices) const {
  std::vector<int64_t> all;
  if (indices.empty()) {
    all.resize(static_cast<size_t>(desc_.samples));
    std::iota(all.begin(), all.end(), int64_t{0});
    indices = all;
  }
  for (int64_t i : indices)
    if (i < 0 || i >= desc_.samples)
      throw Error("sample index " + std::to_string(i) + " is outside 0.." +
                  std::to_string(desc_.samples - 1));
  if (threads < 0) throw SweepError(SweepField::Threads, "", "must be >= 0 (0 = every core)");
  // One task per sample, each writing its own slot: the order of completion cannot matter.
  std::vector<SampleResult> results(indices.size());
  tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : threads);
  arena.execute([&] {
    tbb::parallel_for(size_t{0}, indices.size(), [&](size_t k) { results[k] = run(indices[k]); });
  });
  return results;
}

// Hands results to `emit` in index order from whichever worker completes the next one.
class InOrder {
 public:
  InOrder(int64_t first, const std::function<void(const SampleResult&)>& emit)
      : next_(first), emit_(emit) {}

  void done(SampleResult result) {
    const std::lock_guard lock(mutex_);
    waiting_.emplace(result.index, std::move(result));
    while (!waiting_.empty() && waiting_.begin()->first == next_ && next_ < failed_at_) {
      emit_(waiting_.begin()->second);
      waiting_.erase(waiting_.begin());
      ++next_;
    }
  }
  // Keeps the lowest failing sample's error; rows stop before it.
  void failed(int64_t index, std::exception_ptr error) {
    const std::lock_guard lock(mutex_);
    if (index < failed_at_) {
      failed_at_ = index;
      error_ = error;
    }
  }
  bool failedBefore(int64_t index) {
    const std::lock_guard lock(mutex_);
    return failed_at_ < index;
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::map<int64_t, SampleResult> waiting_;
  int64_t next_;
  int64_t failed_at_ = INT64_MAX;
  std::exception_ptr error_;
  const std::function<void(const SampleResult&)>& emit_;
};

void Sweep::runInOrder(int threads, int64_t first,
                       const std::function<void(const SampleResult&)>& emit) const {
  if (threads < 0) throw SweepError(SweepField::Threads, "", "must be >= 0 (0 = every core)");
  if (first < 0 || first > desc_.samples)
    throw Error("first sample " + std::to_string(first) + " is outside 0.." +
                std::to_string(desc_.samples));
  // Each worker takes the next index in turn, so rows finish close to their order and few
  // wait for a lower one.
  std::atomic<int64_t> counter{first};
  InOrder order(first, emit);
  tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : threads);
  arena.execute([&] {
    tbb::parallel_for(0, arena.max_concurrency(), [&](int) {
      for (int64_t i = counter++; i < desc_.samples && !order.failedBefore(i); i = counter++) {
        try {
          order.done(run(i));
        } catch (...) {
          order.failed(i, std::current_exception());
        }
      }
    });
  });
  order.rethrow();
}

std::vector<std::string> Sweep::columns() const {
  std::vector<std::string> names = {"sample"};
  for (const Variation& v : desc_.vary) names.push_back(v.path);
  for (const std::string& body : body_names_)
    for (const char* c : {".x", ".y", ".z", ".qw", ".qx", ".qy", ".qz"}) names.push_back(body + c);
  for (const std::string& m : desc_.measures) names.push_back(m);
  names.push_back("state_hash");
  return names;
}

std::string Sweep::csvHeader() const {
  std::string text;
  const std::vector<std::string> names = columns();
  for (size_t i = 0; i < names.size(); ++i) text += (i ? "," : "") + names[i];
  return text + '\n';
}

std::string Sweep::csvRow(const SampleResult& r) const {
  // Index, values, poses, measures, hash.
  std::string text = std::to_string(r.index);
  auto add = [&text](double x) {
    text += ',';
    appendNumber(text, x);
  };
  for (double v : r.values) add(v);
  for (const Transform& p : r.poses) {
    for (int k = 0; k < 3; ++k) add(p.position[k]);
    for (double q : {p.rotation.w(), p.rotation.x(), p.rotation.y(), p.rotation.z()}) add(q);
  }
  for (double m : r.measures) add(m);
  char hash[20];
  std::snprintf(hash, sizeof(hash), ",%016llx\n", static_cast<unsigned long long>(r.state_hash));
  return text + hash;
}

std::string Sweep::csv(std::span<const SampleResult> results) const {
  std::string text = csvHeader();
  for (const SampleResult& r : results) text += csvRow(r);
  return text;
}

}  // namespace asperity
