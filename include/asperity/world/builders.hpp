// Small scene builders shared by tests, benchmarks and examples (z up, metres, kg).
#pragma once

#include <string>
#include <vector>

#include "asperity/dynamics/body.hpp"
#include "asperity/world/world.hpp"

namespace asperity {

// A static plane through `point` with upward normal `normal`.
BodyDesc groundPlaneDesc(const Vec3& normal = Vec3::UnitZ(), const Vec3& point = Vec3::Zero());

// A dynamic box of half extents `half` (m) and density (kg/m^3) at `pose`.
BodyDesc boxDesc(const std::string& name, const Vec3& half, const Transform& pose,
                 double density = 1000.0);

// A column of `count` cubes of side `size` standing on z = 0 at (x, y), touching each other
// (centres at z = size/2 + i size). Returns their ids, bottom first.
std::vector<BodyId> addCubeStack(World& world, const std::string& prefix, double x, double y,
                                 int count, double size, double density = 1000.0);

// A loose pile of `count` cubes on a grid above the ground (layers `per_layer` x `per_layer`,
// spacing 1.5 size, alternate layers offset by half a cube), returned bottom layer first.
std::vector<BodyId> addCubePile(World& world, int count, double size, int per_layer);

}  // namespace asperity
