// Asperity's friction over another engine's contacts (asperity/engines/contact_friction.hpp):
// the engine's objects become bodies that carry only surfaces and poses, its contacts become
// Contacts, and the frame and friction stages run over them as in a World's step.
#include "asperity/engines/contact_friction.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "asperity/error.hpp"
#include "asperity/scene/friction_providers.hpp"
#include "asperity/world/world.hpp"
#include "math/stopwatch.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

// Sense memory per contact identity: (A, B, shape A, shape B, key).
using SenseKey = std::tuple<ObjectId, ObjectId, int, int, uint64_t>;
struct Senses {
  int t = 0, b = 0;  // sign A last slid with along +t and +b (0: unknown)
};

// Key-less contacts get one from their rank within their pair, in the batch's order: kept
// patch samples are still checked against where the contact lies (patch_reuse.hpp), so a
// rank that moves to another point only samples afresh.
constexpr uint64_t kRankKey = uint64_t{1} << 63;

void checkSettings(const ContactFrictionSettings& s) {
  auto fail = [](const std::string& what) { throw Error("contact friction settings: " + what); };
  validate(s.friction, "contact friction settings");
  if (s.threads < 0 || s.threads > kMaxThreads)
    fail("threads must be in 0.." + std::to_string(kMaxThreads) + " (0 = every core)");
  if (!(s.frame.sliding_speed >= 0.0)) fail("sliding_speed must be >= 0");
}

// The body that stands for an object: its shapes and where it is; no mass (nothing here
// integrates it).
Body objectBody(const ObjectDesc& desc) {
  Body body;
  body.name = desc.name;
  body.type = BodyType::Kinematic;
  body.shapes = desc.shapes;
  body.frame_axis = desc.frame_axis;
  return body;
}

bool finite(const Vec3& v) {
  return v.allFinite();
}

}  // namespace

double symmetricCoefficient(double mu_pos, double mu_neg, double velocity, int last_sense,
                            double sliding_speed) {
  // A sliding along +axis meets friction along -axis, bounded by mu_neg (SPEC 1).
  const int sense = std::abs(velocity) > sliding_speed ? (velocity > 0.0 ? 1 : -1) : last_sense;
  if (sense > 0) return mu_neg;
  if (sense < 0) return mu_pos;
  return std::max(mu_pos, mu_neg);
}

struct ContactFriction::Impl {
  ContactFrictionSettings settings;
  std::unique_ptr<FrictionProvider> provider;
  std::unique_ptr<ThreadPool> pool;
  std::vector<Body> bodies;  // one per object, in ObjectId order
  std::map<std::string, ObjectId, std::less<>> names;
  std::vector<Contact> contacts;
  std::vector<ContactFrictionResult> results;
  // Senses of the last compute, sorted by key; `next` is this compute's (kept for its room).
  std::vector<std::pair<SenseKey, Senses>> senses, next;
  std::vector<std::pair<SenseKey, size_t>> ranks;  // assignRankKeys' room
  double last_ms = 0.0;
  Diagnostics diagnostics;

  Contact toContact(const EngineContact& e, size_t index) const;
  void assignRankKeys(std::span<const EngineContact> in);
  std::vector<Vec3> linear, angular;  // frame mode Auto's velocities, by ObjectId
  void setFrames();
  void fillResults(std::span<const EngineContact> in);
};

