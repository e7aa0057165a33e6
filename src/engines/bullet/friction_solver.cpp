// The box limit surface in Bullet's solver. solveSingleIteration follows Bullet 3.24's own
// (btSequentialImpulseConstraintSolver.cpp) statement for statement, so that a contact whose
// four bounds are equal is solved to the same bits as by Bullet; the one change is that a
// friction row's limits come from its sense's coefficients instead of +-m_friction.
//
// Rejected alternative: swapping Bullet's row solver function (setConstraintRowSolverGeneric)
// for one that reads bounds hidden in the row. It would keep Bullet's loop, but the function
// gets no context, and joint and friction rows cannot be told apart from the row alone.
#include "engines/bullet/friction_solver.hpp"

#include <algorithm>
#include <utility>

namespace asperity::bullet_detail {

namespace {

// Bullet's in-place shuffle of a row order (btRandInt2 draws in the same sequence).
template <class Rand>
void shuffle(btAlignedObjectArray<int>& order, int count, Rand&& rand) {
  for (int j = 0; j < count; ++j) {
    const int tmp = order[j];
    const int swap = rand(j + 1);
    order[j] = order[swap];
    order[swap] = tmp;
  }
}

}  // namespace

FrictionSolver::FrictionSolver(std::function<void()> before_solve, const PointBounds& bounds)
    : before_solve_(std::move(before_solve)), bounds_(bounds) {}

void FrictionSolver::prepareSolve(int num_bodies, int num_manifolds) {
  btSequentialImpulseConstraintSolver::prepareSolve(num_bodies, num_manifolds);
  before_solve_();
}

btScalar FrictionSolver::solveGroupCacheFriendlySetup(
    btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds, int num_manifolds,
    btTypedConstraint** constraints, int num_constraints, const btContactSolverInfo& info,
    btIDebugDraw* debug_draw) {
  const btScalar out = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info, debug_draw);
  // Each friction row's contact row holds its manifold point; its rows follow each other from
  // the contact's m_frictionIndex: first along m_lateralFrictionDir1 (t), then Dir2 (b).
  const int count = m_tmpSolverContactFrictionConstraintPool.size();
  rows_.resize(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const btSolverConstraint& row = m_tmpSolverContactFrictionConstraintPool[i];
    const btSolverConstraint& contact = m_tmpSolverContactConstraintPool[row.m_frictionIndex];
    const auto found =
        bounds_.find(static_cast<const btManifoldPoint*>(contact.m_originalContactPoint));
    RowBounds& r = rows_[static_cast<size_t>(i)];
    // Contacts Asperity does not handle keep Bullet's symmetric bounds.
    r = {row.m_friction, row.m_friction};
    if (found == bounds_.end()) continue;
    const BoxLimit& box = found->second;
    const bool along_t = i == contact.m_frictionIndex;
    r.upper = static_cast<btScalar>(std::max(0.0, along_t ? box.mu_pos_t : box.mu_pos_b));
    r.lower = static_cast<btScalar>(std::max(0.0, along_t ? box.mu_neg_t : box.mu_neg_b));
  }
  return out;
}

btScalar FrictionSolver::solveSingleIteration(
    int iteration, btCollisionObject** /*bodies*/, int /*num_bodies*/,
    btPersistentManifold** /*manifolds*/, int /*num_manifolds*/, btTypedConstraint** constraints,
    int num_constraints, const btContactSolverInfo& info, btIDebugDraw* /*debug_draw*/) {
  BT_PROFILE("solveSingleIteration");
  // Bullet's order: shuffles, joint rows, then (within the contact iterations) old-style
  // constraints, contacts and their friction, rolling friction. Residuals are squared.
  if (info.m_solverMode & SOLVER_RANDMIZE_ORDER) shuffleRows(iteration, info);
  btScalar residual = solveJointRows(iteration);
  if (iteration >= info.m_numIterations) return residual;
  solveObsoleteConstraints(constraints, num_constraints, info);
  const bool interleave =
      (info.m_solverMode & SOLVER_INTERLEAVE_CONTACT_AND_FRICTION_CONSTRAINTS) != 0;
  residual = btMax(residual, interleave ? solveInterleaved(info) : solveContactsThenFriction());
  return btMax(residual, solveRollingFriction());
}

void FrictionSolver::shuffleRows(int iteration, const btContactSolverInfo& info) {
  auto rand = [this](int n) { return btRandInt2(n); };
  shuffle(m_orderNonContactConstraintPool, m_tmpSolverNonContactConstraintPool.size(), rand);
  // Contact and friction rows only while they are iterated.
  if (iteration >= info.m_numIterations) return;
  shuffle(m_orderTmpConstraintPool, m_tmpSolverContactConstraintPool.size(), rand);
  shuffle(m_orderFrictionConstraintPool, m_tmpSolverContactFrictionConstraintPool.size(), rand);
}

