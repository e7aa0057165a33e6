// Joint rows of the PGS solver: ball blocks and scalar rows (distance, hinge and fixed angular
// rows), velocity constraints with a Baumgarte bias (fraction `baumgarte` of the position
// error removed per step).
#include <algorithm>
#include <cmath>

#include "solver/contact_solver.hpp"

namespace asperity {

namespace {

constexpr size_t kSlots = 6;  // per joint: 3 ball + up to 3 scalar rows

}  // namespace

void ContactSolver::setJoints(std::span<const JointDesc> joints,
                              std::span<const Quat> rest_rotations, double t, double dt) {
  // Into the solver's own scratch: a warmed-up step allocates nothing.
  joints_.resize(joints.size());
  for (size_t i = 0; i < joints.size(); ++i) {
    const JointDesc& j = joints[i];
    const Transform& a = com_offset_[j.body_a];
    const Transform& b = com_offset_[j.body_b];
    SolverJoint& s = joints_[i];
    s.type = j.type;
    s.body_a = j.body_a;
    s.body_b = j.body_b;
    s.anchor_a = a.applyInverse(j.anchor_a);
    s.anchor_b = b.applyInverse(j.anchor_b);
    s.axis_a = a.rotation.conjugate() * j.axis_a;
    s.axis_b = b.rotation.conjugate() * j.axis_b;
    s.rest_rotation = rest_rotations[i];
    s.length = distanceJointLength(j, t);
    s.length_rate = (distanceJointLength(j, t + dt) - s.length) / dt;
  }
  setJoints(joints_);
}

void ContactSolver::setJoints(std::span<const SolverJoint> joints) {
  islands_ready_ = false;
  balls_.clear();
  axes_.clear();
  joint_lambda_.resize(joints.size() * kSlots, 0.0);
  const double bias_rate = settings_.baumgarte / settings_.dt;
  for (size_t j = 0; j < joints.size(); ++j) {
    const SolverJoint& jd = joints[j];
    const size_t a = jd.body_a, b = jd.body_b;
    const int ia = static_cast<int>(a), ib = static_cast<int>(b), ji = static_cast<int>(j);
    const Vec3 ra = rotation_[a] * jd.anchor_a;
    const Vec3 rb = rotation_[b] * jd.anchor_b;
    const Vec3 error = (position_[a] + ra) - (position_[b] + rb);
    // Distance: one row along the anchors' separation, time-varying target length.
    if (jd.type == JointType::Distance) {
      const double length = error.norm();
      const Vec3 n = length > 1e-12 ? Vec3(error / length) : Vec3::UnitZ();
      AxisRow row;
      row.a = ia;
      row.b = ib;
      row.joint = ji;
      row.slot = 3;
      row.ang_a = ra.cross(n);
      row.ang_b = rb.cross(n);
      row.lin = n;
      row.target = jd.length_rate - bias_rate * (length - jd.length);
      addAxisRow(row);
      continue;
    }
    // Ball part of ball, hinge and fixed joints: K = (m_a^-1 + m_b^-1) 1 - [ra] Ia [ra] - ...
    BallRow ball{ia, ib, ji, ra, rb, Mat3::Zero(), bias_rate * error, Vec3::Zero()};
    const Mat3 sa = skew(ra), sb = skew(rb);
    const Mat3 k = (inv_mass_[a] + inv_mass_[b]) * Mat3::Identity() - sa * inv_inertia_[a] * sa -
                   sb * inv_inertia_[b] * sb;
    ball.inv_k = k.determinant() > 1e-300 ? Mat3(k.inverse()) : Mat3::Zero();
    balls_.push_back(ball);
    // Angular rows: C_u = u . theta with d theta / dt = w_a - w_b.
    if (jd.type == JointType::Hinge) {
      const Vec3 a1 = (rotation_[a] * jd.axis_a).normalized();
      const Vec3 a2 = (rotation_[b] * jd.axis_b).normalized();
      // p, q complete a1 to an orthonormal basis.
      const Vec3 p = anyPerpendicular(a1);
      const Vec3 q = a1.cross(p);
      const Vec3 theta = a2.cross(a1);  // small-angle rotation error perpendicular to a1
      addAngularRow(ia, ib, ji, 3, p, -bias_rate * p.dot(theta));
      addAngularRow(ia, ib, ji, 4, q, -bias_rate * q.dot(theta));
    } else if (jd.type == JointType::Fixed) {
      // Error rotation e = q_a r q_b^-1, theta = 2 vec(e) (shortest way round).
      Quat e = rotation_[a] * jd.rest_rotation * rotation_[b].conjugate();
      if (e.w() < 0.0) e.coeffs() = -e.coeffs();
      const Vec3 theta = 2.0 * e.vec();
      for (int k2 = 0; k2 < 3; ++k2) {
        const Vec3 u = Vec3::Unit(k2);
        addAngularRow(ia, ib, ji, 3 + k2, u, -bias_rate * theta[k2]);
      }
    }
  }
}

void ContactSolver::addAngularRow(int a, int b, int joint, int slot, const Vec3& u, double target) {
  AxisRow row;
  row.a = a;
  row.b = b;
  row.joint = joint;
  row.slot = slot;
  row.ang_a = u;
  row.ang_b = u;
  row.target = target;
  addAxisRow(row);
}

void ContactSolver::addAxisRow(AxisRow row) {
  // I^-1 of the angular parts and the effective mass 1 / (J M^-1 J^T).
  const size_t a = static_cast<size_t>(row.a), b = static_cast<size_t>(row.b);
  row.ia = inv_inertia_[a] * row.ang_a;
  row.ib = inv_inertia_[b] * row.ang_b;
  const double k = (inv_mass_[a] + inv_mass_[b]) * row.lin.squaredNorm() + row.ang_a.dot(row.ia) +
                   row.ang_b.dot(row.ib);
  row.mass = k > 1e-300 ? 1.0 / k : 0.0;
  row.lambda = 0.0;
  axes_.push_back(row);
}

void ContactSolver::warmStartJoints() {
  // Last step's impulses of the same joints (rows are rebuilt in the same order).
  for (BallRow& r : balls_) {
    const size_t s = static_cast<size_t>(r.joint) * kSlots;
    r.lambda = Vec3(joint_lambda_[s], joint_lambda_[s + 1], joint_lambda_[s + 2]);
    const size_t a = static_cast<size_t>(r.a), b = static_cast<size_t>(r.b);
    applyImpulse(r.a, r.b, r.lambda, inv_inertia_[a] * r.ra.cross(r.lambda),
                 inv_inertia_[b] * r.rb.cross(r.lambda));
  }
  for (AxisRow& r : axes_) {
    r.lambda = joint_lambda_[static_cast<size_t>(r.joint) * kSlots + static_cast<size_t>(r.slot)];
    applyImpulse(r.a, r.b, r.lambda * r.lin, r.lambda * r.ia, r.lambda * r.ib);
  }
}

void ContactSolver::storeJointImpulses() {
  std::fill(joint_lambda_.begin(), joint_lambda_.end(), 0.0);
  for (const BallRow& r : balls_) {
    const size_t s = static_cast<size_t>(r.joint) * kSlots;
    for (int k = 0; k < 3; ++k) joint_lambda_[s + static_cast<size_t>(k)] = r.lambda[k];
  }
  for (const AxisRow& r : axes_) {
    joint_lambda_[static_cast<size_t>(r.joint) * kSlots + static_cast<size_t>(r.slot)] = r.lambda;
  }
}

double ContactSolver::sweepJoints(const Island& island) {
  double delta2 = 0.0;
  // Ball blocks: P = -K^-1 Cdot on the velocities, applied at both anchors. The drift is
  // removed on the pseudo-velocities (split impulse, as for contacts): a Baumgarte bias in
  // the velocities would be real motion that friction has to hold (a chain on a rod creeps).
  for (const int index : island.balls) {
    BallRow& r = balls_[static_cast<size_t>(index)];
    const size_t a = static_cast<size_t>(r.a), b = static_cast<size_t>(r.b);
    const Vec3 cdot = (v_[a] + w_[a].cross(r.ra)) - (v_[b] + w_[b].cross(r.rb));
    const Vec3 p = -(r.inv_k * cdot);
    r.lambda += p;
    applyImpulse(r.a, r.b, p, inv_inertia_[a] * r.ra.cross(p), inv_inertia_[b] * r.rb.cross(p));
    delta2 += p.squaredNorm();
    // Pseudo-velocity block toward -bias.
    const Vec3 cdot_p = (vp_[a] + wp_[a].cross(r.ra)) - (vp_[b] + wp_[b].cross(r.rb));
    const Vec3 pp = -(r.inv_k * (cdot_p + r.bias));
    if (inv_mass_[a] > 0.0) {
      vp_[a] += inv_mass_[a] * pp;
      wp_[a] += inv_inertia_[a] * r.ra.cross(pp);
    }
    if (inv_mass_[b] > 0.0) {
      vp_[b] -= inv_mass_[b] * pp;
      wp_[b] -= inv_inertia_[b] * r.rb.cross(pp);
    }
  }
  // Scalar rows, unbounded.
  for (const int index : island.axes) {
    AxisRow& r = axes_[static_cast<size_t>(index)];
    const size_t a = static_cast<size_t>(r.a), b = static_cast<size_t>(r.b);
    const double jv = r.lin.dot(v_[a] - v_[b]) + r.ang_a.dot(w_[a]) - r.ang_b.dot(w_[b]);
    const double d = (r.target - jv) * r.mass;
    r.lambda += d;
    applyImpulse(r.a, r.b, d * r.lin, d * r.ia, d * r.ib);
    delta2 += d * d;
  }
  return delta2;
}

}  // namespace asperity
