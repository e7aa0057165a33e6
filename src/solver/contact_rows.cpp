// The contact rows of the PGS solver: Jacobians and effective masses of each contact, its
// limit surface (SPEC 4), the sweep order, and the warm-start lookup of the last step's impulses.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "parallel/thread_pool.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

namespace {

// body(first, last) over runs of 64 contacts of [0, n), on the pool when there is one and
// enough contacts. A run that walks the warm-start cache keeps its own cursor.
template <class Body>
void forEachRun(const ThreadPool* pool, size_t n, const Body& body) {
  constexpr size_t kRun = 64;
  forEachOn(n >= ContactSolver::kParallelRows ? pool : nullptr, (n + kRun - 1) / kRun, 1,
            [&](size_t k) { body(k * kRun, std::min(n, (k + 1) * kRun)); });
}

}  // namespace

void ContactSolver::prepareContact(const Contact& c, ContactRow& row) const {
  row.a = static_cast<int>(c.body_a);
  row.b = static_cast<int>(c.body_b);
  const size_t a = c.body_a, b = c.body_b;
  const Vec3 ra = c.point - position_[a];
  const Vec3 rb = c.point - position_[b];
  row.n = c.normal;
  row.t = c.t;
  // b = n x t (SPEC 1: right-handed (t, b, n), as the frame stage sets it); rows do not
  // store it: the sweep recomputes it, which costs less than streaming it from memory.
  const Vec3 bt = c.normal.cross(c.t);
  // Angular Jacobians r x d and their images I^-1 (r x d).
  row.ra = ra;
  row.rb = rb;
  const Vec3 ra_n = ra.cross(row.n), rb_n = rb.cross(row.n);
  const Vec3 ra_t = ra.cross(row.t), rb_t = rb.cross(row.t);
  const Vec3 ra_b = ra.cross(bt), rb_b = rb.cross(bt);
  row.ia_n = inv_inertia_[a] * ra_n;
  row.ib_n = inv_inertia_[b] * rb_n;
  row.ia_t = inv_inertia_[a] * ra_t;
  row.ib_t = inv_inertia_[b] * rb_t;
  row.ia_b = inv_inertia_[a] * ra_b;
  row.ib_b = inv_inertia_[b] * rb_b;
  // Effective masses: K = J M^-1 J^T for the normal row and the tangential 2x2 block.
  const double im = inv_mass_[a] + inv_mass_[b];
  const double k_nn = im + ra_n.dot(row.ia_n) + rb_n.dot(row.ib_n);
  row.mass_n = k_nn > 0.0 ? 1.0 / k_nn : 0.0;
  Eigen::Matrix2d k;
  k(0, 0) = im + ra_t.dot(row.ia_t) + rb_t.dot(row.ib_t);
  k(1, 1) = im + ra_b.dot(row.ia_b) + rb_b.dot(row.ib_b);
  k(0, 1) = k(1, 0) = ra_t.dot(row.ia_b) + rb_t.dot(row.ib_b);
  const double det = k.determinant();
  // How a normal impulse changes the tangential velocities (K_tn, K_bn), so the friction row
  // sees the normal row's update without recomputing the relative velocity.
  const Vec3 coupling = im * row.n + row.ia_n.cross(ra) + row.ib_n.cross(rb);
  row.k_tn = row.t.dot(coupling);
  row.k_bn = bt.dot(coupling);
  // K^-1 = [k11 -k01; -k01 k00] / det, kept as its three distinct entries.
  if (det > 1e-300) {
    row.inv_k = Vec3(k(1, 1) / det, -k(0, 1) / det, k(0, 0) / det);
  } else {
    row.inv_k.setZero();
  }
  // Largest eigenvalue of K: the step 1 / k_max never overshoots along any direction.
  const double mean = 0.5 * (k(0, 0) + k(1, 1));
  const double half_gap = 0.5 * (k(0, 0) - k(1, 1));
  const double k_max = mean + std::sqrt(half_gap * half_gap + k(0, 1) * k(0, 1));
  row.inv_k_slide = k_max > 0.0 ? 1.0 / k_max : 0.0;
  // Separated (speculative) contacts may close their gap within the step; restitution 0.
  row.target_n = c.phi < 0.0 ? c.phi / settings_.dt : 0.0;
  // Split impulse: push the penetration beyond the slop out at a bounded pseudo-velocity.
  const double excess = c.phi - settings_.slop;
  row.target_p = excess > 0.0 ? std::min(settings_.baumgarte * excess / settings_.dt,
                                         settings_.max_correction_speed)
                              : 0.0;
  row.lambda_n = row.lambda_t = row.lambda_b = row.lambda_p = 0.0;
}

void ContactSolver::makeLimit(const Contact& contact, size_t row) {
  // The limit surface the settings choose (SPEC 4), from the contact's coefficients.
  std::visit(
      [&](auto& limits) {
        using Limit = typename std::decay_t<decltype(limits)>::value_type;
        limits[row] = Limit::fromContact(contact.mu, settings_.coulomb_mu);
      },
      limits_);
}

