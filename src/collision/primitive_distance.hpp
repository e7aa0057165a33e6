// Exact signed distances of the primitives (box, sphere, capsule, cylinder) in double: the
// field side of signed-distance contacts when a concave mesh touches a primitive.
#pragma once

#include "asperity/geometry/shape.hpp"
#include "collision/signed_distance_field.hpp"

namespace asperity::collision_detail {

// True for the shapes primitiveSample handles.
bool hasPrimitiveDistance(ShapeType type);

// Signed distance (< 0 inside) and outward unit gradient at p (shape frame); `triangle` is -1.
SignedDistanceField::Sample primitiveSample(const Shape& shape, const Vec3& p);

// True when p (shape frame) lies certainly farther than `reach` from the primitive, so that
// primitiveSample would give a distance of at least `reach`: a test of a few products that
// lets a query skip the exact distance of most far points with the same outcome.
bool beyondPrimitive(const Shape& shape, const Vec3& p, double reach);

}  // namespace asperity::collision_detail
