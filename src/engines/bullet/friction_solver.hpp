// Bullet's sequential impulse solver with the box limit surface of SPEC 4: every friction row
// is bounded by the coefficient of its own sense (asperity/engines/bullet.hpp).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <functional>
#include <unordered_map>
#include <vector>

#include "asperity/friction/limit_surfaces/box_limit.hpp"

namespace asperity::bullet_detail {

// The box bounds of this step's contact points, by point; the adapter fills it before the
// islands are solved.
using PointBounds = std::unordered_map<const btManifoldPoint*, BoxLimit>;

class FrictionSolver final : public btSequentialImpulseConstraintSolver {
 public:
  // `before_solve` runs once per step, after collision detection (prepareSolve); `bounds` is
  // read while each island's rows are set up.
  FrictionSolver(std::function<void()> before_solve, const PointBounds& bounds);

  void prepareSolve(int num_bodies, int num_manifolds) override;

 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int num_bodies,
                                        btPersistentManifold** manifolds, int num_manifolds,
                                        btTypedConstraint** constraints, int num_constraints,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* debug_draw) override;
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int num_bodies,
                                btPersistentManifold** manifolds, int num_manifolds,
                                btTypedConstraint** constraints, int num_constraints,
                                const btContactSolverInfo& info, btIDebugDraw* debug_draw) override;

 private:
  // A friction row's bounds per unit normal impulse: of its + sense and of its - sense.
  struct RowBounds {
    btScalar upper = 0, lower = 0;
  };

  void shuffleRows(int iteration, const btContactSolverInfo& info);
  btScalar solveJointRows(int iteration);
  void solveObsoleteConstraints(btTypedConstraint** constraints, int count,
                                const btContactSolverInfo& info);
  btScalar solveContactsThenFriction();
  btScalar solveInterleaved(const btContactSolverInfo& info);
  btScalar solveFrictionRow(int row, btScalar normal_impulse);
  btScalar solveRollingFriction();
  // One row through Bullet's row solver (bounded, or with a lower limit only); its squared
  // residual.
  btScalar generic(const btSolverConstraint& row);
  btScalar lowerLimit(const btSolverConstraint& row);

  std::function<void()> before_solve_;
  const PointBounds& bounds_;
  std::vector<RowBounds> rows_;  // parallel to m_tmpSolverContactFrictionConstraintPool
};

}  // namespace asperity::bullet_detail
