// Convex shapes against a plane, in double precision and in one call: the lowest points of
// the shape's exact geometry (box corners, capsule ends, cylinder rims, hull vertices), so a
// box resting flat gets its four corner contacts at once, at any orientation.
//
// Rejected alternative: Bullet's convex-plane algorithm with perturbed support queries finds
// one point per query and perturbs in the convex's local frame, which misses the second end
// of a capsule or the rim of a cylinder lying on its side; its points are also single
// precision.
#pragma once

#include <vector>

#include "asperity/geometry/shape.hpp"

namespace asperity::collision_detail {

struct PlanePoint {
  int id = -1;            // which candidate (corner, end, rim point, vertex): keys the contact
  Vec3 point;             // on the shape's surface (world)
  double distance = 0.0;  // signed distance to the plane, < 0 below it (m)
};

// The plane {x : normal . x = offset} in world coordinates.
struct WorldPlane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;
};
WorldPlane worldPlane(const Shape& plane, const Transform& plane_world);

// Buffers of planePoints, kept by the caller so that a step allocates nothing once they grew.
struct PlaneScratch {
  std::vector<Vec3> candidates;
  std::vector<PlanePoint> near, points;
};

// Candidate points of `shape` (at `world`) closer to the plane than `max_distance`; at most
// four, spread out (the deepest, then the ones spanning the largest area). The result lives in
// `scratch` until its next use.
const std::vector<PlanePoint>& planePoints(const Shape& shape, const Transform& world,
                                           const WorldPlane& plane, double max_distance,
                                           PlaneScratch& scratch);

}  // namespace asperity::collision_detail
