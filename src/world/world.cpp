// The world: bodies, joints and drivers, and the step that runs the stages in order
// (docs/step.md). The stages live in their folders: dynamics/drivers, collision/, frames/,
// sampler/, solver/ (solve_stage), dynamics/integrate; world_solve.cpp hands them the world's
// data.
#include "asperity/world/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "asperity/error.hpp"
#include "asperity/sampler/cone_provider.hpp"
#include "asperity/world/state_check.hpp"
#include "collision/collision_detector.hpp"
#include "dynamics/drivers.hpp"
#include "math/stopwatch.hpp"
#include "parallel/thread_pool.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

World::World(WorldSettings settings)
    : settings_(std::move(settings)),
      collision_(std::make_unique<CollisionDetector>()),
      solver_(std::make_unique<ContactSolver>()),
      provider_(std::make_unique<ConeProvider>()) {}

World::~World() = default;

const ThreadPool& World::threadPool() {
  // Made again only when the setting changes (a pool starts its threads once).
  if (!pool_ || pool_->requested() != settings_.threads) {
    if (settings_.threads < 0 || settings_.threads > kMaxThreads)
      throw Error("world settings: threads must be in 0.." + std::to_string(kMaxThreads) +
                  " (0 = every core), got " + std::to_string(settings_.threads));
    pool_ = std::make_unique<ThreadPool>(settings_.threads);
  }
  return *pool_;
}

void World::step() {
  if (!(settings_.dt > 0.0)) throw Error("world settings: dt must be > 0");
  if (settings_.iterations < 1) throw Error("world settings: iterations must be >= 1");
  if (settings_.substeps < 1) throw Error("world settings: substeps must be >= 1");
  const ThreadPool& pool = threadPool();
  provider_->setThreadPool(&pool);
  solver_->setThreadPool(&pool);
  StepProfile p;
  Stopwatch clock;
  // 1. Gravity, springs and loads change the velocities (first half of semi-implicit Euler).
  applyDrivers(bodies_, springs_, loads_, settings_.gravity, time_, settings_.dt);
  p.ms(Stage::Drivers) = clock.lap();
  // 2. Contacts from the current poses (normal B -> A, phi, witness points, keys).
  collide();
  p.ms(Stage::Collide) = clock.lap();
  // 3. Each contact's tangent frame (t, b) by the frame mode (SPEC 5).
  computeContactFrames(settings_.frame.mode, frameInputs(), contacts_, &pool);
  p.ms(Stage::Frames) = clock.lap();
  // 4. Per-direction friction coefficients of every contact started (SPEC 3, Eq. 7).
  computeFriction();
  p.ms(Stage::Friction) = clock.lap();
  // 5. PGS on velocities: joints, contacts with limit-surface friction, split impulses; it
  // awaits the coefficients after building its rows.
  solve(p);
  p.ms(Stage::Solve) = clock.lap();
  // 6. Positions and orientations from the new velocities (plus position corrections).
  integrate();
  p.ms(Stage::Integrate) = clock.lap();
  // 7. The clock, and what the step saw.
  time_ += settings_.dt;
  ++steps_;
  p.total_ms = clock.total();
  recordContacts(p);
  profile_ = p;
  // 8. No silent NaN or explosion: an unusable state stops the run here.
  checkWorldState(*this, steps_);
}

void World::recordContacts(StepProfile& p) const {
  const ProviderStats stats = provider_->lastStats();
  p.patch_ms = stats.patch_ms;
  p.averaging_ms = stats.averaging_ms;
  p.reused = stats.reused;
  p.contacts = static_cast<int>(contacts_.size());
  p.fallbacks = static_cast<int>(std::count_if(contacts_.begin(), contacts_.end(),
                                               [](const Contact& c) { return c.fallback; }));
}

BodyId World::createBody(const BodyDesc& desc) {
  // Surfaces arrive resolved (a scene's instantiate(), or resolveSurfaces): no file is read here.
  for (size_t i = 0; i < desc.shapes.size(); ++i)
    if (const std::string part = unresolvedPart(desc.shapes[i].surface); !part.empty())
      throw Error("body \"" + desc.name + "\" shape " + std::to_string(i) + ": its surface's " +
                  part +
                  " is not resolved; call resolveSurfaces(desc.shapes, "
                  "world.diagnostics()) (asperity/geometry/shape.hpp) before createBody");
  bodies_.push_back(makeBody(desc));
  bodies_changed_ = true;
  return static_cast<BodyId>(bodies_.size() - 1);
}

void World::checkBody(BodyId id, const std::string& what) const {
  if (id >= bodies_.size()) {
    throw Error(what + ": body id " + std::to_string(id) + " does not exist");
  }
}

