// Batches of worlds (SPEC 14): n independent worlds of one scene, each with its own values of
// the scene's varied numbers, stepped together on a oneTBB pool with actions for all worlds at
// once, and reset one by one. This is what a learning loop drives (asperity.Batch in Python).
//
// World i takes the values that sample i of a sweep of the same scene, variations and seed
// takes (asperity/sweep/sweep.hpp: the same parsing, pointers and draws), so world i of a batch
// is bit for bit a World instantiated from the scene with sample i's values written in
// (Sweep::sceneJson) and given the same actions, whatever the thread count: each world steps on
// one thread of the pool, alone.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "asperity/sweep/sweep.hpp"
#include "asperity/world/world.hpp"

namespace asperity {

class ThreadPool;

struct BatchDesc {
  std::string scene_json;  // the scene file's text (JSON)
  std::string scene_file;  // for messages; relative paths resolve against its folder
  std::vector<Variation> vary;
  int64_t worlds = 1;  // n, in 1..kMaxBatchWorlds
  uint64_t seed = 0;
  // Threads of the pool the worlds step on (0 = every core). Each world steps on one of them
  // (its own WorldSettings::threads is 1), so the results never depend on this.
  int threads = 0;
};

inline constexpr int64_t kMaxBatchWorlds = 1000000;

// What an action sets before each step of the next Batch::step call.
enum class BatchAction {
  Force,            // N, world frame, at the body frame's origin (a one-step load)
  Torque,           // N m, world frame (a one-step load)
  AngularVelocity,  // rad/s, world frame: the body's angular velocity is set to it
  LinearVelocity,   // m/s of the body frame's origin (after the angular velocity is set)
  JointTarget       // m: a distance joint's rest length (World::setJointRestLength); it stays
};

// Body states of every world, world-major, in the frame the scene wrote (as the CLI's CSV and
// asperity.World's state arrays): element (i, b, k) of a row of width W is at (i B + b) W + k.
struct BatchState {
  std::vector<double> positions;           // (n, B, 3): origin of each body's frame (m)
  std::vector<double> orientations;        // (n, B, 4): its unit quaternion w, x, y, z
  std::vector<double> linear_velocities;   // (n, B, 3): velocity of that origin (m/s)
  std::vector<double> angular_velocities;  // (n, B, 3): world frame (rad/s)
};

class Batch {
 public:
  // Builds the n worlds (in parallel). Throws asperity::Error for a bad world count, variation
  // or thread count, or a scene that does not load ("world i: ..." when a varied one fails).
  explicit Batch(BatchDesc desc);
  ~Batch();
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  int64_t size() const { return static_cast<int64_t>(worlds_.size()); }
  const BatchDesc& desc() const { return desc_; }
  const std::vector<std::string>& bodyNames() const { return sweep_.bodyNames(); }
  const std::vector<std::string>& jointNames() const { return joint_names_; }
  // Index of a named body or joint; throws asperity::Error naming it and listing the known ones.
  BodyId bodyIndex(std::string_view name) const;
  JointId jointIndex(std::string_view name) const;

  // The sample world i was built from (i at first; Batch::reset may give it another), and the
  // values that sample drew, one per variation (Sweep::values).
  int64_t sample(int64_t world) const { return samples_.at(static_cast<size_t>(world)); }
  std::span<const double> values(int64_t world) const;
  const World& world(int64_t i) const { return *worlds_.at(static_cast<size_t>(i)); }

  // Sets an action for every world: `values` holds n rows of 3 numbers (n numbers for
  // JointTarget), finite. It applies before each step of the next step() call and is then
  // cleared (a joint target stays, as the joint keeps its length). Setting the same action on
  // the same body again replaces it. Throws asperity::Error naming the body or joint: forces
  // and torques need a dynamic body, velocities a body that is not static, joint targets a
  // distance joint.
  void setAction(BatchAction action, uint32_t target, std::span<const double> values);
  void clearActions() { actions_.clear(); }

  // Steps every world `steps` times (each world's steps on one pool thread), then refreshes
  // state(). A world whose step throws (StepError) stops there; the others finish, and the
  // error of the lowest such world is thrown as "world i: ...".
  void step(int64_t steps = 1);

  // Puts the worlds whose mask entry is non-zero (all when `mask` is empty) back to the start:
  // each is instantiated anew, so it evolves exactly as a new world, contact history included
  // (World::prepare builds its collision objects here rather than in its first step).
  // With `samples` (n entries) world i becomes sample samples[i] with its values. With `state`,
  // each of its arrays that is not empty (full (n, B, W) size) then replaces that part of the
  // initial state (quaternions normalised), and the contact history is forgotten
  // (World::forgetContactHistory). Throws asperity::Error for a bad size, a non-finite number
  // or a zero quaternion, before any world changes.
  void reset(std::span<const uint8_t> mask = {}, const BatchState* state = nullptr,
             std::span<const int64_t> samples = {});

  // The state after the last step or reset (refreshed in place: its buffers never move).
  const BatchState& state() const { return state_; }
  // World::stateHash of every world.
  std::vector<uint64_t> stateHashes() const;

 private:
  struct Action {
    BatchAction kind;
    uint32_t target;
    std::vector<double> values;
  };
  // World i anew as sample `sample`, with its drawn values and the non-empty parts of
  // `given` (or none), prepared for its first step.
  void rebuild(size_t i, int64_t sample, const BatchState* given);
  // The actions, applied to world i before one of its steps.
  void applyActions(size_t i);
  // Copies world i's bodies into its rows of state_.
  void gather(size_t i);
  // Writes world i's rows of `given` (its non-empty arrays) into its bodies.
  void scatter(size_t i, const BatchState& given);
  // Throws unless `given`'s non-empty arrays have full size and the rows of `worlds` are
  // finite with non-zero quaternions.
  void checkGiven(const BatchState& given, std::span<const size_t> worlds) const;

  BatchDesc desc_;
  Sweep sweep_;  // the variations: parsed, expanded and drawn as a sweep does
  std::shared_ptr<SceneResources> resources_ = std::make_shared<SceneResources>();
  std::unique_ptr<ThreadPool> pool_;
  std::vector<std::unique_ptr<World>> worlds_;
  std::vector<int64_t> samples_;
  std::vector<double> values_;  // (n, variations)
  std::vector<std::string> joint_names_;
  std::vector<Action> actions_;
  BatchState state_;
};

}  // namespace asperity