void ContactSolver::placeRows(std::span<const Contact> contacts, bool friction) {
  friction_ = friction;
  islands_ready_ = false;
  const size_t n = contacts.size();
  scheduleRows(contacts);
  // Rows and limit surfaces are stored in sweep order: each sweep streams through memory front
  // to back, so the prefetcher hides the misses once the rows outgrow the cache. slot_ maps a
  // contact to its row.
  slot_.resize(n);
  for (size_t k = 0; k < n; ++k) slot_[static_cast<size_t>(order_[k])] = static_cast<int>(k);
  rows_.resize(n);
  std::visit(
      [&](auto& surfaces) {
        surfaces.clear();
        if (friction) surfaces.resize(n);
      },
      limits_);
}

void ContactSolver::fillRows(std::span<const Contact> contacts, bool rows, bool limits, bool warm) {
  // One pass over the contacts, in runs on the pool, each contact written into its own slot.
  // Each run has its own walking cursor for the warm start: findCached's matches do not
  // depend on where the cursor was.
  const bool warm_start = warm && settings_.warm_starting;
  const auto run = [&](size_t first, size_t last) {
    size_t cursor = 0;
    for (size_t i = first; i < last; ++i) {
      const auto row = static_cast<size_t>(slot_[i]);
      if (rows) prepareContact(contacts[i], rows_[row]);
      if (limits) makeLimit(contacts[i], row);
      if (!warm_start) continue;
      if (const Cached* cached = findCached(contacts[i], cursor))
        warmStartRow(*cached, rows_[row], row);
    }
  };
  forEachRun(pool_, contacts.size(), run);
}

void ContactSolver::scheduleRows(std::span<const Contact> contacts) {
  // The sweep order: input order, except that a row sharing a moving body with the row just
  // before it waits in a FIFO until a row without that dependency has gone first. Consecutive
  // rows then rarely touch the same velocities, so the processor overlaps them (the four
  // contacts of a manifold would otherwise form one long dependency chain). Deterministic.
  order_.clear();
  pending_.clear();
  size_t head = 0;
  BodyId last_a = kNoBody, last_b = kNoBody;
  auto conflicts = [&](int i) {
    const Contact& c = contacts[static_cast<size_t>(i)];
    auto moving = [&](BodyId body) { return inv_mass_[body] > 0.0; };
    return (moving(c.body_a) && (c.body_a == last_a || c.body_a == last_b)) ||
           (moving(c.body_b) && (c.body_b == last_a || c.body_b == last_b));
  };
  auto emit = [&](int i) {
    order_.push_back(i);
    last_a = contacts[static_cast<size_t>(i)].body_a;
    last_b = contacts[static_cast<size_t>(i)].body_b;
  };
  for (int i = 0; i < static_cast<int>(contacts.size()); ++i) {
    if (head < pending_.size() && !conflicts(pending_[head])) emit(pending_[head++]);
    if (conflicts(i)) {
      pending_.push_back(i);
    } else {
      emit(i);
    }
  }
  while (head < pending_.size()) emit(pending_[head++]);
}

bool ContactSolver::Cached::operator<(const Cached& o) const {
  return std::tie(a, b, key) < std::tie(o.a, o.b, o.key);
}

const ContactSolver::Cached* ContactSolver::findCached(const Contact& c, size_t& cursor) const {
  // Contacts and cache share the order (body_a, body_b, key): a walking cursor finds most
  // entries in O(1); anything else falls back to a binary search. Only a key the cache holds
  // once counts, whatever the cursor was, so any split of the contacts finds the same entries.
  const Cached probe{c.body_a, c.body_b, c.key, 0.0, Vec3::Zero()};
  auto same = [&](size_t i) {
    return i < cache_.size() && !(cache_[i] < probe) && !(probe < cache_[i]);
  };
  if (!same(cursor)) {
    cursor =
        static_cast<size_t>(std::lower_bound(cache_.begin(), cache_.end(), probe) - cache_.begin());
    if (!same(cursor)) return nullptr;
  }
  const size_t hit = cursor++;
  if (same(cursor) || (hit > 0 && same(hit - 1))) return nullptr;  // the key is not unique
  return &cache_[hit];
}

void ContactSolver::previousNormalImpulses(std::span<Contact> contacts) const {
  // In runs, each with its own cursor: findCached's answer does not depend on where it starts.
  forEachRun(pool_, contacts.size(), [&](size_t first, size_t last) {
    size_t cursor = 0;
    for (size_t i = first; i < last; ++i) {
      const Cached* hit = findCached(contacts[i], cursor);
      contacts[i].lambda_n = hit != nullptr ? hit->lambda_n : 0.0;
    }
  });
}

void ContactSolver::warmStartRow(const Cached& cached, ContactRow& row, size_t slot) const {
  // Same contact last step: reuse its impulses, the tangential one re-expressed in this
  // step's frame and projected on this step's limit surface.
  const auto range = std::make_pair(&cached, &cached + 1);
  row.lambda_n = range.first->lambda_n;
  if (!friction_) return;
  const Vec2 tb(range.first->tangential.dot(row.t),
                range.first->tangential.dot(row.n.cross(row.t)));
  const Vec2 projected = std::visit(
      [&](const auto& limits) { return limits[slot].project(tb, row.lambda_n); }, limits_);
  row.lambda_t = projected.x();
  row.lambda_b = projected.y();
}

}  // namespace asperity
