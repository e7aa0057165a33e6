// The tribometer's rig: plate, block, settings and providers of one run (rig.hpp).
#include "tribometer/rig.hpp"

#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "asperity/scene/friction_providers.hpp"
#include "asperity/world/builders.hpp"

namespace asperity::tribo {

namespace {

// World settings of a run: t along s (frame mode World), the box limit with its 4 directions.
WorldSettings rigSettings(const TribometerSettings& settings, const Vec3& slide) {
  WorldSettings w;
  w.dt = settings.dt;
  w.iterations = settings.iterations;
  w.gravity = Vec3(0.0, 0.0, -settings.gravity);
  w.limit_surface = LimitSurfaceKind::Box;
  w.frame.mode = FrameMode::World;
  w.frame.world_axis = slide;
  w.frame.fallback_axis = Vec3::UnitZ().cross(slide);
  w.friction = settings.friction;
  w.friction.directions = 4;
  w.threads = 1;
  return w;
}

}  // namespace

Rig makeRig(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
            double angle_deg, bool guided, const Vec2& position) {
  Rig rig;
  const double a = angle_deg * kPi / 180.0;
  rig.slide = Vec3(std::cos(a), std::sin(a), 0.0);
  rig.world = std::make_unique<World>(rigSettings(settings, rig.slide));
  rig.world->setFrictionProvider(FrictionProviders::builtIn().make(settings.sampler));
  // The plate: a static plane through the origin, surface B facing +z.
  BodyDesc plate = groundPlaneDesc();
  plate.name = "plate";
  plate.shapes[0].surface = surfaces.plate;
  rig.world->createBody(plate);
  // The block: a box resting on the plate, its weight the normal load, surface A underneath.
  const Vec3 half(0.5 * settings.block_size, 0.5 * settings.block_size,
                  0.5 * settings.block_height);
  // Set 0.1 mm into the plate: touching at the first step, rather than dropping onto it then.
  const Vec3 start(position.x(), position.y(), half.z() - 1e-4);
  BodyDesc block = boxDesc("block", half, {start, Quat::Identity()});
  block.shapes[0].surface = surfaces.block;
  rig.mass = settings.load / settings.gravity;
  block.mass_override = rig.mass;
  rig.block = rig.world->createBody(block);
  // The guide of the drag test: the box's principal z is the world's z, so a millionfold
  // inertia about it keeps the block from turning on the plate (0 would break the gyroscopic
  // step, which inverts the inertia).
  if (guided) rig.world->body(rig.block).inverse_inertia_local.z() *= 1e-6;
  return rig;
}

Vec2 trackStart(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                double angle_deg, int track) {
  const double a = angle_deg * kPi / 180.0;
  const double across = surfaces.plate.texture_size * (track + 0.5) / settings.tracks;
  return across * Vec2(-std::sin(a), std::cos(a));
}

ContactLoad blockContactLoad(const World& world, BodyId block, const Vec3& slide) {
  ContactLoad load;
  for (const Contact& c : world.contacts()) {
    if (c.body_a != block && c.body_b != block) continue;
    // The block's friction along -s is A's along -s when the block is A, else A's along +s.
    const Vec3 e = c.body_a == block ? Vec3(-slide) : slide;
    const double mu = c.mu.along(std::atan2(e.dot(c.b), e.dot(c.t)));
    load.impulse += c.lambda_n;
    load.weighted_mu += mu * c.lambda_n;
    load.contacts += 1;
    load.mu_sum += mu;
  }
  return load;
}

std::array<Vec3, 4> bottomCorners(const World& world, BodyId block) {
  const Body& body = world.body(block);
  const Vec3& half = body.shapes.front().half_extents;
  const Transform box = body.pose * body.shapes.front().local;
  std::array<Vec3, 4> corners;
  for (int c = 0; c < 4; ++c)
    corners[c] =
        box.apply(Vec3((c & 1 ? 1 : -1) * half.x(), (c & 2 ? 1 : -1) * half.y(), -half.z()));
  return corners;
}

double blockTiltDeg(const World& world, BodyId block) {
  const Vec3 up = world.body(block).pose.rotation * Vec3::UnitZ();
  return std::acos(std::clamp(up.z(), -1.0, 1.0)) * 180.0 / kPi;
}

}  // namespace asperity::tribo
