// Exact signed distances of the primitives (box, sphere, capsule, cylinder) in double: the
// field side of signed-distance contacts when a concave mesh touches a primitive.
#pragma once

#include "asperity/geometry/shape.hpp"
#include "collision/signed_distance_field.hpp"
#include "math/lanes.hpp"

namespace asperity::collision_detail {

// True for the shapes primitiveSample handles.
bool hasPrimitiveDistance(ShapeType type);

// Signed distance (< 0 inside) and outward unit gradient at p (shape frame); `triangle` is -1.
SignedDistanceField::Sample primitiveSample(const Shape& shape, const Vec3& p);

// Whether points (shape frame) lie certainly farther than `reach` from the primitive, so that
// primitiveSample would give a distance of at least `reach`: a test of a few products that
// lets a query skip the exact distance of most far points with the same outcome. Two points
// at once, one per lane, or one; the bounds are worked out once.
class PrimitiveReach {
 public:
  PrimitiveReach() = default;  // nothing is beyond
  PrimitiveReach(const Shape& shape, double reach);

  lanes::Mask beyond(const lanes::Lanes3& p) const {
    switch (type_) {
      case ShapeType::Sphere:
        return radius2_ < p.x * p.x + p.y * p.y + p.z * p.z;
      case ShapeType::Capsule: {
        const lanes::Lanes dz = p.z - lanes::clamp(p.z, -half_height_, half_height_);
        return radius2_ < p.x * p.x + p.y * p.y + dz * dz;
      }
      case ShapeType::Cylinder:
        return (radius2_ < p.x * p.x + p.y * p.y) | (z_limit_ < lanes::abs(p.z));
      default:
        return lanes::none();
    }
  }
  bool beyond(const Vec3& p) const { return lanes::any(beyond(lanes::splat(p))); }

 private:
  ShapeType type_ = ShapeType::Box;  // a box (or none): its bounds already hold its points
  lanes::Lanes radius2_{}, z_limit_{};
  double half_height_ = 0.0;
};

}  // namespace asperity::collision_detail
