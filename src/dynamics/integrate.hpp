// The last stage of a step (docs/step.md): positions from velocities (semi-implicit Euler),
// orientations by the exact rotation of the angular velocity over dt, renormalised.
#pragma once

#include <span>

#include "asperity/dynamics/body.hpp"

namespace asperity {

class ThreadPool;

// Moves every kinematic and dynamic body over dt by its velocities; dynamic bodies also by the
// solve's split-impulse pseudo-velocities (indexed by BodyId; then forgotten). Bodies move
// independently, so any split over the pool's threads (null: the calling thread) gives the
// same bits.
void integratePoses(std::span<Body> bodies, std::span<const Vec3> pseudo_linear,
                    std::span<const Vec3> pseudo_angular, double dt, const ThreadPool* pool);

}  // namespace asperity
