// ODE geoms as ContactFriction objects (ode_geoms.hpp).
#include "engines/ode/ode_geoms.hpp"

namespace asperity::ode_detail {

std::optional<Shape> geomShape(dGeomID geom) {
  Shape s;
  dReal radius = 0, length = 0;
  switch (dGeomGetClass(geom)) {
    case dPlaneClass: {
      // a x + b y + c z = d with a unit (a, b, c).
      dVector4 p;
      dGeomPlaneGetParams(geom, p);
      s.type = ShapeType::Plane;
      s.plane_normal = Vec3(p[0], p[1], p[2]);
      s.plane_offset = p[3];
      break;
    }
    case dSphereClass:
      s.type = ShapeType::Sphere;
      s.radius = dGeomSphereGetRadius(geom);
      break;
    case dCapsuleClass:
    case dCylinderClass:
      // `length` is the axis' full length (without the capsule's caps).
      if (dGeomGetClass(geom) == dCapsuleClass)
        dGeomCapsuleGetParams(geom, &radius, &length);
      else
        dGeomCylinderGetParams(geom, &radius, &length);
      s.type = dGeomGetClass(geom) == dCapsuleClass ? ShapeType::Capsule : ShapeType::Cylinder;
      s.radius = radius;
      s.half_height = 0.5 * length;
      break;
    case dBoxClass: {
      dVector3 lengths;
      dGeomBoxGetLengths(geom, lengths);
      s.type = ShapeType::Box;
      s.half_extents = 0.5 * Vec3(lengths[0], lengths[1], lengths[2]);
      break;
    }
    default:
      return std::nullopt;
  }
  return s;
}

ObjectState geomState(dGeomID geom) {
  ObjectState s;
  if (dGeomGetClass(geom) == dPlaneClass) return s;
  const dReal* p = dGeomGetPosition(geom);
  dQuaternion q;  // w, x, y, z
  dGeomGetQuaternion(geom, q);
  s.pose = {Vec3(p[0], p[1], p[2]), Quat(q[0], q[1], q[2], q[3]).normalized()};
  // The velocity of the geom's own origin, which a body offset moves off the body's.
  if (dBodyID body = dGeomGetBody(geom)) {
    dVector3 v;
    dBodyGetPointVel(body, p[0], p[1], p[2], v);
    const dReal* w = dBodyGetAngularVel(body);
    s.linear_velocity = Vec3(v[0], v[1], v[2]);
    s.angular_velocity = Vec3(w[0], w[1], w[2]);
  }
  return s;
}

}  // namespace asperity::ode_detail
