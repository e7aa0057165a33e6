// Joint rows of the solver: ball, distance, hinge and fixed constraints on free bodies.
#include <gtest/gtest.h>

#include <vector>

#include "solver/contact_solver.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

Body cube(const Vec3& position, const Vec3& v, const Vec3& w) {
  Body b;
  b.pose.position = position;
  b.inverse_mass = 1.0;
  b.inverse_inertia_local = Vec3::Constant(150.0);
  b.linear_velocity = v;
  b.angular_velocity = w;
  return b;
}

// Velocity of the world point `p` of body `id` in the solver.
Vec3 pointVelocity(const ContactSolver& s, const std::vector<Body>& bodies, BodyId id,
                   const Vec3& p) {
  return s.linearVelocity(id) + s.angularVelocity(id).cross(p - bodies[id].pose.position);
}

struct Pair {
  std::vector<Body> bodies;
  ContactSolver solver;
};

// Two spinning, drifting cubes joined at x = 0.1 and solved to convergence.
void solvePair(Pair& p, const SolverJoint& joint) {
  p.bodies = {cube(Vec3(0, 0, 0), Vec3(1, 0, 0.5), Vec3(0.3, 2, 0)),
              cube(Vec3(0.2, 0, 0), Vec3(-1, 0.4, 0), Vec3(0, -1, 3))};
  SolverSettings s;
  s.warm_starting = false;
  p.solver.begin(p.bodies, s);
  const std::vector<SolverJoint> joints{joint};
  p.solver.setJoints(joints);
  p.solver.setContacts({}, true);
  p.solver.iterate(200);
}

SolverJoint joint(JointType type) {
  SolverJoint j;
  j.type = type;
  j.body_a = 0;
  j.body_b = 1;
  j.anchor_a = Vec3(0.1, 0, 0);
  j.anchor_b = Vec3(-0.1, 0, 0);
  j.axis_a = j.axis_b = Vec3::UnitY();
  j.length = 0.0;
  return j;
}

TEST(JointRows, BallJointAnchorsMoveTogether) {
  Pair p;
  solvePair(p, joint(JointType::Ball));
  const Vec3 anchor(0.1, 0, 0);
  EXPECT_LT(
      (pointVelocity(p.solver, p.bodies, 0, anchor) - pointVelocity(p.solver, p.bodies, 1, anchor))
          .norm(),
      1e-9);
}

TEST(JointRows, BallJointConservesMomentum) {
  // Internal impulses: total linear momentum unchanged (equal masses).
  Pair p;
  solvePair(p, joint(JointType::Ball));
  const Vec3 total = p.solver.linearVelocity(0) + p.solver.linearVelocity(1);
  EXPECT_LT((total - Vec3(0, 0.4, 0.5)).norm(), 1e-9);
}

TEST(JointRows, HingeLeavesOnlyRotationAboutItsAxis) {
  Pair p;
  solvePair(p, joint(JointType::Hinge));
  const Vec3 relative = p.solver.angularVelocity(0) - p.solver.angularVelocity(1);
  EXPECT_LT(std::abs(relative.x()) + std::abs(relative.z()), 1e-9);
  EXPECT_GT(std::abs(relative.y()), 0.1);
}

TEST(JointRows, FixedJointMovesAsOneBody) {
  Pair p;
  solvePair(p, joint(JointType::Fixed));
  EXPECT_LT((p.solver.angularVelocity(0) - p.solver.angularVelocity(1)).norm(), 1e-9);
}

TEST(JointRows, DistanceJointFollowsItsLengthRate) {
  // Anchors 0.2 m apart (centres), target length 0.2 growing at 0.3 m/s.
  SolverJoint j = joint(JointType::Distance);
  j.anchor_a = j.anchor_b = Vec3::Zero();
  j.length = 0.2;
  j.length_rate = 0.3;
  Pair p;
  solvePair(p, j);
  const double separation_rate = (p.solver.linearVelocity(1) - p.solver.linearVelocity(0)).x();
  EXPECT_TRUE(near(separation_rate, 0.3, 1e-9));
}

TEST(JointRows, BaumgarteBiasPullsAnchorsTogetherOnPseudoVelocities) {
  // Anchors 1 cm apart at rest: the pseudo-velocities close baumgarte * error / dt (split
  // impulse), the velocities stay at rest (drift correction adds no motion).
  SolverJoint j = joint(JointType::Ball);
  j.anchor_b = Vec3(-0.09, 0, 0);
  std::vector<Body> bodies{cube(Vec3::Zero(), Vec3::Zero(), Vec3::Zero()),
                           cube(Vec3(0.2, 0, 0), Vec3::Zero(), Vec3::Zero())};
  SolverSettings s;
  s.warm_starting = false;
  ContactSolver solver;
  solver.begin(bodies, s);
  solver.setJoints(std::vector<SolverJoint>{j});
  solver.iterate(200);
  const Vec3 anchor_a(0.1, 0, 0), anchor_b(0.11, 0, 0);
  const double closing =
      (pointVelocity(solver, bodies, 1, anchor_b) - pointVelocity(solver, bodies, 0, anchor_a)).x();
  EXPECT_TRUE(near(closing, 0.0, 0, 1e-12));
  const Vec3 ra(0.1, 0, 0), rb(-0.09, 0, 0);
  const Vec3 pa = solver.pseudoLinear(0) + solver.pseudoAngular(0).cross(ra);
  const Vec3 pb = solver.pseudoLinear(1) + solver.pseudoAngular(1).cross(rb);
  EXPECT_TRUE(near((pb - pa).x(), -0.2 * 0.01 / s.dt, 1e-9));
}

}  // namespace
}  // namespace asperity
