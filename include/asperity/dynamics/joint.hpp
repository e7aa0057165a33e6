// Joints between two bodies: pure descriptions that the world turns into velocity constraints
// (solved by the same PGS loop as contacts, with Baumgarte position correction).
#pragma once

#include <string>

#include "asperity/dynamics/body.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

enum class JointType {
  Distance,  // one row: |p_a - p_b| = length(t)
  Ball,      // three rows: p_a = p_b
  Hinge,     // ball + two angular rows keeping axis_a parallel to axis_b
  Fixed      // ball + three angular rows keeping the initial relative orientation
};
inline constexpr std::pair<const char*, JointType> kJointTypeNames[] = {
    {"distance", JointType::Distance},
    {"ball", JointType::Ball},
    {"hinge", JointType::Hinge},
    {"fixed", JointType::Fixed}};

// A joint's index in its world, as World::createJoint returns it.
using JointId = uint32_t;
inline constexpr JointId kNoJoint = 0xffffffffu;

struct JointDesc {
  std::string name;
  JointType type = JointType::Ball;
  BodyId body_a = kNoBody;
  BodyId body_b = kNoBody;
  Vec3 anchor_a = Vec3::Zero();  // body-local attachment point on A (m, body frame)
  Vec3 anchor_b = Vec3::Zero();  // body-local attachment point on B (m, body frame)
  Vec3 axis_a = Vec3::UnitZ();   // hinge axis in A's frame (unit)
  Vec3 axis_b = Vec3::UnitZ();   // hinge axis in B's frame (unit)
  // Distance joints: length(t) = rest_length + amplitude cos(2 pi frequency t + phase).
  double rest_length = -1.0;       // m; < 0 = the anchors' distance when the joint is created
  double amplitude = 0.0;          // m
  double frequency = 0.0;          // Hz
  double phase = 0.0;              // rad
  bool collide_connected = false;  // false: the two bodies never collide with each other
};

// Target length of a distance joint at time t (s).
double distanceJointLength(const JointDesc& joint, double time);

}  // namespace asperity
