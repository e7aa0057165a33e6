// The PGS sweeps over the contact rows (SPEC 4): each row's normal update and its tangential
// block projected on the limit surface, two rows of different islands side by side in the two
// lanes of a register, and the split-impulse position rows.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "math/lanes.hpp"
#include "parallel/thread_pool.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

namespace {

// Tag for the frictionless pass (frame mode Auto): normal rows only.
struct NoFriction {};

}  // namespace

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
  const size_t a[2] = {ax, ay}, b[2] = {bx, by};
  storePair(a, b, ima, imb, va + ima * p, wa + ia, vb - imb * p, wb - ib);
  if (rx.target_p > 0.0) solvePositionRow(rx, ax, bx);
  if (ry.target_p > 0.0) solvePositionRow(ry, ay, by);
}

void ContactSolver::storePair(const size_t a[2], const size_t b[2], Lanes ima, Lanes imb,
                              const Lanes3& va, const Lanes3& wa, const Lanes3& vb,
                              const Lanes3& wb) {
  // Static and kinematic bodies keep their velocity: no store, no false dependency.
  for (int k = 0; k < 2; ++k) {
    if (ima[k] > 0.0) {
      v_[a[k]] = lanes::lane(va, k);
      w_[a[k]] = lanes::lane(wa, k);
    }
    if (imb[k] > 0.0) {
      v_[b[k]] = lanes::lane(vb, k);
      w_[b[k]] = lanes::lane(wb, k);
    }
  }
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
  if (!islands_ready_) buildIslands();
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

}  // namespace asperity