JointId World::createJoint(const JointDesc& desc) {
  const std::string what = "joint '" + desc.name + "'";
  checkBody(desc.body_a, what);
  checkBody(desc.body_b, what);
  if (desc.body_a == desc.body_b) throw Error(what + ": joins a body to itself");
  JointDesc joint = desc;
  const Body& a = bodies_[desc.body_a];
  const Body& b = bodies_[desc.body_b];
  // A negative rest length means "as placed": the anchors' current distance.
  const Vec3 pa = a.descriptionPose().apply(desc.anchor_a);
  const Vec3 pb = b.descriptionPose().apply(desc.anchor_b);
  if (joint.type == JointType::Distance && joint.rest_length < 0.0) {
    joint.rest_length = (pa - pb).norm();
  }
  if (joint.type == JointType::Hinge &&
      (desc.axis_a.norm() < 1e-12 || desc.axis_b.norm() < 1e-12)) {
    throw Error(what + ": hinge axis has zero length");
  }
  joints_.push_back(joint);
  joint_rest_rotation_.push_back(a.pose.rotation.conjugate() * b.pose.rotation);
  if (!desc.collide_connected) {
    collision_->ignorePair(desc.body_a, desc.body_b);
    bodies_changed_ = true;
  }
  return static_cast<JointId>(joints_.size() - 1);
}

SpringId World::addSpring(const SpringDesc& desc) {
  checkBody(desc.body, "spring '" + desc.name + "'");
  if (desc.stiffness < 0.0 || desc.damping < 0.0) {
    throw Error("spring '" + desc.name + "': stiffness and damping must be >= 0");
  }
  springs_.push_back(desc);
  return static_cast<SpringId>(springs_.size() - 1);
}

LoadId World::addLoad(const LoadDesc& desc) {
  checkBody(desc.body, "load '" + desc.name + "'");
  if (!desc.value.allFinite()) throw Error("load '" + desc.name + "': value is not finite");
  loads_.push_back(desc);
  return static_cast<LoadId>(loads_.size() - 1);
}

size_t World::removeFinishedLoads() {
  // The same tolerance as the drivers' stage: a load ending or firing within 1e-9 dt of now.
  const double eps = 1e-9 * settings_.dt;
  const auto finished = [&](const LoadDesc& l) {
    const bool once = l.kind == LoadDesc::Kind::Impulse || l.kind == LoadDesc::Kind::AngularImpulse;
    return once ? l.start < time_ - eps : time_ >= l.end - eps;
  };
  return std::erase_if(loads_, finished);
}

void World::setFrictionProvider(std::unique_ptr<FrictionProvider> provider) {
  if (!provider) throw Error("World::setFrictionProvider: provider is null");
  provider_ = std::move(provider);
}

Body& World::body(BodyId id) {
  checkBody(id, "World::body");
  return bodies_[id];
}

const Body& World::body(BodyId id) const {
  checkBody(id, "World::body");
  return bodies_[id];
}

BodyId World::findBody(std::string_view name) const {
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].name == name) return static_cast<BodyId>(i);
  }
  return kNoBody;
}

double World::jointError(JointId id) const {
  const JointDesc& j = joints_.at(id);
  const Vec3 pa = bodies_[j.body_a].descriptionPose().apply(j.anchor_a);
  const Vec3 pb = bodies_[j.body_b].descriptionPose().apply(j.anchor_b);
  // Distance joints: deviation from the current target length; others: anchor separation.
  if (j.type == JointType::Distance) {
    return std::abs((pa - pb).norm() - distanceJointLength(j, time_));
  }
  return (pa - pb).norm();
}

void World::setJointRestLength(JointId id, double length) {
  if (id >= joints_.size()) throw Error("joint id " + std::to_string(id) + " does not exist");
  JointDesc& j = joints_[id];
  if (j.type != JointType::Distance)
    throw Error("joint '" + j.name + "': only distance joints have a rest length");
  if (!std::isfinite(length) || length < 0.0)
    throw Error("joint '" + j.name + "': rest length must be a finite number >= 0 (m)");
  j.rest_length = length;
}

void World::forgetContactHistory() {
  // Collision is rebuilt before the next step: new pairs, found in the same order as in a new
  // world, with new persistent points numbered from 1.
  bodies_changed_ = true;
  collision_->restartPointIds();
  solver_->forgetWarmStart();
  provider_->forgetHistory();
  contacts_.clear();
}

uint64_t World::stateHash() const {
  // FNV-1a over the bit patterns of the doubles (bit-exact, platform byte order).
  uint64_t hash = 1469598103934665603ull;
  auto mix = [&hash](double value) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &value, sizeof(double));
    for (const unsigned char byte : bytes) {
      hash ^= byte;
      hash *= 1099511628211ull;
    }
  };
  for (const Body& b : bodies_) {
    for (int k = 0; k < 3; ++k) mix(b.pose.position[k]);
    for (int k = 0; k < 4; ++k) mix(b.pose.rotation.coeffs()[k]);
    for (int k = 0; k < 3; ++k) mix(b.linear_velocity[k]);
    for (int k = 0; k < 3; ++k) mix(b.angular_velocity[k]);
  }
  return hash;
}

}  // namespace asperity
