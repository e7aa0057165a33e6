// The last stage of a step (docs/step.md): positions from velocities (semi-implicit Euler),
// orientations by the exact rotation of the angular velocity over dt, renormalised.
#pragma once

#include <span>

#include "asperity/dynamics/body.hpp"

namespace asperity {

class ContactSolver;
class ThreadPool;

// Moves every kinematic and dynamic body over dt by its velocities; dynamic bodies also by the
// solver's split-impulse pseudo-velocities (then forgotten). Bodies move independently, so
// any split over the pool's threads gives the same bits.
void integratePoses(std::span<Body> bodies, const ContactSolver& solver, double dt,
                    const ThreadPool& pool);

}  // namespace asperity
