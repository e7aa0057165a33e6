// The world's state after each step: finite, and no body faster than the set limit; the
// likely cause of a blow-up; load-time warnings for parameters that cannot be stable.
#include "asperity/world/state_check.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "asperity/world/world.hpp"

namespace asperity {

namespace {

std::string quoted(const std::string& name) {
  return "'" + name + "'";
}

std::string number(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

// Mass of a dynamic body (kg); 0 for static and kinematic bodies.
double massOf(const Body& body) {
  return body.isDynamic() && body.inverse_mass > 0.0 ? 1.0 / body.inverse_mass : 0.0;
}

// Ratio of the larger to the smaller mass of two dynamic bodies; 1 when either is not dynamic.
double massRatio(const Body& a, const Body& b) {
  const double ma = massOf(a);
  const double mb = massOf(b);
  if (ma <= 0.0 || mb <= 0.0) return 1.0;
  return std::max(ma, mb) / std::min(ma, mb);
}

// Period of a spring on a free body, T = 2 pi sqrt(m / k) (s); infinite when it cannot swing.
double springPeriod(const World& world, const SpringDesc& spring) {
  const double mass = massOf(world.body(spring.body));
  if (mass <= 0.0 || !(spring.stiffness > 0.0)) return INFINITY;
  return 2.0 * std::numbers::pi * std::sqrt(mass / spring.stiffness);
}

bool finite(const Vec3& v) {
  return v.allFinite();
}

// What is wrong with one body's state, or "" when nothing is.
std::string stateProblem(const Body& body, double max_speed) {
  if (!finite(body.pose.position)) return "position is not finite";
  if (!body.pose.rotation.coeffs().allFinite()) return "orientation is not finite";
  if (!finite(body.linear_velocity)) return "velocity is not finite";
  if (!finite(body.angular_velocity)) return "angular velocity is not finite";
  const double speed = body.linear_velocity.norm();
  if (max_speed > 0.0 && speed > max_speed)
    return "speed " + number(speed) + " m/s is above the limit of " + number(max_speed) +
           " m/s (WorldSettings::max_speed)";
  return {};
}

}  // namespace

std::string likelyCause(const World& world, BodyId id) {
  const double dt = world.settings().dt;
  // A spring too stiff for the step: semi-implicit Euler needs the period well above dt.
  for (const SpringDesc& spring : world.springs()) {
    const double period = springPeriod(world, spring);
    if (spring.body == id && period < 2.0 * dt)
      return "spring " + quoted(spring.name) + " has a period of " + number(period) +
             " s, shorter than 2 dt = " + number(2.0 * dt) + " s (lower its stiffness or dt)";
  }
  // A joint or contact between very different masses: PGS cannot converge in its iterations.
  for (const JointDesc& joint : world.joints()) {
    if (joint.body_a != id && joint.body_b != id) continue;
    const double ratio = massRatio(world.body(joint.body_a), world.body(joint.body_b));
    if (ratio > kMaxStableMassRatio)
      return "joint " + quoted(joint.name) + " joins masses in a ratio of " + number(ratio);
  }
  for (const Contact& c : world.contacts()) {
    if (c.body_a != id && c.body_b != id) continue;
    const double ratio = massRatio(world.body(c.body_a), world.body(c.body_b));
    if (ratio > kMaxStableMassRatio)
      return "a contact between " + quoted(world.body(c.body_a).name) + " and " +
             quoted(world.body(c.body_b).name) + " has a mass ratio of " + number(ratio);
  }
  return "a load, spring or initial velocity too large for dt = " + number(dt) + " s";
}

void checkWorldState(const World& world, int64_t step) {
  const auto bodies = world.bodies();
  for (BodyId id = 0; id < bodies.size(); ++id) {
    // Static and kinematic bodies follow their descriptions; only dynamic ones can blow up.
    if (!bodies[id].isDynamic()) continue;
    const std::string problem = stateProblem(bodies[id], world.settings().max_speed);
    if (problem.empty()) continue;
    throw StepError("step " + std::to_string(step) + " (t = " + number(world.time()) +
                        " s): body " + quoted(bodies[id].name) + ": " + problem +
                        "; likely cause: " + likelyCause(world, id),
                    id, step);
  }
}

std::vector<std::string> stabilityWarnings(const World& world) {
  std::vector<std::string> out;
  const double dt = world.settings().dt;
  // Springs whose period is under 2 dt oscillate with growing amplitude.
  for (const SpringDesc& spring : world.springs()) {
    const double period = springPeriod(world, spring);
    if (period < 2.0 * dt)
      out.push_back("spring " + quoted(spring.name) + ": period " + number(period) +
                    " s is shorter than 2 dt = " + number(2.0 * dt) +
                    " s; the spring will not be simulated stably");
  }
  // Joints between bodies whose masses differ by more than kMaxStableMassRatio.
  for (const JointDesc& joint : world.joints()) {
    const double ratio = massRatio(world.body(joint.body_a), world.body(joint.body_b));
    if (ratio > kMaxStableMassRatio)
      out.push_back("joint " + quoted(joint.name) + ": mass ratio " + number(ratio) + " between " +
                    quoted(world.body(joint.body_a).name) + " and " +
                    quoted(world.body(joint.body_b).name) + " is beyond " +
                    number(kMaxStableMassRatio) + "; the joint will stretch or explode");
  }
  return out;
}

}  // namespace asperity
