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

// A rig for the direction `angle_deg`, the block's centre above `position` (m, on the plate).
// `guided`: the block cannot turn about the plate's normal (the drag test's guide, done by a
// millionfold inertia about its vertical axis); it may still pitch and roll, so that its four
// corners share the load. (Locking every rotation was tried: with an infinite inertia the four
// normal rows no longer couple and the first corner in the solver's order takes the whole load.)
// Throws asperity::Error for an unknown sampler.
Rig makeRig(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
            double angle_deg, bool guided, const Vec2& position);

// Where track `track` (0 .. settings.tracks - 1) starts: beside the others, across the direction
// `angle_deg`, the tracks one repeat of the plate's texture apart in all.
Vec2 trackStart(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                double angle_deg, int track);

// Sums over the block's contacts of one step: normal impulse, and the coefficient resisting the
// block's sliding along s weighted by it (SPEC 1: the bound on the block's friction along -s).
struct ContactLoad {
  double impulse = 0.0;      // sum of lambda_n (N s)
  double weighted_mu = 0.0;  // sum of mu lambda_n
  int contacts = 0;
  double mu_sum = 0.0;  // sum of mu, unweighted
};
ContactLoad blockContactLoad(const World& world, BodyId block, const Vec3& slide);

// The four corners of the block's base, in the world.
std::array<Vec3, 4> bottomCorners(const World& world, BodyId block);

// The angle (degrees) between the block's up axis and the plate's normal.
double blockTiltDeg(const World& world, BodyId block);

}  // namespace asperity::tribo
