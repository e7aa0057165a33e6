// Projected Gauss-Seidel on body velocities: contact rows (SPEC 4) and the sweep machinery.
// Joint rows live in joint_rows.cpp.
#include "solver/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "asperity/error.hpp"
#include "math/lanes.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

// Fewest rows (contacts and joint rows) that the islands are swept in parallel for, and fewest
// items (bodies, contacts) that per-item work goes to the threads for: below that, waking them
// costs more than the work.
constexpr size_t kParallelRows = 256;

// body(i) for i in [0, n), on the pool when there is one and enough items.
template <class Body>
void forEachItem(const ThreadPool* pool, size_t n, size_t grain, const Body& body) {
  forEachOn(n >= kParallelRows ? pool : nullptr, n, grain, body);
}

// Tag for the frictionless pass (frame mode Auto): normal rows only.
struct NoFriction {};

// An empty vector of the limit surface `kind` (LimitSurfaceTypes in enum order).
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
  warm_started_ = false;
  last_delta_ = 0.0;
}

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

void ContactSolver::setContacts(std::span<const Contact> contacts, bool friction) {
  placeRows(contacts, friction);
  fillRows(contacts, true, friction, true);
}

void ContactSolver::setContactRows(std::span<const Contact> contacts) {
  placeRows(contacts, true);
  fillRows(contacts, true, false, false);
}

