// Conversion of asperity shapes to Bullet collision shapes (single precision), with collision
// margins and contact thresholds scaled to each shape's size so that millimetre parts and
// metre boxes both work.
#pragma once

#include <btBulletCollisionCommon.h>

#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>

#include <array>
#include <map>
#include <memory>
#include <span>
#include <vector>

#include "asperity/dynamics/body.hpp"
#include "asperity/geometry/shape.hpp"

namespace asperity::collision_detail {

inline btVector3 toBt(const Vec3& v) {
  return {static_cast<btScalar>(v.x()), static_cast<btScalar>(v.y()), static_cast<btScalar>(v.z())};
}
inline Vec3 fromBt(const btVector3& v) {
  return {static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z())};
}
btTransform toBt(const Transform& t);

// Bullet's GJK and manifolds carry absolute tolerances tuned for shapes of decimetres to
// metres, so a scene of millimetre parts fails to touch. Bullet therefore works in scaled
// units: lengths times this power of two (exact in floats), chosen so that the smallest
// dynamic shape is at least 0.2 units across; 1 for scenes of ordinary objects.
double bulletScale(std::span<const Body> bodies);
// The shape with every length (extents, radii, offsets, local position, mesh) times `scale`.
Shape scaledShape(const Shape& shape, double scale);
// A transform with its translation times `scale`, as Bullet's single precision.
btTransform toBt(const Transform& t, double scale);

// The smallest extent of a shape (m): the size its margin and thresholds follow.
double shapeSize(const Shape& shape);
// Radius of the smallest sphere about the shape's frame origin holding the shape (m; 0 for a
// plane): how far a point of it can be from the origin the shape turns about.
double boundingRadius(const Shape& shape);
// Bullet's collision margin for a shape of this size: min(0.04, 0.02 * size) (m).
double marginFor(double size);

// A Bullet shape and the storage it points into (triangle arrays for meshes).
struct BulletShape {
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btTriangleIndexVertexArray> mesh_interface;
  std::vector<float> vertices;  // x, y, z per vertex, referenced by mesh_interface
  std::vector<int> indices;     // three per triangle
};

// Boxes' polyhedral features (Bullet's separating-axis data) by half extents and margin: a
// thousand equal boxes compute them once and copy them (the copy is the same numbers), which
// took four fifths of building a 1000-cube pile's collision world.
class BoxPolyhedra {
 public:
  void apply(btBoxShape& box);

 private:
  std::map<std::array<btScalar, 4>, std::unique_ptr<btConvexPolyhedron>> made_;
};

// Builds the Bullet shape of `shape` for a body of this type (boxes' features from `boxes` when
// given). Throws Error for shapes that cannot be built (a plane on a dynamic body, a mesh
// without triangles, a degenerate hull).
BulletShape makeBulletShape(const Shape& shape, BodyType body_type, BoxPolyhedra* boxes = nullptr);

}  // namespace asperity::collision_detail