Contact ContactFriction::Impl::toContact(const EngineContact& e, size_t index) const {
  // The messages' prefix, built only for an error.
  const auto what = [index] { return "contact " + std::to_string(index) + ": "; };
  auto checkSide = [&](ObjectId id, int shape, const char* side) {
    if (id >= bodies.size())
      throw Error(what() + "object " + side + " (" + std::to_string(id) + ") is not registered");
    if (shape < 0 || static_cast<size_t>(shape) >= bodies[id].shapes.size())
      throw Error(what() + "object '" + bodies[id].name + "' has no shape " +
                  std::to_string(shape));
  };
  checkSide(e.object_a, e.shape_a, "A");
  checkSide(e.object_b, e.shape_b, "B");
  if (!finite(e.point)) throw Error(what() + "point is not finite");
  if (!finite(e.normal) || std::abs(e.normal.norm() - 1.0) > 1e-6)
    throw Error(what() + "normal must be a unit vector");
  if (!(e.depth >= 0.0) || !std::isfinite(e.depth))
    throw Error(what() + "depth must be a finite number >= 0");
  if (!(e.normal_force >= 0.0) || !std::isfinite(e.normal_force))
    throw Error(what() + "normal_force must be a finite number >= 0");
  Contact c;
  c.body_a = e.object_a;
  c.body_b = e.object_b;
  c.shape_a = e.shape_a;
  c.shape_b = e.shape_b;
  c.feature_a = e.feature_a;
  c.feature_b = e.feature_b;
  c.point = e.point;
  c.normal = e.normal;
  c.phi = e.depth;
  // A's deepest point lies inside B (toward -n), B's inside A (SPEC 1).
  c.witness_a = e.point - 0.5 * e.depth * e.normal;
  c.witness_b = e.point + 0.5 * e.depth * e.normal;
  c.key = e.key;
  c.lambda_n = e.normal_force;  // the models read a force: ContactFriction gives them dt = 1
  return c;
}

void ContactFriction::Impl::assignRankKeys(std::span<const EngineContact> in) {
  // Key-less contacts grouped by pair, in batch order within a pair (no allocation once warm).
  ranks.clear();
  for (size_t i = 0; i < in.size(); ++i)
    if (in[i].key == 0)
      ranks.push_back({{in[i].object_a, in[i].object_b, in[i].shape_a, in[i].shape_b, 0}, i});
  std::sort(ranks.begin(), ranks.end());
  // Each contact's rank within its pair.
  uint64_t rank = 0;
  for (size_t k = 0; k < ranks.size(); ++k) {
    rank = k > 0 && ranks[k].first == ranks[k - 1].first ? rank + 1 : 0;
    contacts[ranks[k].second].key = kRankKey | rank;
  }
}

void ContactFriction::Impl::setFrames() {
  FrameInputs in;
  in.bodies = bodies;
  in.world_axis = settings.frame.world_axis;
  in.fallback_axis = settings.frame.fallback_axis;
  in.sliding_speed = settings.frame.sliding_speed;
  // Frame mode Auto: the engine's own velocities stand for the prediction, gathered only when
  // the mode asks, into buffers kept across calls.
  in.predict_velocities = [this](std::span<const Contact>) {
    linear.resize(bodies.size());
    angular.resize(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i) {
      linear[i] = bodies[i].linear_velocity;
      angular[i] = bodies[i].angular_velocity;
    }
    return PredictedVelocities{linear, angular};
  };
  computeContactFrames(settings.frame.mode, in, contacts, pool.get());
}

