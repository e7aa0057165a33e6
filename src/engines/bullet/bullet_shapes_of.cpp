// Asperity shapes from Bullet collision shapes (asperity/engines/bullet.hpp): what
// BulletFriction::attach maps an object's surface onto when the caller gives no shapes.
#include <btBulletCollisionCommon.h>

#include <string>

#include "asperity/engines/bullet.hpp"
#include "asperity/error.hpp"
#include "collision/bullet_shapes.hpp"

namespace asperity {

namespace {

using collision_detail::fromBt;

// Asperity's capsules and cylinders run along local z; Bullet's along their up axis.
Quat zToAxis(int axis) {
  if (axis == 0) return Quat(Eigen::AngleAxisd(0.5 * kPi, Vec3::UnitY()));
  if (axis == 1) return Quat(Eigen::AngleAxisd(-0.5 * kPi, Vec3::UnitX()));
  return Quat::Identity();
}

Transform fromBt(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  return {collision_detail::fromBt(t.getOrigin()),
          Quat(static_cast<double>(q.w()), static_cast<double>(q.x()), static_cast<double>(q.y()),
               static_cast<double>(q.z()))
              .normalized()};
}

// One convex or plane shape (not a compound).
Shape primitiveOf(const btCollisionShape& bt, const std::string& what) {
  Shape s;
  switch (bt.getShapeType()) {
    case BOX_SHAPE_PROXYTYPE:
      s.type = ShapeType::Box;
      s.half_extents = fromBt(static_cast<const btBoxShape&>(bt).getHalfExtentsWithMargin());
      return s;
    case SPHERE_SHAPE_PROXYTYPE:
      s.type = ShapeType::Sphere;
      s.radius = static_cast<const btSphereShape&>(bt).getRadius();
      return s;
    case CAPSULE_SHAPE_PROXYTYPE: {
      const auto& capsule = static_cast<const btCapsuleShape&>(bt);
      s.type = ShapeType::Capsule;
      s.radius = capsule.getRadius();
      s.half_height = capsule.getHalfHeight();
      s.local.rotation = zToAxis(capsule.getUpAxis());
      return s;
    }
    case CYLINDER_SHAPE_PROXYTYPE: {
      const auto& cylinder = static_cast<const btCylinderShape&>(bt);
      const int up = cylinder.getUpAxis();
      const btVector3 half = cylinder.getHalfExtentsWithMargin();
      s.type = ShapeType::Cylinder;
      s.radius = half[(up + 1) % 3];
      s.half_height = half[up];
      s.local.rotation = zToAxis(up);
      return s;
    }
    case STATIC_PLANE_PROXYTYPE: {
      const auto& plane = static_cast<const btStaticPlaneShape&>(bt);
      s.type = ShapeType::Plane;
      s.plane_normal = fromBt(plane.getPlaneNormal()).normalized();
      s.plane_offset = plane.getPlaneConstant();
      return s;
    }
    default:
      throw Error(what + ": Bullet shape '" + bt.getName() +
                  "' has no Asperity counterpart here; attach it with an ObjectDesc that "
                  "describes its shapes");
  }
}

}  // namespace

std::vector<Shape> shapesOfBulletShape(const btCollisionShape& shape, const Surface& surface,
                                       const std::string& what) {
  std::vector<Shape> out;
  // A compound: its children in order, each at its transform (no nested compounds).
  if (shape.getShapeType() == COMPOUND_SHAPE_PROXYTYPE) {
    const auto& compound = static_cast<const btCompoundShape&>(shape);
    for (int i = 0; i < compound.getNumChildShapes(); ++i) {
      Shape child = primitiveOf(*compound.getChildShape(i),
                                what + ": child " + std::to_string(i) + " of its compound");
      child.local = fromBt(compound.getChildTransform(i)) * child.local;
      out.push_back(child);
    }
  } else {
    out.push_back(primitiveOf(shape, what));
  }
  for (Shape& s : out) s.surface = surface;
  return out;
}

}  // namespace asperity