btScalar FrictionSolver::solveJointRows(int iteration) {
  btScalar residual = 0;
  for (int j = 0; j < m_tmpSolverNonContactConstraintPool.size(); ++j) {
    btSolverConstraint& row =
        m_tmpSolverNonContactConstraintPool[m_orderNonContactConstraintPool[j]];
    if (iteration >= row.m_overrideNumSolverIterations) continue;
    residual = btMax(residual, generic(row));
  }
  return residual;
}

void FrictionSolver::solveObsoleteConstraints(btTypedConstraint** constraints, int count,
                                              const btContactSolverInfo& info) {
  for (int j = 0; j < count; ++j) {
    if (!constraints[j]->isEnabled()) continue;
    const int a = getOrInitSolverBody(constraints[j]->getRigidBodyA(), info.m_timeStep);
    const int b = getOrInitSolverBody(constraints[j]->getRigidBodyB(), info.m_timeStep);
    constraints[j]->solveConstraintObsolete(m_tmpSolverBodyPool[a], m_tmpSolverBodyPool[b],
                                            info.m_timeStep);
  }
}

btScalar FrictionSolver::solveContactsThenFriction() {
  btScalar residual = 0;
  // Every contact row, then every friction row with its contact's current normal impulse.
  for (int j = 0; j < m_tmpSolverContactConstraintPool.size(); ++j) {
    const btSolverConstraint& row = m_tmpSolverContactConstraintPool[m_orderTmpConstraintPool[j]];
    residual = btMax(residual, lowerLimit(row));
  }
  for (int j = 0; j < m_tmpSolverContactFrictionConstraintPool.size(); ++j) {
    const int row = m_orderFrictionConstraintPool[j];
    const int contact = m_tmpSolverContactFrictionConstraintPool[row].m_frictionIndex;
    residual =
        btMax(residual,
              solveFrictionRow(row, m_tmpSolverContactConstraintPool[contact].m_appliedImpulse));
  }
  return residual;
}

btScalar FrictionSolver::solveInterleaved(const btContactSolverInfo& info) {
  btScalar residual = 0;
  const int per_contact = (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) ? 2 : 1;
  // Each contact row, then its friction rows with the normal impulse it just got.
  for (int c = 0; c < m_tmpSolverContactConstraintPool.size(); ++c) {
    const btSolverConstraint& row = m_tmpSolverContactConstraintPool[m_orderTmpConstraintPool[c]];
    residual = btMax(residual, lowerLimit(row));
    const btScalar normal_impulse = row.m_appliedImpulse;
    for (int k = 0; k < per_contact; ++k) {
      const int friction = m_orderFrictionConstraintPool[c * per_contact + k];
      residual = btMax(residual, solveFrictionRow(friction, normal_impulse));
    }
  }
  return residual;
}

btScalar FrictionSolver::solveFrictionRow(int index, btScalar normal_impulse) {
  if (!(normal_impulse > btScalar(0))) return 0;
  // SPEC 4, box: the row's impulse on A within [-mu_neg lambda_n, mu_pos lambda_n].
  btSolverConstraint& row = m_tmpSolverContactFrictionConstraintPool[index];
  const RowBounds& bounds = rows_[static_cast<size_t>(index)];
  row.m_lowerLimit = -(bounds.lower * normal_impulse);
  row.m_upperLimit = bounds.upper * normal_impulse;
  return generic(row);
}

btScalar FrictionSolver::generic(const btSolverConstraint& row) {
  const btScalar r = resolveSingleConstraintRowGeneric(
      m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
  return r * r;
}

btScalar FrictionSolver::lowerLimit(const btSolverConstraint& row) {
  const btScalar r = resolveSingleConstraintRowLowerLimit(
      m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
  return r * r;
}

btScalar FrictionSolver::solveRollingFriction() {
  btScalar residual = 0;
  // Bullet's rolling and spinning friction rows, unchanged (bounded by their own coefficient).
  for (int j = 0; j < m_tmpSolverContactRollingFrictionConstraintPool.size(); ++j) {
    btSolverConstraint& row = m_tmpSolverContactRollingFrictionConstraintPool[j];
    const btScalar total = m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_appliedImpulse;
    if (!(total > btScalar(0))) continue;
    const btScalar magnitude = btMin(row.m_friction * total, row.m_friction);
    row.m_lowerLimit = -magnitude;
    row.m_upperLimit = magnitude;
    residual = btMax(residual, generic(row));
  }
  return residual;
}

}  // namespace asperity::bullet_detail
