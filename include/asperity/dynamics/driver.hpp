// Things that push bodies around: springs pulling a body point toward a (moving) target, the
// paper's "mouse spring", and timed loads (forces, torques, impulses). All are external forces
// applied before the solve.
#pragma once

#include <string>

#include "asperity/dynamics/body.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

// A spring's and a load's index in their world, as World::addSpring and World::addLoad return
// them (World::springs(), World::loads()).
using SpringId = uint32_t;
inline constexpr SpringId kNoSpring = 0xffffffffu;
using LoadId = uint32_t;
inline constexpr LoadId kNoLoad = 0xffffffffu;

// A damped spring from a body point to a target: f = k (target(t) - p) - c (v_p - v_target).
struct SpringDesc {
  std::string name;
  BodyId body = kNoBody;
  Vec3 local_point = Vec3::Zero();      // attachment point in the body frame (m)
  Vec3 target = Vec3::Zero();           // world point at t = 0 (m); the viewer moves it
  Vec3 target_velocity = Vec3::Zero();  // target(t) = target + target_velocity t (m/s)
  double stiffness = 100.0;             // N/m
  double damping = 0.0;                 // N s/m
};

// A load applied during [start, end) (forces, torques) or once at `start` (impulses).
struct LoadDesc {
  enum class Kind { Force, Torque, Impulse, AngularImpulse };
  std::string name;
  BodyId body = kNoBody;
  Kind kind = Kind::Force;
  Vec3 value = Vec3::Zero();        // world frame: N, N m, N s or N m s
  Vec3 local_point = Vec3::Zero();  // application point of forces and impulses (body frame, m)
  double start = 0.0;               // s
  double end = 1e30;                // s (ignored by impulses)
};
inline constexpr std::pair<const char*, LoadDesc::Kind> kLoadKindNames[] = {
    {"force", LoadDesc::Kind::Force},
    {"torque", LoadDesc::Kind::Torque},
    {"impulse", LoadDesc::Kind::Impulse},
    {"angular_impulse", LoadDesc::Kind::AngularImpulse}};

// World position of a spring's target at time t (s).
inline Vec3 springTarget(const SpringDesc& spring, double time) {
  return spring.target + spring.target_velocity * time;
}

}  // namespace asperity
