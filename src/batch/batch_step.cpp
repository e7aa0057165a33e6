// A batch's actions and its step: forces and torques as one-step loads, velocities written
// into the bodies, joint targets into the joints, before each step of every world on the pool.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "asperity/batch/batch.hpp"
#include "asperity/error.hpp"
#include "batch/each_world.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {
namespace {

// Numbers per world of an action, and its name in messages.
size_t widthOf(BatchAction kind) {
  return kind == BatchAction::JointTarget ? 1 : 3;
}

const char* nameOf(BatchAction kind) {
  switch (kind) {
    case BatchAction::Force:
      return "force";
    case BatchAction::Torque:
      return "torque";
    case BatchAction::AngularVelocity:
      return "angular velocity";
    case BatchAction::LinearVelocity:
      return "velocity";
    default:
      return "joint target";
  }
}

// A load on `body` for exactly the coming step: World::step's clock reaches `end` after it.
LoadDesc oneStepLoad(const World& world, BodyId body, LoadDesc::Kind kind, const double* v) {
  LoadDesc load;
  load.name = "batch";
  load.body = body;
  load.kind = kind;
  load.value = Vec3(v[0], v[1], v[2]);
  load.start = world.time();
  load.end = world.time() + world.settings().dt;
  return load;
}

}  // namespace

void Batch::setAction(BatchAction kind, uint32_t target, std::span<const double> values) {
  // The target: a distance joint, or a body that the action can move.
  const World& first = *worlds_[0];
  const std::string what = std::string(nameOf(kind)) + " on ";
  if (kind == BatchAction::JointTarget) {
    if (target >= joint_names_.size())
      throw Error(what + "joint id " + std::to_string(target) + ": no such joint");
    if (first.joints()[target].type != JointType::Distance)
      throw Error(what + "'" + joint_names_[target] + "': only distance joints take a target");
  } else {
    if (target >= bodyNames().size())
      throw Error(what + "body id " + std::to_string(target) + ": no such body");
    const BodyType type = first.bodies()[target].type;
    const bool load = kind == BatchAction::Force || kind == BatchAction::Torque;
    if ((load && type != BodyType::Dynamic) || type == BodyType::Static)
      throw Error(what + "'" + bodyNames()[target] + "': the body is " +
                  (type == BodyType::Static ? "static" : "kinematic") +
                  (load ? " (forces and torques move dynamic bodies only)" : ""));
  }
  // n rows of finite numbers.
  const std::string name =
      what + "'" + (kind == BatchAction::JointTarget ? joint_names_ : bodyNames())[target] + "'";
  const size_t width = widthOf(kind), size = worlds_.size() * width;
  if (values.size() != size)
    throw Error(name + ": needs " + std::to_string(size) + " numbers (n x " +
                std::to_string(width) + "), got " + std::to_string(values.size()));
  for (size_t k = 0; k < size; ++k)
    if (!std::isfinite(values[k]))
      throw Error(name + ": the value of world " + std::to_string(k / width) + " is not finite");
  // Kept in (kind, target) order, so that angular velocities are set before linear ones.
  Action action{kind, target, std::vector<double>(values.begin(), values.end())};
  const auto before = [](const Action& a, const Action& b) {
    return std::pair(a.kind, a.target) < std::pair(b.kind, b.target);
  };
  const auto at = std::lower_bound(actions_.begin(), actions_.end(), action, before);
  if (at != actions_.end() && at->kind == kind && at->target == target)
    *at = std::move(action);
  else
    actions_.insert(at, std::move(action));
}

void Batch::applyActions(size_t i) {
  World& world = *worlds_[i];
  for (const Action& a : actions_) {
    const double* v = a.values.data() + i * widthOf(a.kind);
    switch (a.kind) {
      case BatchAction::Force:
        world.addLoad(oneStepLoad(world, a.target, LoadDesc::Kind::Force, v));
        break;
      case BatchAction::Torque:
        world.addLoad(oneStepLoad(world, a.target, LoadDesc::Kind::Torque, v));
        break;
      case BatchAction::AngularVelocity:
        world.body(a.target).angular_velocity = Vec3(v[0], v[1], v[2]);
        break;
      case BatchAction::LinearVelocity: {
        // The frame origin's velocity: v_com = v - w x (origin - com).
        Body& b = world.body(a.target);
        b.linear_velocity =
            Vec3(v[0], v[1], v[2]) -
            b.angular_velocity.cross(b.descriptionPose().position - b.pose.position);
        break;
      }
      case BatchAction::JointTarget:
        world.setJointRestLength(a.target, v[0]);
        break;
    }
  }
}

void Batch::step(int64_t steps) {
  if (steps < 0) throw Error("step: the step count must be >= 0, got " + std::to_string(steps));
  const bool loads = std::any_of(actions_.begin(), actions_.end(), [](const Action& a) {
    return a.kind == BatchAction::Force || a.kind == BatchAction::Torque;
  });
  std::vector<size_t> all(worlds_.size());
  std::iota(all.begin(), all.end(), size_t{0});
  // Each world's steps on one pool thread; its rows of the state after them, even on error.
  const std::string error = eachWorld(*pool_, all, [&](size_t i) {
    World& world = *worlds_[i];
    try {
      for (int64_t s = 0; s < steps; ++s) {
        applyActions(i);
        world.step();
        // The action's loads have done their work.
        if (loads) world.removeFinishedLoads();
      }
    } catch (const Error&) {
      gather(i);
      throw;
    }
    gather(i);
  });
  // Actions are for one step() call.
  actions_.clear();
  if (!error.empty()) throw Error(error);
}

}  // namespace asperity
