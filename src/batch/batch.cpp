// A batch's worlds: built from the sweep's samples on the pool, named bodies and joints, the
// drawn values, resets to a new world of the same (or another) sample, and the state hashes.
#include "asperity/batch/batch.hpp"

#include <nlohmann/json.hpp>
#include <numeric>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "batch/each_world.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {
namespace {

// The sweep whose samples the worlds are: same scene, variations and seed.
SweepDesc sweepOf(const BatchDesc& d) {
  if (d.worlds < 1 || d.worlds > kMaxBatchWorlds)
    throw Error("batch: n must be in 1.." + std::to_string(kMaxBatchWorlds) + ", got " +
                std::to_string(d.worlds));
  if (d.threads < 0 || d.threads > kMaxThreads)
    throw Error("batch: threads must be in 0.." + std::to_string(kMaxThreads) +
                " (0 = every core), got " + std::to_string(d.threads));
  SweepDesc s;
  s.scene_json = d.scene_json;
  s.scene_file = d.scene_file;
  s.vary = d.vary;
  s.samples = d.worlds;
  s.seed = d.seed;
  s.seconds = 0.0;
  return s;
}

// "NAME" among `names`, else an error listing them.
uint32_t indexOf(const std::vector<std::string>& names, std::string_view name, const char* what,
                 const char* plural) {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<uint32_t>(i);
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  throw Error(std::string("no ") + what + " named '" + std::string(name) + "' (" + plural + ": " +
              (known.empty() ? "none" : known) + ")");
}

}  // namespace

Batch::Batch(BatchDesc desc)
    : desc_(std::move(desc)),
      sweep_(sweepOf(desc_)),
      pool_(std::make_unique<ThreadPool>(desc_.threads)) {
  // Storage sized once: state() hands out views of these buffers.
  const auto n = static_cast<size_t>(desc_.worlds);
  const size_t rows = n * bodyNames().size();
  worlds_.resize(n);
  samples_.resize(n);
  values_.resize(n * desc_.vary.size());
  state_.positions.resize(rows * 3);
  state_.orientations.resize(rows * 4);
  state_.linear_velocities.resize(rows * 3);
  state_.angular_velocities.resize(rows * 3);
  // Every world on the pool: sample i's scene, its values, its state.
  std::vector<size_t> all(n);
  std::iota(all.begin(), all.end(), size_t{0});
  const std::string error = eachWorld(*pool_, all, [&](size_t i) {
    rebuild(i, static_cast<int64_t>(i), nullptr);
    gather(i);
  });
  if (!error.empty()) throw Error(error);
  for (const JointDesc& j : worlds_[0]->joints()) joint_names_.push_back(j.name);
}

Batch::~Batch() = default;

void Batch::rebuild(size_t i, int64_t sample, const BatchState* given) {
  SceneDesc scene = parseScene(sweep_.sceneJson(sample), desc_.scene_file);
  // One thread per world: the pool runs the worlds side by side.
  scene.settings.threads = 1;
  InstantiateOptions options;
  options.resources = resources_;
  worlds_[i] = instantiate(scene, options);
  // The given parts of the state, with no history behind them.
  if (given) {
    scatter(i, *given);
    worlds_[i]->forgetContactHistory();
  }
  // Collision objects now rather than in the first step (World::prepare; no bits change).
  worlds_[i]->prepare();
  // The sample and its drawn values, kept beside the world they built.
  samples_[i] = sample;
  const std::vector<double> drawn = sweep_.values(sample);
  std::copy(drawn.begin(), drawn.end(),
            values_.begin() + static_cast<std::ptrdiff_t>(i * drawn.size()));
}

void Batch::reset(std::span<const uint8_t> mask, const BatchState* state,
                  std::span<const int64_t> samples) {
  const size_t n = worlds_.size();
  // Every argument checked before any world changes.
  if (!mask.empty() && mask.size() != n)
    throw Error("reset: mask needs " + std::to_string(n) + " entries, got " +
                std::to_string(mask.size()));
  if (!samples.empty() && samples.size() != n)
    throw Error("reset: samples needs " + std::to_string(n) + " entries, got " +
                std::to_string(samples.size()));
  std::vector<size_t> chosen;
  for (size_t i = 0; i < n; ++i)
    if (mask.empty() || mask[i]) chosen.push_back(i);
  for (size_t i : chosen)
    if (!samples.empty() && samples[i] < 0)
      throw Error("reset: samples[" + std::to_string(i) + "] must be >= 0, got " +
                  std::to_string(samples[i]));
  if (state) checkGiven(*state, chosen);
  // Each chosen world anew, with the given parts of its state.
  const std::string error = eachWorld(*pool_, chosen, [&](size_t i) {
    rebuild(i, samples.empty() ? samples_[i] : samples[i], state);
    gather(i);
  });
  if (!error.empty()) throw Error(error);
}

BodyId Batch::bodyIndex(std::string_view name) const {
  return indexOf(bodyNames(), name, "body", "bodies");
}

JointId Batch::jointIndex(std::string_view name) const {
  return indexOf(joint_names_, name, "joint", "joints");
}

std::span<const double> Batch::values(int64_t world) const {
  const size_t v = desc_.vary.size();
  return std::span<const double>(values_).subspan(static_cast<size_t>(world) * v, v);
}

std::vector<uint64_t> Batch::stateHashes() const {
  std::vector<uint64_t> hashes;
  hashes.reserve(worlds_.size());
  for (const auto& w : worlds_) hashes.push_back(w->stateHash());
  return hashes;
}

}  // namespace asperity
