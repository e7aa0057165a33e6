// The texture's +u axis of a body's surface at a contact, in world.
#include "dynamics/texture_axis.hpp"

#include "asperity/geometry/shape_mesh.hpp"

namespace asperity {

std::optional<Vec3> textureAxisWorld(const Body& body, int shape, int feature, const Vec3& point) {
  if (shape < 0 || static_cast<size_t>(shape) >= body.shapes.size()) return std::nullopt;
  const Shape& s = body.shapes[static_cast<size_t>(shape)];
  // The point in the shape frame, the mapping there, its T back to world.
  const Transform shape_world = body.pose * s.local;
  const SurfaceFrame frame = surfaceFrameAt(s, feature, shape_world.applyInverse(point));
  const Vec3 axis = shape_world.rotation * frame.t;
  if (!(axis.squaredNorm() > 1e-24) || !axis.allFinite()) return std::nullopt;
  return axis.normalized();
}

}  // namespace asperity
