// A batch's state arrays: each world's bodies copied into its rows after a step or reset, and
// rows given to a reset written back, in the frame the scene wrote (as asperity.World's arrays).
#include <cmath>

#include "asperity/batch/batch.hpp"
#include "asperity/error.hpp"

namespace asperity {
namespace {

// Row widths of the four arrays, and their names for messages.
struct Part {
  std::vector<double> BatchState::*array;
  size_t width;
  const char* name;
};
constexpr Part kParts[] = {{&BatchState::positions, 3, "positions"},
                           {&BatchState::orientations, 4, "orientations"},
                           {&BatchState::linear_velocities, 3, "linear_velocities"},
                           {&BatchState::angular_velocities, 3, "angular_velocities"}};

// One body's state in the scene's frame.
struct FrameState {
  Vec3 position, linear, angular;
  Quat rotation;
};

// The description frame's pose and its origin's velocity.
FrameState frameState(const Body& b) {
  const Transform pose = b.descriptionPose();
  return {pose.position, b.pointVelocity(pose.position), b.angular_velocity, pose.rotation};
}

Vec3 vec3At(const std::vector<double>& a, size_t row) {
  return Vec3(a[row * 3], a[row * 3 + 1], a[row * 3 + 2]);
}

void putVec3(std::vector<double>& a, size_t row, const Vec3& v) {
  for (int k = 0; k < 3; ++k) a[row * 3 + static_cast<size_t>(k)] = v[k];
}

}  // namespace

void Batch::gather(size_t i) {
  const std::span<const Body> bodies = worlds_[i]->bodies();
  for (size_t b = 0; b < bodies.size(); ++b) {
    // Row i B + b of each array.
    const size_t row = i * bodies.size() + b;
    const FrameState s = frameState(bodies[b]);
    putVec3(state_.positions, row, s.position);
    putVec3(state_.linear_velocities, row, s.linear);
    putVec3(state_.angular_velocities, row, s.angular);
    const double q[4] = {s.rotation.w(), s.rotation.x(), s.rotation.y(), s.rotation.z()};
    std::copy(q, q + 4, state_.orientations.begin() + static_cast<std::ptrdiff_t>(row * 4));
  }
}

void Batch::scatter(size_t i, const BatchState& given) {
  World& world = *worlds_[i];
  const size_t count = world.bodies().size();
  for (BodyId b = 0; b < count; ++b) {
    // The initial state in the scene's frame, with the given parts in place of its own.
    Body& body = world.body(b);
    FrameState s = frameState(body);
    const size_t row = i * count + b;
    if (!given.positions.empty()) s.position = vec3At(given.positions, row);
    if (!given.linear_velocities.empty()) s.linear = vec3At(given.linear_velocities, row);
    if (!given.angular_velocities.empty()) s.angular = vec3At(given.angular_velocities, row);
    if (!given.orientations.empty()) {
      const double* q = given.orientations.data() + row * 4;
      s.rotation = Quat(q[0], q[1], q[2], q[3]).normalized();
    }
    // Back to the body frame: the centre of mass follows the frame, v_com = v - w x (o - com).
    Transform pose;
    pose.position = s.position;
    pose.rotation = s.rotation;
    body.pose = pose * body.com_offset;
    body.angular_velocity = s.angular;
    body.linear_velocity = s.linear - s.angular.cross(s.position - body.pose.position);
  }
}

void Batch::checkGiven(const BatchState& given, std::span<const size_t> worlds) const {
  const size_t bodies = bodyNames().size();
  for (const Part& part : kParts) {
    const std::vector<double>& a = given.*part.array;
    if (a.empty()) continue;
    // Full size, then the chosen worlds' rows finite (and quaternions not zero).
    const size_t size = worlds_.size() * bodies * part.width;
    if (a.size() != size)
      throw Error(std::string("reset: ") + part.name + " needs " + std::to_string(size) +
                  " numbers (n x " + std::to_string(bodies) + " x " + std::to_string(part.width) +
                  "), got " + std::to_string(a.size()));
    for (size_t i : worlds) {
      const size_t begin = i * bodies * part.width;
      for (size_t k = begin; k < begin + bodies * part.width; ++k)
        if (!std::isfinite(a[k]))
          throw Error(std::string("reset: ") + part.name + " of world " + std::to_string(i) +
                      " is not finite");
      if (part.width != 4) continue;
      for (size_t k = begin; k < begin + bodies * 4; k += 4)
        if (!(std::abs(a[k]) + std::abs(a[k + 1]) + std::abs(a[k + 2]) + std::abs(a[k + 3]) > 0))
          throw Error("reset: orientations of world " + std::to_string(i) + " body " +
                      std::to_string((k - begin) / 4) + " is a zero quaternion");
    }
  }
}

}  // namespace asperity