void ContactFriction::Impl::fillResults(std::span<const EngineContact> in) {
  next.clear();
  results.resize(contacts.size());
  for (size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    ContactFrictionResult& r = results[i];
    r.t = c.t;
    r.b = c.b;
    r.mu = c.mu;
    r.bounds = BoxLimit::fromDirectional(c.mu);
    r.covered_pixels = c.covered_pixels;
    r.fallback = c.fallback;
    // A's velocity over B's at the point, in the contact plane.
    const Vec3 v =
        bodies[c.body_a].pointVelocity(c.point) - bodies[c.body_b].pointVelocity(c.point);
    r.sliding = v - v.dot(c.normal) * c.normal;
    const SenseKey key{in[i].object_a, in[i].object_b, c.shape_a, c.shape_b, c.key};
    const auto last =
        std::lower_bound(senses.begin(), senses.end(), key,
                         [](const auto& e, const SenseKey& k) { return e.first < k; });
    const Senses before = last != senses.end() && last->first == key ? last->second : Senses{};
    const double vt = r.sliding.dot(c.t), vb = r.sliding.dot(c.b);
    const double speed = settings.frame.sliding_speed;
    r.symmetric_t = symmetricCoefficient(r.bounds.mu_pos_t, r.bounds.mu_neg_t, vt, before.t, speed);
    r.symmetric_b = symmetricCoefficient(r.bounds.mu_pos_b, r.bounds.mu_neg_b, vb, before.b, speed);
    // Remember the senses for the steps this contact rests.
    Senses now = before;
    if (std::abs(vt) > speed) now.t = vt > 0.0 ? 1 : -1;
    if (std::abs(vb) > speed) now.b = vb > 0.0 ? 1 : -1;
    next.push_back({key, now});
  }
  // Sorted for the next compute's lookups.
  std::sort(next.begin(), next.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  senses.swap(next);
}

ContactFriction::ContactFriction(ContactFrictionSettings settings)
    : ContactFriction(std::move(settings), FrictionProviders::builtIn()) {}

ContactFriction::ContactFriction(ContactFrictionSettings settings,
                                 const FrictionProviders& providers)
    : impl_(std::make_unique<Impl>()) {
  checkSettings(settings);
  impl_->provider = providers.make(settings.provider);
  settings.models.dt = 1.0;
  impl_->provider->setFrictionModels(settings.models);
  if (settings.threads != 1) impl_->pool = std::make_unique<ThreadPool>(settings.threads);
  impl_->provider->setThreadPool(impl_->pool.get());
  impl_->settings = std::move(settings);
}

ContactFriction::~ContactFriction() = default;

ObjectId ContactFriction::addObject(const ObjectDesc& desc) {
  const std::string what = "object '" + desc.name + "'";
  if (desc.name.empty()) throw Error("contact friction: an object needs a name");
  if (impl_->names.count(desc.name)) throw Error(what + " is registered already");
  for (size_t i = 0; i < desc.shapes.size(); ++i) {
    const Shape& s = desc.shapes[i];
    if (!finite(s.local.position) || !s.local.rotation.coeffs().allFinite())
      throw Error(what + ": shape " + std::to_string(i) + " has a non-finite transform");
    const std::string unresolved = unresolvedPart(s.surface);
    if (!unresolved.empty())
      throw Error(what + ": shape " + std::to_string(i) + ": " + unresolved +
                  " is not resolved (resolveSurfaces, asperity/geometry/shape.hpp)");
  }
  const auto id = static_cast<ObjectId>(impl_->bodies.size());
  impl_->bodies.push_back(objectBody(desc));
  impl_->names.emplace(desc.name, id);
  return id;
}

ObjectId ContactFriction::findObject(std::string_view name) const {
  const auto it = impl_->names.find(name);
  return it == impl_->names.end() ? kNoObject : it->second;
}

size_t ContactFriction::objectCount() const {
  return impl_->bodies.size();
}

void ContactFriction::setState(ObjectId id, const ObjectState& state) {
  if (id >= impl_->bodies.size())
    throw Error("contact friction: object " + std::to_string(id) + " is not registered");
  Body& body = impl_->bodies[id];
  if (!finite(state.pose.position) || !state.pose.rotation.coeffs().allFinite() ||
      !finite(state.linear_velocity) || !finite(state.angular_velocity))
    throw Error("object '" + body.name + "': pose or velocity is not finite");
  body.pose = {state.pose.position, state.pose.rotation.normalized()};
  body.linear_velocity = state.linear_velocity;
  body.angular_velocity = state.angular_velocity;
}

std::span<const ContactFrictionResult> ContactFriction::compute(
    std::span<const EngineContact> contacts) {
  Impl& m = *impl_;
  Stopwatch clock;
  m.contacts.resize(contacts.size());
  for (size_t i = 0; i < contacts.size(); ++i) m.contacts[i] = m.toContact(contacts[i], i);
  m.assignRankKeys(contacts);
  // Stages 3 and 4 of a World's step (docs/step.md) over the engine's contacts.
  m.setFrames();
  if (!m.contacts.empty()) {
    m.provider->startCoefficients(m.bodies, m.contacts, m.settings.friction);
    m.provider->finishCoefficients();
  }
  m.fillResults(contacts);
  m.last_ms = clock.total();
  return m.results;
}

void ContactFriction::forgetHistory() {
  impl_->provider->forgetHistory();
  impl_->senses.clear();
}

Diagnostics& ContactFriction::diagnostics() {
  return impl_->diagnostics;
}
const ContactFrictionSettings& ContactFriction::settings() const {
  return impl_->settings;
}
std::string ContactFriction::providerName() const {
  return impl_->provider->name();
}
double ContactFriction::lastComputeMs() const {
  return impl_->last_ms;
}

}  // namespace asperity