void ContactSolver::setContactLimits(std::span<const Contact> contacts) {
  if (contacts.size() != rows_.size()) {
    throw Error("solver: setContactLimits got " + std::to_string(contacts.size()) +
                " contacts, setContactRows had " + std::to_string(rows_.size()));
  }
  fillRows(contacts, false, true, true);
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
  constexpr size_t kRun = 64;
  const size_t n = contacts.size();
  forEachOn(n >= kParallelRows ? pool_ : nullptr, (n + kRun - 1) / kRun, 1,
            [&](size_t k) { run(k * kRun, std::min(n, (k + 1) * kRun)); });
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

void ContactSolver::applyImpulse(int a, int b, const Vec3& p, const Vec3& ia, const Vec3& ib) {
  // Impulse p on A at its contact (I^-1 (r x p) given as ia), the opposite on B. Bodies that
  // do not move take nothing (and are not written: islands share them across threads).
  const size_t ua = static_cast<size_t>(a), ub = static_cast<size_t>(b);
  if (inv_mass_[ua] > 0.0) {
    v_[ua] += inv_mass_[ua] * p;
    w_[ua] += ia;
  }
  if (inv_mass_[ub] > 0.0) {
    v_[ub] -= inv_mass_[ub] * p;
    w_[ub] -= ib;
  }
}

void ContactSolver::warmStart() {
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

template <class Limit>
inline void ContactSolver::sweepRow(std::span<const Limit> limits, size_t i, double& delta2) {
  ContactRow& r = rows_[i];
  const size_t a = static_cast<size_t>(r.a), b = static_cast<size_t>(r.b);
  // Local copies: the compiler need not reload the row after each velocity write.
  Vec3 va = v_[a], wa = w_[a], vb = v_[b], wb = w_[b];
  const double ima = inv_mass_[a], imb = inv_mass_[b];
  // Relative velocity of A's contact point over B's, once per row.
  const Vec3 dv = (va + wa.cross(r.ra)) - (vb + wb.cross(r.rb));
  // Normal row: lambda_n >= 0 (SPEC 1: impulse lambda_n n on A).
  const double ln = std::max(0.0, r.lambda_n + (r.target_n - r.n.dot(dv)) * r.mass_n);
  const double dn = ln - r.lambda_n;
  r.lambda_n = ln;
  delta2 += dn * dn;
  Vec3 p = dn * r.n;
  Vec3 ia = dn * r.ia_n, ib = dn * r.ib_n;
  if constexpr (!std::is_same_v<Limit, NoFriction>) {
    // Tangential block: the tangential velocity after the normal update (through the
    // coupling K_tn, K_bn), the unconstrained 2x2 update, then the accumulated impulse
    // projected on the limit surface for the current lambda_n (SPEC 4).
    const Vec3 bt = r.n.cross(r.t);
    const Vec2 vel(r.t.dot(dv) + dn * r.k_tn, bt.dot(dv) + dn * r.k_bn);
    const Vec2 old(r.lambda_t, r.lambda_b);
    bool outside = false;
    const Vec2 step(r.inv_k.x() * vel.x() + r.inv_k.y() * vel.y(),
                    r.inv_k.y() * vel.x() + r.inv_k.z() * vel.y());
    Vec2 next = limits[i].project(old - step, ln, outside);
    // Sliding (the block update left the limit set): redo the update in the isotropic
    // metric 1 / k_max so that the projected friction opposes the slip velocity (maximal
    // dissipation). Projecting the K^-1-metric update instead turns the friction off the
    // slip direction wherever K couples t and b, which spins a sliding box about n.
    if (outside) {
      next = limits[i].project(old - r.inv_k_slide * vel, ln, outside);
    }
    const Vec2 d = next - old;
    r.lambda_t = next.x();
    r.lambda_b = next.y();
    p += d.x() * r.t + d.y() * bt;
    ia += d.x() * r.ia_t + d.y() * r.ia_b;
    ib += d.x() * r.ib_t + d.y() * r.ib_b;
    delta2 += d.squaredNorm();
  }
  // Both rows' impulses applied at once: p on A at r_A, -p on B at r_B.
  va += ima * p;
  wa += ia;
  vb -= imb * p;
  wb -= ib;
  // Static and kinematic bodies keep their velocity: no store, no false dependency.
  if (ima > 0.0) {
    v_[a] = va;
    w_[a] = wa;
  }
  if (imb > 0.0) {
    v_[b] = vb;
    w_[b] = wb;
  }
  // Split impulse: the same normal row on the pseudo-velocities toward target_p, while the
  // row is in cache.
  if (r.target_p > 0.0) solvePositionRow(r, a, b);
}

namespace {

using lanes::Lanes;
using lanes::Lanes3;
using lanes::Mask;

// Projection of two rows' tangential updates (lanes: the rows), as sweepRow projects one:
// `first` = old - K^-1 vel, and where that leaves the limit set, old - vel / k_max instead.
template <class Limit>
void projectPair(const Limit& lx, const Limit& ly, Lanes ln, Lanes first_t, Lanes first_b,
                 Lanes slide_t, Lanes slide_b, Lanes& next_t, Lanes& next_b) {
  const Limit* limit[2] = {&lx, &ly};
  for (int k = 0; k < 2; ++k) {
    bool outside = false;
    Vec2 next = limit[k]->project(Vec2(first_t[k], first_b[k]), ln[k], outside);
    if (outside) next = limit[k]->project(Vec2(slide_t[k], slide_b[k]), ln[k], outside);
    next_t[k] = next.x();
    next_b[k] = next.y();
  }
}

// The Coulomb disc on both lanes at once (CoulombLimit::project, operation for operation).
template <>
void projectPair(const CoulombLimit& lx, const CoulombLimit& ly, Lanes ln, Lanes first_t,
                 Lanes first_b, Lanes slide_t, Lanes slide_b, Lanes& next_t, Lanes& next_b) {
  const Lanes zero{0.0, 0.0};
  const Mask loaded = zero < ln;  // !(ln > 0): the impulse is zero, whichever update
  const Lanes radius = lanes::max0(lanes::of(lx.mu, ly.mu)) * ln;
  const Lanes limit2 = radius * radius;
  const Mask outside = (first_t * first_t + first_b * first_b) > limit2;
  next_t = lanes::select(loaded, first_t, zero);
  next_b = lanes::select(loaded, first_b, zero);
  const Mask sliding = outside & loaded;
  if (!lanes::any(sliding)) return;
  const Lanes norm2 = slide_t * slide_t + slide_b * slide_b;
  const Mask shrink = sliding & (norm2 > limit2);
  // The square root per lane (what std::sqrt gives); only lanes that shrink read it.
  const Lanes root{std::sqrt(norm2[0]), std::sqrt(norm2[1])};
  const Lanes scale = radius / root;
  next_t = lanes::select(sliding, lanes::select(shrink, slide_t * scale, slide_t), next_t);
  next_b = lanes::select(sliding, lanes::select(shrink, slide_b * scale, slide_b), next_b);
}

}  // namespace

template <class Limit>
inline void ContactSolver::sweepRowPair(std::span<const Limit> limits, size_t ix, size_t iy,
                                        Lanes& delta2) {
  // sweepRow for row ix in lane 0 and row iy in lane 1 (rows of two islands: no body that
  // one writes is read by the other).
  ContactRow& rx = rows_[ix];
  ContactRow& ry = rows_[iy];
  const size_t ax = static_cast<size_t>(rx.a), bx = static_cast<size_t>(rx.b);
  const size_t ay = static_cast<size_t>(ry.a), by = static_cast<size_t>(ry.b);
  const Lanes3 va = lanes::of(v_[ax], v_[ay]), wa = lanes::of(w_[ax], w_[ay]);
  const Lanes3 vb = lanes::of(v_[bx], v_[by]), wb = lanes::of(w_[bx], w_[by]);
  const Lanes ima = lanes::of(inv_mass_[ax], inv_mass_[ay]);
  const Lanes imb = lanes::of(inv_mass_[bx], inv_mass_[by]);
  const Lanes3 n = lanes::of(rx.n, ry.n);
  const Lanes3 dv = (va + lanes::cross(wa, lanes::of(rx.ra, ry.ra))) -
                    (vb + lanes::cross(wb, lanes::of(rx.rb, ry.rb)));
  const Lanes lambda_n = lanes::of(rx.lambda_n, ry.lambda_n);
  const Lanes ln =
      lanes::max0(lambda_n + (lanes::of(rx.target_n, ry.target_n) - lanes::dot(n, dv)) *
                                 lanes::of(rx.mass_n, ry.mass_n));
  const Lanes dn = ln - lambda_n;
  rx.lambda_n = ln[0];
  ry.lambda_n = ln[1];
  delta2 += dn * dn;
  Lanes3 p = dn * n;
  Lanes3 ia = dn * lanes::of(rx.ia_n, ry.ia_n), ib = dn * lanes::of(rx.ib_n, ry.ib_n);
  if constexpr (!std::is_same_v<Limit, NoFriction>) {
    const Lanes3 t = lanes::of(rx.t, ry.t);
    const Lanes3 bt = lanes::cross(n, t);
    const Lanes vel_t = lanes::dot(t, dv) + dn * lanes::of(rx.k_tn, ry.k_tn);
    const Lanes vel_b = lanes::dot(bt, dv) + dn * lanes::of(rx.k_bn, ry.k_bn);
    const Lanes old_t = lanes::of(rx.lambda_t, ry.lambda_t);
    const Lanes old_b = lanes::of(rx.lambda_b, ry.lambda_b);
    const Lanes k_tt = lanes::of(rx.inv_k.x(), ry.inv_k.x());
    const Lanes k_tb = lanes::of(rx.inv_k.y(), ry.inv_k.y());
    const Lanes k_bb = lanes::of(rx.inv_k.z(), ry.inv_k.z());
    const Lanes slide = lanes::of(rx.inv_k_slide, ry.inv_k_slide);
    Lanes next_t, next_b;
    projectPair(limits[ix], limits[iy], ln, old_t - (k_tt * vel_t + k_tb * vel_b),
                old_b - (k_tb * vel_t + k_bb * vel_b), old_t - slide * vel_t, old_b - slide * vel_b,
                next_t, next_b);
    const Lanes d_t = next_t - old_t, d_b = next_b - old_b;
    rx.lambda_t = next_t[0];
    ry.lambda_t = next_t[1];
    rx.lambda_b = next_b[0];
    ry.lambda_b = next_b[1];
    p = p + (d_t * t + d_b * bt);
    ia = ia + (d_t * lanes::of(rx.ia_t, ry.ia_t) + d_b * lanes::of(rx.ia_b, ry.ia_b));
    ib = ib + (d_t * lanes::of(rx.ib_t, ry.ib_t) + d_b * lanes::of(rx.ib_b, ry.ib_b));
    delta2 += d_t * d_t + d_b * d_b;
  }
  const Lanes3 va_next = va + ima * p, wa_next = wa + ia;
  const Lanes3 vb_next = vb - imb * p, wb_next = wb - ib;
  const size_t a[2] = {ax, ay}, b[2] = {bx, by};
  for (int k = 0; k < 2; ++k) {
    if (ima[k] > 0.0) {
      v_[a[k]] = lanes::lane(va_next, k);
      w_[a[k]] = lanes::lane(wa_next, k);
    }
    if (imb[k] > 0.0) {
      v_[b[k]] = lanes::lane(vb_next, k);
      w_[b[k]] = lanes::lane(wb_next, k);
    }
  }
  if (rx.target_p > 0.0) solvePositionRow(rx, ax, bx);
  if (ry.target_p > 0.0) solvePositionRow(ry, ay, by);
}

template <class Limit>
void ContactSolver::sweepContacts(std::span<const Limit> limits, std::span<const int> x,
                                  std::span<const int> y, double& delta_x, double& delta_y) {
  // Row k of x beside row k of y, in the two lanes of one register, while both islands have
  // rows; then the rest of the longer one alone. Each island sees its own rows in its own
  // order, with the operations of sweepRow: the same bits as sweeping them one by one.
  const size_t both = std::min(x.size(), y.size());
  Lanes delta = lanes::of(delta_x, delta_y);
  for (size_t k = 0; k < both; ++k)
    sweepRowPair(limits, static_cast<size_t>(x[k]), static_cast<size_t>(y[k]), delta);
  delta_x = delta[0];
  delta_y = delta[1];
  for (size_t k = both; k < x.size(); ++k) sweepRow(limits, static_cast<size_t>(x[k]), delta_x);
  for (size_t k = both; k < y.size(); ++k) sweepRow(limits, static_cast<size_t>(y[k]), delta_y);
}

void ContactSolver::solvePositionRow(ContactRow& r, size_t a, size_t b) {
  const double vn = r.n.dot((vp_[a] + wp_[a].cross(r.ra)) - (vp_[b] + wp_[b].cross(r.rb)));
  const double lp = std::max(0.0, r.lambda_p + (r.target_p - vn) * r.mass_n);
  const double dp = lp - r.lambda_p;
  r.lambda_p = lp;
  if (inv_mass_[a] > 0.0) {
    vp_[a] += (inv_mass_[a] * dp) * r.n;
    wp_[a] += dp * r.ia_n;
  }
  if (inv_mass_[b] > 0.0) {
    vp_[b] -= (inv_mass_[b] * dp) * r.n;
    wp_[b] -= dp * r.ib_n;
  }
}

int ContactSolver::findRoot(int body) {
  // Path halving: every other node on the way points to its grandparent.
  size_t x = static_cast<size_t>(body);
  while (root_[x] != static_cast<int>(x)) {
    root_[x] = root_[static_cast<size_t>(root_[x])];
    x = static_cast<size_t>(root_[x]);
  }
  return static_cast<int>(x);
}

void ContactSolver::buildIslands() {
  // Moving bodies joined by a joint or contact row share an island; static and kinematic
  // bodies join nothing (their velocities are read, never written).
  const size_t n = v_.size();
  root_.resize(n);
  for (size_t i = 0; i < n; ++i) root_[i] = static_cast<int>(i);
  auto moving = [&](int body) { return inv_mass_[static_cast<size_t>(body)] > 0.0; };
  auto unite = [&](int a, int b) {
    if (moving(a) && moving(b)) root_[static_cast<size_t>(findRoot(a))] = findRoot(b);
  };
  for (const BallRow& r : balls_) unite(r.a, r.b);
  for (const AxisRow& r : axes_) unite(r.a, r.b);
  for (const ContactRow& r : rows_) unite(r.a, r.b);
  // Islands numbered in order of first appearance: the same numbering on every thread count.
  island_of_.assign(n, -1);
  for (size_t k = 0; k < island_count_; ++k) {
    islands_[k].balls.clear();
    islands_[k].axes.clear();
    islands_[k].contacts.clear();
  }
  island_count_ = 0;
  auto islandOf = [&](int a, int b) -> Island& {
    int& id = island_of_[static_cast<size_t>(findRoot(moving(a) ? a : b))];
    if (id < 0) {
      id = static_cast<int>(island_count_++);
      if (islands_.size() < island_count_) islands_.emplace_back();
    }
    return islands_[static_cast<size_t>(id)];
  };
  for (size_t i = 0; i < balls_.size(); ++i)
    islandOf(balls_[i].a, balls_[i].b).balls.push_back(static_cast<int>(i));
  for (size_t i = 0; i < axes_.size(); ++i)
    islandOf(axes_[i].a, axes_[i].b).axes.push_back(static_cast<int>(i));
  row_island_.resize(rows_.size());
  for (size_t i = 0; i < rows_.size(); ++i) {
    Island& island = islandOf(rows_[i].a, rows_[i].b);
    island.contacts.push_back(static_cast<int>(i));
    row_island_[i] = static_cast<int>(&island - islands_.data());
  }
}

const ThreadPool* ContactSolver::islandPool(size_t tasks) const {
  // Threads pay off only when there is enough to sweep: waking them costs tens of us.
  const size_t rows = rows_.size() + balls_.size() + axes_.size();
  return tasks > 1 && rows >= kParallelRows ? pool_ : nullptr;
}

void ContactSolver::forEachIsland(const std::function<void(size_t)>& body) const {
  forEachOn(islandPool(island_count_), island_count_, 1, body);
}

void ContactSolver::sweepIslands(const Island& x, const Island& y, int iterations, double& delta_x,
                                 double& delta_y) {
  // Fixed order per island: joints, contacts (with the projection chosen once), position
  // rows. delta_* end as the last sweep's squared impulse changes.
  for (int it = 0; it < iterations; ++it) {
    const double joints_x = sweepJoints(x), joints_y = sweepJoints(y);
    double contacts_x = 0.0, contacts_y = 0.0;
    if (!friction_) {
      sweepContacts(std::span<const NoFriction>(), x.contacts, y.contacts, contacts_x, contacts_y);
    } else {
      std::visit(
          [&](const auto& limits) {
            sweepContacts(std::span(limits), x.contacts, y.contacts, contacts_x, contacts_y);
          },
          limits_);
    }
    delta_x = joints_x + contacts_x;
    delta_y = joints_y + contacts_y;
  }
}

void ContactSolver::iterate(int iterations) {
  buildIslands();
  if (!warm_started_) {
    if (settings_.warm_starting) warmStart();
    warm_started_ = true;
  }
  // Islands two at a time, side by side (sweepContacts); an odd last one beside an empty one.
  island_delta_.assign(island_count_ + 1, 0.0);
  if (islands_.size() == island_count_) islands_.emplace_back();
  Island& empty = islands_[island_count_];
  empty.balls.clear();
  empty.axes.clear();
  empty.contacts.clear();
  const size_t pairs = (island_count_ + 1) / 2;
  forEachOn(islandPool(pairs), pairs, 1, [&](size_t pair) {
    const size_t k = 2 * pair;
    sweepIslands(islands_[k], islands_[k + 1], iterations, island_delta_[k], island_delta_[k + 1]);
  });
  // The last sweep's impulse changes, summed in island order.
  double delta2 = 0.0;
  for (size_t k = 0; k < island_count_; ++k) delta2 += island_delta_[k];
  last_delta_ = std::sqrt(delta2);
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

void ContactSolver::forgetWarmStart() {
  cache_.clear();
  std::fill(joint_lambda_.begin(), joint_lambda_.end(), 0.0);
}

}  // namespace asperity
