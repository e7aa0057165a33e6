// The PGS solver's life cycle over one solve: begin, the contact rows in their parts, the warm
// start, finish (solver/contact_solver.hpp). Rows are made in contact_rows.cpp, swept in
// contact_sweep.cpp over the islands of solver_islands.cpp; joint rows live in joint_rows.cpp.
#include "solver/contact_solver.hpp"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

#include "asperity/error.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

// body(i) for i in [0, n), on the pool when there is one and enough items.
template <class Body>
void forEachItem(const ThreadPool* pool, size_t n, size_t grain, const Body& body) {
  forEachOn(n >= ContactSolver::kParallelRows ? pool : nullptr, n, grain, body);
}

template <size_t... I>
ContactSolver::LimitVectors emptyLimits(LimitSurfaceKind kind, std::index_sequence<I...>) {
  ContactSolver::LimitVectors out;
  ((static_cast<size_t>(kind) == I ? static_cast<void>(out.emplace<I>()) : void()), ...);
  return out;
}

}  // namespace

void ContactSolver::begin(std::span<const Body> bodies, const SolverSettings& settings) {
  settings_ = settings;
  const size_t n = bodies.size();
  v_.resize(n);
  w_.resize(n);
  vp_.assign(n, Vec3::Zero());
  wp_.assign(n, Vec3::Zero());
  inv_mass_.resize(n);
  inv_inertia_.resize(n);
  position_.resize(n);
  com_offset_.resize(n);
  rotation_.resize(n);
  // Static and kinematic bodies keep their velocity and never take an impulse.
  forEachItem(pool_, n, 64, [&](size_t i) {
    const Body& body = bodies[i];
    v_[i] = body.linear_velocity;
    w_[i] = body.angular_velocity;
    const bool dynamic = body.isDynamic();
    inv_mass_[i] = dynamic ? body.inverse_mass : 0.0;
    inv_inertia_[i] = dynamic ? body.inverseInertiaWorld() : Mat3::Zero();
    position_[i] = body.pose.position;
    com_offset_[i] = body.com_offset;
    rotation_[i] = body.pose.rotation;
  });
  rows_.clear();
  order_.clear();
  // A new vector only when the kind changed: the old one keeps its room for this step's rows.
  if (limits_.index() != static_cast<size_t>(settings.limit_surface)) {
    limits_ = emptyLimits(settings.limit_surface,
                          std::make_index_sequence<std::tuple_size_v<LimitSurfaceTypes>>());
  }
  balls_.clear();
  axes_.clear();
  islands_ready_ = false;
  last_delta_ = 0.0;
}

void ContactSolver::setContacts(std::span<const Contact> contacts, bool friction) {
  setContactRows(contacts, friction);
  setContactLimits(contacts);
  warmStart(contacts);
}

void ContactSolver::setContactRows(std::span<const Contact> contacts, bool friction) {
  placeRows(contacts, friction);
  fillRows(contacts, true, false, false);
}

void ContactSolver::setContactLimits(std::span<const Contact> contacts) {
  if (contacts.size() != rows_.size()) {
    throw Error("solver: setContactLimits got " + std::to_string(contacts.size()) +
                " contacts, setContactRows had " + std::to_string(rows_.size()));
  }
  if (friction_) fillRows(contacts, false, true, false);
}

void ContactSolver::warmStart(std::span<const Contact> contacts) {
  // Islands first: the impulses of the last step are applied island by island.
  buildIslands();
  if (!settings_.warm_starting) return;
  fillRows(contacts, false, false, true);
  warmStartJoints();
  // Contact order (not sweep order): the same sums as before the rows were reordered. Island
  // by island, which share no moving body: each body still takes its impulses in contact
  // order, so the islands may run on the pool.
  for (size_t k = 0; k < island_count_; ++k) islands_[k].warm.clear();
  for (const int row : slot_)
    islands_[static_cast<size_t>(row_island_[static_cast<size_t>(row)])].warm.push_back(row);
  forEachIsland([&](size_t k) {
    for (const int row : islands_[k].warm) {
      const ContactRow& r = rows_[static_cast<size_t>(row)];
      const Vec3 p = r.lambda_n * r.n + r.lambda_t * r.t + r.lambda_b * r.n.cross(r.t);
      const Vec3 ia = r.lambda_n * r.ia_n + r.lambda_t * r.ia_t + r.lambda_b * r.ia_b;
      const Vec3 ib = r.lambda_n * r.ib_n + r.lambda_t * r.ib_t + r.lambda_b * r.ib_b;
      applyImpulse(r.a, r.b, p, ia, ib);
    }
  });
}

void ContactSolver::finish(std::span<Body> bodies, std::span<Contact> contacts) {
  // Velocities of dynamic bodies; the impulses on each contact.
  forEachItem(pool_, bodies.size(), 64, [&](size_t i) {
    if (!bodies[i].isDynamic()) return;
    bodies[i].linear_velocity = v_[i];
    bodies[i].angular_velocity = w_[i];
  });
  cache_.resize(std::min(rows_.size(), contacts.size()));
  forEachItem(pool_, cache_.size(), 256, [&](size_t i) {
    const ContactRow& r = rows_[static_cast<size_t>(slot_[i])];
    contacts[i].lambda_n = r.lambda_n;
    contacts[i].lambda_t = r.lambda_t;
    contacts[i].lambda_b = r.lambda_b;
    cache_[i] = {contacts[i].body_a, contacts[i].body_b, contacts[i].key, r.lambda_n,
                 r.lambda_t * r.t + r.lambda_b * r.n.cross(r.t)};
  });
  // Sorted by (body_a, body_b, key) for the next step's lookups; contacts usually arrive in
  // that order already (stable: ties keep contact order).
  if (!std::is_sorted(cache_.begin(), cache_.end())) std::stable_sort(cache_.begin(), cache_.end());
  storeJointImpulses();
}

void ContactSolver::saveWarmStart(StateWriter& out) const {
  out.put<uint64_t>(cache_.size());
  for (const Cached& c : cache_) {
    out.put(c.a);
    out.put(c.b);
    out.put(c.key);
    out.put(c.lambda_n);
    for (int k = 0; k < 3; ++k) out.put(c.tangential[k]);
  }
  out.putVector(joint_lambda_);
}

void ContactSolver::loadWarmStart(StateReader& in) {
  cache_.resize(in.count(sizeof(Cached::a) + sizeof(Cached::b) + 5 * sizeof(double)));
  for (Cached& c : cache_) {
    c.a = in.get<BodyId>();
    c.b = in.get<BodyId>();
    c.key = in.get<uint64_t>();
    c.lambda_n = in.get<double>();
    for (int k = 0; k < 3; ++k) c.tangential[k] = in.get<double>();
  }
  in.getVector(joint_lambda_);
}

void ContactSolver::forgetWarmStart() {
  cache_.clear();
  std::fill(joint_lambda_.begin(), joint_lambda_.end(), 0.0);
}

}  // namespace asperity
