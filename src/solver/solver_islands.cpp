// Islands of the PGS solver: rows that touch one group of moving bodies, swept on their own
// (on the pool's threads) with the bits of one sweep over all rows.
#include <functional>

#include "parallel/thread_pool.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {

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
  islands_ready_ = true;
}

const ThreadPool* ContactSolver::islandPool(size_t tasks) const {
  // Threads pay off only when there is enough to sweep: waking them costs tens of us.
  const size_t rows = rows_.size() + balls_.size() + axes_.size();
  return tasks > 1 && rows >= kParallelRows ? pool_ : nullptr;
}

void ContactSolver::forEachIsland(const std::function<void(size_t)>& body) const {
  forEachOn(islandPool(island_count_), island_count_, 1, body);
}

}  // namespace asperity
