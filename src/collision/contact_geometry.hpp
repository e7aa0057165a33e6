// Contact geometry finished in double precision: witness points snapped onto the exact
// primitive surfaces (Bullet works in floats and rounds shapes by their margins), the plane's
// exact normal, phi from the witness points, and box face features.
#pragma once

#include "asperity/collision/contact.hpp"
#include "asperity/geometry/shape.hpp"

namespace asperity::collision_detail {

// The closest point on the exact surface of a primitive to `witness` (world), given the
// outward surface normal there (world). Hulls and meshes return `witness` unchanged.
Vec3 snapToSurface(const Shape& shape, const Transform& shape_world, const Vec3& witness,
                   const Vec3& outward);

// Face index of a box whose outward normal is `outward` (world): 2 * axis + (negative ? 1 : 0).
int boxFace(const Transform& shape_world, const Vec3& outward);

// Whether two boxes (half extents, world axes as matrix columns, centres) are apart by more
// than `gap` along one of their six face normals: a separating axis, so that no narrowphase
// finds a contact.
bool boxesApart(const Vec3& half_a, const Mat3& axes_a, const Vec3& centre_a, const Vec3& half_b,
                const Mat3& axes_b, const Vec3& centre_b, double gap);

// Finishes a contact whose witness points and normal (B to A) are set: snaps the witness
// points, uses a plane's exact normal, recomputes point and phi (SPEC 1), sets box faces.
void finishContact(Contact& c, const Shape& shape_a, const Transform& world_a, const Shape& shape_b,
                   const Transform& world_b);

}  // namespace asperity::collision_detail
