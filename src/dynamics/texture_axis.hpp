// Where a body's texture points at a contact: the texture's +u axis in world (the analytic or
// mesh mapping of geometry/shape_mesh.hpp, texture_rotation included). Used by frame mode
// Texture (SPEC 5) and by the cone provider to turn texture-frame cones into contact frames.
#pragma once

#include <optional>

#include "asperity/dynamics/body.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

// The +u axis (world, unit, not projected on any plane) of shape `shape` of `body` at the
// world point `point`; `feature` is the collision stage's feature id (box face, triangle).
// Empty when the shape index is out of range or the mapping is degenerate there.
std::optional<Vec3> textureAxisWorld(const Body& body, int shape, int feature, const Vec3& point);

}  // namespace asperity
