// ODE geoms as ContactFriction objects: the Asperity shape of a geom, and its pose and
// velocity per step.
#pragma once

#include <ode/ode.h>

#include <optional>

#include "asperity/engines/contact_friction.hpp"

namespace asperity::ode_detail {

// The geom's shape in its own frame (ODE's capsules and cylinders run along local z, as
// Asperity's do; a plane is non-placeable, so it lies in world coordinates), or none for a
// class Asperity lacks.
std::optional<Shape> geomShape(dGeomID geom);

// Where the geom is and how it moves (a geom without a body rests; a plane sits at the origin).
ObjectState geomState(dGeomID geom);

}  // namespace asperity::ode_detail
