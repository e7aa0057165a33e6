// Rigid bodies: a description (pure data, what scenes hold) and the live state the step uses.
#pragma once

#include <string>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

enum class BodyType { Static, Kinematic, Dynamic };
inline constexpr std::pair<const char*, BodyType> kBodyTypeNames[] = {
    {"dynamic", BodyType::Dynamic},
    {"static", BodyType::Static},
    {"kinematic", BodyType::Kinematic}};

using BodyId = uint32_t;
inline constexpr BodyId kNoBody = 0xffffffffu;

struct BodyDesc {
  std::string name;
  BodyType type = BodyType::Dynamic;
  Transform pose;                        // body frame in world (m, unit quaternion)
  Vec3 linear_velocity = Vec3::Zero();   // m/s
  Vec3 angular_velocity = Vec3::Zero();  // rad/s, world frame
  std::vector<Shape> shapes;             // compound when more than one
  double mass_override = 0.0;            // kg; 0 = from shapes' densities
  // Contact frame alignment for frame mode "body" (SPEC 5): t follows this body-local axis.
  Vec3 frame_axis = Vec3::Zero();  // zero = not set
};

// The live state of one body; the body frame sits at the centre of mass.
struct Body {
  std::string name;
  BodyType type = BodyType::Dynamic;
  Transform pose;
  Vec3 linear_velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  double inverse_mass = 0.0;
  Vec3 inverse_inertia_local = Vec3::Zero();  // principal, in the body frame
  std::vector<Shape> shapes;                  // local transforms relative to the centre of mass
  Vec3 frame_axis = Vec3::Zero();
  // The body frame (centre of mass, principal axes) relative to the frame the description
  // used: x_body = com_offset.applyInverse(x_desc). Poses of the description's frame are
  // pose * com_offset.inverse().
  Transform com_offset;
  Vec3 force = Vec3::Zero();   // accumulated external force this step (N)
  Vec3 torque = Vec3::Zero();  // accumulated external torque this step (N m)

  bool isDynamic() const { return type == BodyType::Dynamic; }
  // World-space inverse inertia tensor.
  Mat3 inverseInertiaWorld() const;
  // Pose of the description's body frame (what a scene file wrote).
  Transform descriptionPose() const { return pose * com_offset.inverse(); }
  // Velocity of a world point attached to the body (m/s).
  Vec3 pointVelocity(const Vec3& world_point) const {
    return linear_velocity + angular_velocity.cross(world_point - pose.position);
  }
};

// The live body for a description: mass and principal inertia from the shapes' densities
// (or mass_override), body frame moved to the centre of mass and principal axes (shapes'
// local transforms follow), velocities copied. Static and kinematic bodies get infinite mass.
// Throws asperity::Error naming the body for a dynamic body without mass, a plane on a
// non-static body, a non-finite pose or a negative mass_override.
Body makeBody(const BodyDesc& desc);

}  // namespace asperity
