// Stage 1 of a step (docs/step.md): gravity, springs and loads become velocity changes (the
// velocity half of semi-implicit Euler), with the gyroscopic term integrated implicitly.
#pragma once

#include <span>

#include "asperity/dynamics/body.hpp"
#include "asperity/dynamics/driver.hpp"

namespace asperity {

// Sets each body's force and torque accumulators from the springs and the loads active at
// `time`, fires the impulses due in [time, time + dt), and adds dt (gravity + F / m) and
// dt I^-1 tau to the dynamic bodies' velocities.
void applyDrivers(std::span<Body> bodies, std::span<const SpringDesc> springs,
                  std::span<const LoadDesc> loads, const Vec3& gravity, double time, double dt);

}  // namespace asperity
