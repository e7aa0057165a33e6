// The simulation world: bodies, joints, drivers and the step (docs/step.md).
//
// World::step runs, in order: drivers (gravity, springs, loads) -> collide -> contact frames
// (SPEC 5) -> friction coefficients (SPEC 3) -> solve (PGS, SPEC 4) -> integrate. Each stage
// is timed into StepProfile. Results (contacts, profile) stay valid until the next step.
// z is up everywhere in Asperity.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/diagnostics.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/dynamics/driver.hpp"
#include "asperity/dynamics/joint.hpp"
#include "asperity/frames/contact_frames.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/solver/solve_stage.hpp"

namespace asperity {

// Internals of the step (src/): the world owns them but a user never touches them.
class CollisionDetector;
class ContactSolver;
class ThreadPool;
struct SolveInputs;

// Most worker threads a world may ask for (WorldSettings::threads).
inline constexpr int kMaxThreads = 1024;

struct WorldSettings {
  double dt = 0.01;     // s
  int iterations = 20;  // PGS iterations per solve (per sub-step)
  // Solves per step, each over dt / substeps with the step's contacts carried along by the
  // bodies' motion (docs/step.md). 1: one solve per step.
  int substeps = 1;
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  // m/s^2
  LimitSurfaceKind limit_surface = LimitSurfaceKind::Box;
  FrameSettings frame;
  FrictionSettings friction;
  int auto_frame_iterations = 5;  // frictionless PGS iterations of frame mode Auto
  bool warm_starting = true;
  double baumgarte = 0.2;             // fraction of the position error removed per step (1)
  double linear_slop = 0.0;           // m of penetration left alone; 0 = automatic from body sizes
  double contact_margin = 0.0;        // m, handed to collision; 0 = automatic
  double max_correction_speed = 2.0;  // m/s, cap of the position-correction velocity
  // m/s; World::step throws StepError when a dynamic body is faster (0 = no limit). Far above
  // anything the scenes do, it catches explosions before they turn into NaN.
  double max_speed = 1000.0;
  // Overlapping shape pairs the broadphase may find in a step before World::step throws
  // StepError naming the bodies in most (0 = no limit). Far above any scene's (a pile of 1000
  // cubes has a few thousand); 1000 boxes placed in one point have 499 500.
  int64_t max_pairs = 100000;
  // Worker threads of a step (oneTBB): 0 = every core, 1 = the calling thread only. Narrow
  // phase, frames, friction sampling, the solver's independent islands and integration are
  // split over them; the state after every step is the same bits whatever the count (SPEC 9).
  int threads = 1;
};

// The stages of a step, in the order World::step runs them (docs/step.md).
enum class Stage { Drivers, Collide, Frames, Friction, Solve, Integrate };
inline constexpr int kStageCount = 6;
// "drivers", "collide", "frames", "friction", "solve", "integrate".
const char* stageName(Stage stage);

// Wall-clock time of each stage of the last step (ms), and what it saw.
struct StepProfile {
  std::array<double, kStageCount> stage_ms{};  // indexed by Stage
  SolveStageTimes solve_ms{};  // the parts of Solve, indexed by SolveStage (sub-steps summed)
  double patch_ms = 0.0;       // provider's patch time, inside Friction (paper Table 1)
  double averaging_ms = 0.0;   // provider's averaging time, inside Friction (paper Table 1)
  double total_ms = 0.0;
  int contacts = 0;
  int fallbacks = 0;  // contacts whose patch was empty (mu = mu0)
  int reused = 0;     // contacts that kept an earlier patch sample (patch coherence)

  double& ms(Stage stage) { return stage_ms[static_cast<size_t>(stage)]; }
  double ms(Stage stage) const { return stage_ms[static_cast<size_t>(stage)]; }
};

// StepProfiles summed over a run, for every front end that reports per-step means (run
// --stats, bench, the experiments, the viewer, Python). Counts are summed in doubles: an int
// sum overflows after a million steps of a few thousand contacts.
struct ProfileSums {
  int64_t steps = 0;
  std::array<double, kStageCount> stage_ms{};
  SolveStageTimes solve_ms{};
  double patch_ms = 0.0, averaging_ms = 0.0, total_ms = 0.0;
  double contacts = 0.0, fallbacks = 0.0, reused = 0.0;
  int max_contacts = 0;
  double prepare_ms = 0.0;  // World::prepare before the first step: once, not per step

  void add(const StepProfile& step);
  // Per-step means, named as `asperity run --stats` writes them: contacts, fallbacks, then
  // <stage>_ms in step order with patch_ms and averaging_ms after friction_ms and the solve's
  // parts (solve_<part>_ms, SolveStage order) after solve_ms, then total_ms.
  std::vector<std::pair<std::string, double>> means() const;
  double meanMs(Stage stage) const;
};

class World {
 public:
  // Per-world hook of frame mode Body: returns the desired tangent t (need not be unit or in
  // the contact plane; it is projected).
  using FrameCallback = std::function<Vec3(const World&, const Contact&)>;

  explicit World(WorldSettings settings = {});
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Adds a body; mass and inertia come from its shapes (geometry/mass.hpp). Its surfaces must
  // be resolved (resolveSurfaces, or a scene's instantiate()): the world reads no files.
  // Throws asperity::Error naming the body for an unresolved surface, a dynamic body without
  // volume or a bad pose.
  BodyId createBody(const BodyDesc& desc);
  // Adds a joint; its id indexes joints(). Throws asperity::Error for unknown bodies.
  JointId createJoint(const JointDesc& desc);
  // Adds a spring; its id indexes springs(). Throws asperity::Error for an unknown body.
  SpringId addSpring(const SpringDesc& desc);
  // Adds a timed load; its id indexes loads() until removeFinishedLoads() drops an earlier
  // one. Throws asperity::Error for an unknown body.
  LoadId addLoad(const LoadDesc& desc);
  // Drops the loads that can no longer act (forces and torques past their end, impulses already
  // fired), so that a controller adding loads step after step keeps the list short. Returns
  // how many it dropped. The state a step produces does not change.
  size_t removeFinishedLoads();

