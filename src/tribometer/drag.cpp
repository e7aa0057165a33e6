// The drag test (tribometer.hpp): the block, guided so that it cannot turn on the plate, pulled
// along s at constant speed by a stiff, critically damped spring attached at the middle of its
// base (in the plane of the friction forces, so that the pull does not tip it); mu_k = mean spring
// force along s / mean normal force of the plate in the measured window (the weight less what the
// spring carries: the block settles a little below the spring's line, which lifts it by about 1 %),
// mu_model = the load-weighted mean coefficient of the block's contacts.
#include <algorithm>
#include <cmath>

#include "asperity/tribometer/tribometer.hpp"
#include "tribometer/rig.hpp"

namespace asperity {

namespace {

// The drive: a spring from the middle of the block's base to a target moving along s from there.
SpringDesc dragSpring(const tribo::Rig& rig, const TribometerSettings& settings) {
  const double omega = 2.0 * kPi * settings.spring_frequency;
  SpringDesc spring;
  spring.name = "drive";
  spring.body = rig.block;
  spring.local_point = Vec3(0.0, 0.0, -0.5 * settings.block_height);
  spring.target = rig.world->body(rig.block).descriptionPose().apply(spring.local_point);
  spring.target_velocity = settings.drag_speed * rig.slide;
  spring.stiffness = rig.mass * omega * omega;
  spring.damping = 2.0 * rig.mass * omega;  // critical
  return spring;
}

// The spring's force on the block now, as the drivers stage will apply it in the next step.
Vec3 springForce(const World& world, const SpringDesc& spring) {
  const Body& body = world.body(spring.body);
  const Vec3 p = body.descriptionPose().apply(spring.local_point);
  return spring.stiffness * (springTarget(spring, world.time()) - p) -
         spring.damping * (body.pointVelocity(p) - spring.target_velocity);
}

// What a window measures, summed over steps (and tracks), each step weighted by the distance
// the block slid in it: the spring's work, the normal force times the distance, and the
// contacts' coefficients on the same weights. A steady slide's time means equal these; where
// the speed wavers, time means would weight the places where the block slows down, and by how
// much depends on the gains, which calibration's unit-gain runs would not reproduce.
struct DragSums {
  double work = 0.0;       // spring force along s times the distance (J)
  double normal = 0.0;     // normal force of the block's contacts times the distance (N m)
  double loaded_mu = 0.0;  // their coefficients times their share of that
  double mean_mu = 0.0;    // the contacts' mean coefficient times the distance
  double distance = 0.0;   // m slid with contacts
  double min_speed = 0.0;  // m/s along s
};

// One drag along track `track`: settle, then measure the window into `sums`.
void dragTrack(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
               double angle_deg, int track, DragSums& sums) {
  tribo::Rig rig = tribo::makeRig(surfaces, settings, angle_deg, true,
                                  tribo::trackStart(surfaces, settings, angle_deg, track));
  World& world = *rig.world;
  const SpringDesc spring = dragSpring(rig, settings);
  world.addSpring(spring);
  // Settle: the spring stretches until the block breaks away and the start-up transient dies.
  const int settle = static_cast<int>(std::ceil(settings.drag_settle / settings.dt - 1e-9));
  const int window = static_cast<int>(std::ceil(settings.drag_window / settings.dt - 1e-9));
  for (int i = 0; i < settle; ++i) world.step();
  // Measure: the force each step applies, the contacts' loads and coefficients, the distance.
  for (int i = 0; i < window; ++i) {
    const double force = springForce(world, spring).dot(rig.slide);
    const double before = world.body(rig.block).pose.position.dot(rig.slide);
    world.step();
    const double moved = world.body(rig.block).pose.position.dot(rig.slide) - before;
    const tribo::ContactLoad load = tribo::blockContactLoad(world, rig.block, rig.slide);
    sums.work += force * moved;
    sums.normal += load.impulse / settings.dt * moved;
    sums.loaded_mu += load.weighted_mu / settings.dt * moved;
    sums.mean_mu += load.contacts > 0 ? load.mu_sum / load.contacts * moved : 0.0;
    sums.distance += load.contacts > 0 ? moved : 0.0;
    const double speed = world.body(rig.block).linear_velocity.dot(rig.slide);
    sums.min_speed = std::min(sums.min_speed, speed);
  }
}

}  // namespace

DragResult runDragTest(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                       double angle_deg) {
  validateTribometerSettings(settings);
  // Every track's sums pooled: forces and impulses add up, the slowest speed is kept.
  DragSums sums;
  sums.min_speed = settings.drag_speed;
  for (int track = 0; track < settings.tracks; ++track)
    dragTrack(surfaces, settings, angle_deg, track, sums);
  // Steady sliding: the block never stopped (below a tenth of the drive's speed) in a window.
  DragResult result;
  result.min_speed = sums.min_speed;
  result.mu_model = sums.distance > 0.0 ? sums.mean_mu / sums.distance : settings.friction.mu0;
  result.mu_loaded = sums.normal > 0.0 ? sums.loaded_mu / sums.normal : settings.friction.mu0;
  if (sums.min_speed > 0.1 * settings.drag_speed && sums.normal > 0.0)
    result.mu_k = sums.work / sums.normal;
  return result;
}

}  // namespace asperity
