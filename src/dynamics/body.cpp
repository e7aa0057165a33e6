// Live bodies from descriptions: mass properties, centre-of-mass frame, inverse inertia.
#include "asperity/dynamics/body.hpp"

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "geometry/mass.hpp"

namespace asperity {

namespace {

// One line naming the body for error messages.
std::string label(const BodyDesc& desc) {
  return "body '" + (desc.name.empty() ? std::string("<unnamed>") : desc.name) + "'";
}

// Rejects poses and velocities with NaN/inf and rotations that are far from unit length.
void checkState(const BodyDesc& desc) {
  const bool finite = desc.pose.position.allFinite() && desc.pose.rotation.coeffs().allFinite() &&
                      desc.linear_velocity.allFinite() && desc.angular_velocity.allFinite();
  if (!finite) throw Error(label(desc) + ": pose or velocity is not finite");
  if (std::abs(desc.pose.rotation.norm() - 1.0) > 1e-3) {
    throw Error(label(desc) + ": pose rotation is not a unit quaternion");
  }
  if (desc.mass_override < 0.0) throw Error(label(desc) + ": mass must be >= 0");
}

}  // namespace

Mat3 Body::inverseInertiaWorld() const {
  // R diag(I^-1) R^T.
  const Mat3 r = pose.rotation.toRotationMatrix();
  return r * inverse_inertia_local.asDiagonal() * r.transpose();
}

Body makeBody(const BodyDesc& desc) {
  checkState(desc);
  Body body;
  body.name = desc.name;
  body.type = desc.type;
  body.pose = {desc.pose.position, desc.pose.rotation.normalized()};
  body.linear_velocity = desc.linear_velocity;
  body.angular_velocity = desc.angular_velocity;
  body.shapes = desc.shapes;
  body.frame_axis = desc.frame_axis;
  if (desc.type == BodyType::Static) {
    body.linear_velocity.setZero();
    body.angular_velocity.setZero();
  }
  // Planes are infinite: only static bodies may carry them.
  for (const Shape& s : desc.shapes) {
    if (s.type == ShapeType::Plane && desc.type != BodyType::Static) {
      throw Error(label(desc) + ": a plane shape needs a static body");
    }
  }
  if (desc.type != BodyType::Dynamic) return body;

  // Dynamic: principal frame at the centre of mass.
  const PrincipalFrame frame = principalFrame(desc.shapes);
  double mass = frame.properties.mass;
  Vec3 inertia = frame.principal_inertia;
  if (!(mass > 0.0)) throw Error(label(desc) + ": dynamic body has no mass (no solid shape)");
  if (desc.mass_override > 0.0) {
    inertia *= desc.mass_override / mass;
    mass = desc.mass_override;
  }
  if (!(inertia.minCoeff() > 0.0)) throw Error(label(desc) + ": inertia is not positive");
  body.inverse_mass = 1.0 / mass;
  body.inverse_inertia_local = inertia.cwiseInverse();
  // Move the body frame; shapes keep their place in the world.
  body.com_offset = frame.com_frame;
  body.pose = body.pose * frame.com_frame;
  const Transform to_com = frame.com_frame.inverse();
  for (Shape& s : body.shapes) s.local = to_com * s.local;
  body.frame_axis = to_com.rotation * desc.frame_axis;
  return body;
}

}  // namespace asperity