  // The friction stage (default: ConeProvider, kDefaultFrictionProvider, as for scenes).
  void setFrictionProvider(std::unique_ptr<FrictionProvider> provider);
  const FrictionProvider& frictionProvider() const { return *provider_; }
  FrictionProvider& frictionProvider() { return *provider_; }
  void setFrameCallback(FrameCallback callback) { frame_callback_ = std::move(callback); }

  // Advances the world by settings().dt. Then checks the state (world/state_check.hpp): a
  // non-finite pose or velocity, or a dynamic body faster than settings().max_speed, throws
  // StepError (an asperity::Error naming the body, the step and the likely cause); the world
  // is then left as that step made it.
  void step();

  // Builds what the collision stage keeps for the current bodies: their collision objects and
  // each concave mesh's signed distance field (150 ms for the M4 nut of scenes/nut_bolt.json).
  // step() does this itself when bodies or ignored pairs changed; calling it first moves that
  // one-off cost out of the first step (a loading screen rather than a stall). Uses the
  // settings of the moment (contact_margin). Returns its wall-clock ms, 0 when nothing changed.
  double prepare();

  double time() const { return time_; }
  int64_t stepCount() const { return steps_; }

  std::span<const Body> bodies() const { return bodies_; }
  // After changing a body's shapes or surfaces through this, call forgetContactHistory():
  // kept patch samples (FrictionSettings::reuse_pixels) do not see such changes.
  Body& body(BodyId id);
  const Body& body(BodyId id) const;
  // The body with this name, or kNoBody.
  BodyId findBody(std::string_view name) const;

  std::span<const JointDesc> joints() const { return joints_; }
  std::span<SpringDesc> springs() { return springs_; }
  std::span<const SpringDesc> springs() const { return springs_; }
  std::span<const LoadDesc> loads() const { return loads_; }
  // Position error of joint i (m): distance between the anchors, or from the target length.
  double jointError(JointId id) const;
  // Sets distance joint `id`'s rest length (m): from the next step on it holds rest_length +
  // amplitude cos(...) (JointDesc). Throws asperity::Error for an unknown id, another joint
  // type, or a length that is not a finite number >= 0.
  void setJointRestLength(JointId id, double length);

  const std::vector<Contact>& contacts() const { return contacts_; }
  const StepProfile& profile() const { return profile_; }
  // The warnings of this world (deprecated scene keys, normal maps that are not all normals):
  // the library prints nothing; front ends read them or set a sink.
  Diagnostics& diagnostics() { return diagnostics_; }
  const Diagnostics& diagnostics() const { return diagnostics_; }
  WorldSettings& settings() { return settings_; }
  const WorldSettings& settings() const { return settings_; }

  // Forgets everything earlier steps left for the next one: the collision pairs and their
  // persistent contact points, the solver's warm-start impulses, the friction provider's kept
  // samples and the last contacts. Call it after setting bodies' poses or velocities to restart
  // from them: from then on the world evolves exactly (bit for bit) as any world of the same
  // bodies, joints and settings restarted from that state, whatever either did before. Call it
  // too after changing bodies' shapes or surfaces.
  void forgetContactHistory();
  // Everything the next step depends on, as bytes (src/world/world_state.cpp, docs/checkpoints.md):
  // the clock, every body's pose and velocities, joints' rest lengths, springs and loads, the
  // collision stage's persistence (Bullet's broadphase, pairs and persistent manifolds, point
  // ids), the solver's warm starts and the provider's kept samples. loadState puts them into a
  // world of the same scene (bodies, joints, settings, provider): from then on it steps exactly
  // (bit for bit) as the saved world would have, on any thread count. Throws asperity::Error
  // naming what does not fit (bodies, joints, provider) or a state cut short.
  std::string saveState() const;
  void loadState(std::string_view state);

  // FNV-1a over the bit patterns of every body's pose and velocities (determinism checks).
  uint64_t stateHash() const;

 private:
  void collide();
  FrameInputs frameInputs();
  void computeFriction();
  // What the solve stage and frame mode Auto's prediction read (solver/solve_stage.hpp).
  SolveInputs solveInputs();
  void solve(StepProfile& profile);
  void integrate();
  // The provider's times and the contact counts of this step into its profile.
  void recordContacts(StepProfile& p) const;
  void checkBody(BodyId id, const std::string& what) const;
  double automaticSlop() const;
  const ThreadPool& threadPool();

  WorldSettings settings_;
  std::vector<Body> bodies_;
  std::vector<JointDesc> joints_;
  std::vector<Quat> joint_rest_rotation_;  // fixed joints: q_a^-1 q_b at creation
  std::vector<SpringDesc> springs_;
  std::vector<LoadDesc> loads_;
  std::vector<Contact> contacts_;
  std::unique_ptr<CollisionDetector> collision_;
  std::unique_ptr<ContactSolver> solver_;
  std::unique_ptr<FrictionProvider> provider_;
  std::unique_ptr<ThreadPool> pool_;  // for settings_.threads, made by the first step
  FrameCallback frame_callback_;
  StepProfile profile_;
  Diagnostics diagnostics_;
  bool bodies_changed_ = true;
  double slop_ = 0.0;  // resolved linear slop (m)
  double time_ = 0.0;
  int64_t steps_ = 0;
};

}  // namespace asperity
