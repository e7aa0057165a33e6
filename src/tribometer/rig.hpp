// The tribometer's rig (internal): one world per run, a static plate (the plane z = 0, surface B)
// and a block (a box on it, surface A), the contact frame's t along the test direction s and
// the box limit surface, and what every test reads from the contacts.
#pragma once

#include <array>
#include <memory>

#include "asperity/tribometer/tribometer.hpp"
#include "asperity/world/world.hpp"

namespace asperity::tribo {

struct Rig {
  std::unique_ptr<World> world;
  BodyId block = kNoBody;
  Vec3 slide = Vec3::UnitX();  // s: the direction the block is to slide in (unit, horizontal)
  double mass = 0.0;           // kg
};

// A rig for the direction `angle_deg`. `lock_rotation`: the block cannot turn (the drag test's
// guide), done by an infinite inertia. `track` (0 .. settings.tracks - 1) starts the block
// beside the others, across s, so that the tracks cover one repeat of the plate's texture.
// Throws asperity::Error for an unknown sampler.
Rig makeRig(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
            double angle_deg, bool lock_rotation, int track);

// Sums over the block's contacts of one step: normal impulse, and the coefficient resisting the
// block's sliding along s weighted by it (SPEC 1: the bound on the block's friction along -s).
struct ContactLoad {
  double impulse = 0.0;      // sum of lambda_n (N s)
  double weighted_mu = 0.0;  // sum of mu lambda_n
};
ContactLoad blockContactLoad(const World& world, BodyId block, const Vec3& slide);

// The four corners of the block's base, in the world.
std::array<Vec3, 4> bottomCorners(const World& world, BodyId block);

// The angle (degrees) between the block's up axis and the plate's normal.
double blockTiltDeg(const World& world, BodyId block);

}  // namespace asperity::tribo
