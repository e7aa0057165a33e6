// Boxes, capsules and spheres against the side of a cylinder, in double precision: contact
// normals that point radially out of the cylinder's axis, and two points where a flat face, an
// edge or a capsule lies along the side (the ends of the line it touches along), so that a
// chain link on a rod neither tips about one point nor is pushed along the rod by a tilted
// normal.
//
// Rejected alternative: Bullet's convex pair (GJK/EPA, then its manifold of one new point per
// call) on a box against a cylinder: its normals came tilted up to 0.49 along the rod's axis,
// its points stacked at one place, and a chain of flat links tore its joints (1.7 cm) on a
// tilted rod (docs/experiments.md).
//
// How: the distance from a point of the axis to the other shape is convex along the axis; its
// minimum (golden section) gives the deepest cross-section and one point. A box face, a box
// edge or a capsule lying along the side gets instead a point at each end of the line it
// touches along.
// Each point's normal runs from the foot of the shape's point on the axis to that point:
// radial by construction.
#pragma once

#include <vector>

#include "asperity/geometry/shape.hpp"

namespace asperity::collision_detail {

struct CylinderSidePoint {
  int id = 0;          // 0, 1: the ends of a face or capsule along the side; 2: one point
  Vec3 on_cylinder;    // world, on the side surface
  Vec3 on_shape;       // world, on the other shape's surface
  Vec3 normal;         // world, radial, out of the cylinder toward the shape
  double depth = 0.0;  // m, > 0 when they overlap
};

// Whether this path serves the pair's shape types (a cylinder and a box, capsule or sphere).
bool isCylinderSideShape(ShapeType type);

// Contact points of `shape` (at `shape_world`) against the side of `cylinder` (at
// `cylinder_world`) when its nearest point is closer than `reach` (m); the second end of a
// face along the side may be a gap (depth < 0). Returns false where the side is not what they
// touch (the shape is nearest a cap, or the axis runs through it): the caller then uses the
// general narrowphase. True with no points means they are apart.
bool cylinderSidePoints(const Shape& cylinder, const Transform& cylinder_world, const Shape& shape,
                        const Transform& shape_world, double reach,
                        std::vector<CylinderSidePoint>& out);

}  // namespace asperity::collision_detail
