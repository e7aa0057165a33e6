// The tilt table (tribometer.hpp): the plate tilts about the axis perpendicular to s until the
// block has slid more than the threshold (every corner of its base has moved that far: tipping
// about an edge leaves that edge in place); mu_s = tan of that tilt.
//
// The tilt is applied to gravity, g (sin(theta) s - cos(theta) z), with the plate fixed: in the
// plate's frame the same load, without the plate's angular velocity terms (below 1e-4 g at the
// rates used), and the textures and contact frames stay put.
//
// A continuous ramp overshoots: the block must gain speed to slide the threshold, which at the
// rate w takes a tilt of about w^(2/3) (6 x / g)^(1/3) beyond the true angle (x = threshold;
// 0.11 deg at the default 0.2 deg/s and 1 mm). A slow ramp from 0 to 45 degrees would take minutes
// of simulated time, so the tilt is ramped in passes: fast from 0, then each slower pass restarts a
// fresh world a little below where the last one slid (twice its overshoot), down to the slow rate.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "asperity/error.hpp"
#include "asperity/tribometer/tribometer.hpp"
#include "tribometer/rig.hpp"

namespace asperity {

namespace {

constexpr double kFastRateDeg = 30.0;  // deg/s of the first pass
constexpr double kRateFactor = 6.0;    // each pass this much slower, down to the slow rate

// How one pass ended.
struct TiltPass {
  double angle_deg = 0.0;  // tilt when it ended
  bool slid = false;
  bool toppled = false;
};

double toRad(double deg) {
  return deg * kPi / 180.0;
}

// The overshoot of a ramp at `rate_deg` deg/s (degrees; see the header comment).
double overshootDeg(double rate_deg, const TribometerSettings& settings) {
  const double w = toRad(rate_deg);
  const double rad =
      std::pow(w, 2.0 / 3.0) * std::cbrt(6.0 * settings.slide_threshold / settings.gravity);
  return rad * 180.0 / kPi;
}

// Gravity with the plate tilted by `deg` about the axis perpendicular to s (downhill = s).
Vec3 tiltedGravity(const TribometerSettings& settings, const Vec3& slide, double deg) {
  const double a = toRad(deg);
  return settings.gravity * (std::sin(a) * slide - std::cos(a) * Vec3::UnitZ());
}

// One ramp from `start_deg` at `rate_deg` until the block slides, topples or the tilt reaches
// `end_deg`, in a fresh world.
TiltPass rampTilt(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                  double angle_deg, int track, double start_deg, double rate_deg, double end_deg) {
  tribo::Rig rig = tribo::makeRig(surfaces, settings, angle_deg, false,
                                  tribo::trackStart(surfaces, settings, angle_deg, track));
  World& world = *rig.world;
  const std::array<Vec3, 4> start = tribo::bottomCorners(world, rig.block);
  TiltPass pass;
  for (int64_t i = 0;; ++i) {
    // The tilt of this step, then the step, then what the block did.
    pass.angle_deg = std::min(end_deg, start_deg + rate_deg * settings.dt * static_cast<double>(i));
    world.settings().gravity = tiltedGravity(settings, rig.slide, pass.angle_deg);
    world.step();
    // Sliding moves every corner of the base; tipping leaves the edge it turns about in place.
    const std::array<Vec3, 4> now = tribo::bottomCorners(world, rig.block);
    double least = std::numeric_limits<double>::infinity();
    for (size_t c = 0; c < 4; ++c)
      least = std::min(least, std::hypot(now[c].x() - start[c].x(), now[c].y() - start[c].y()));
    pass.slid = least > settings.slide_threshold;
    pass.toppled = tribo::blockTiltDeg(world, rig.block) > settings.topple_deg;
    if (pass.slid || pass.toppled || pass.angle_deg >= end_deg) return pass;
  }
}

// The passes of one track, down to the slow rate; the last pass's result.
TiltPass tiltTrack(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                   double angle_deg, int track) {
  const auto ramp = [&](double start, double rate) {
    return rampTilt(surfaces, settings, angle_deg, track, start, rate, settings.tilt_max_deg);
  };
  // First pass: fast, from level to the largest tilt.
  double rate = std::max(kFastRateDeg, settings.tilt_rate_deg);
  TiltPass pass = ramp(0.0, rate);
  // Slower passes, each from below where the last one slid or toppled (again lower if it
  // slid at once): the fast ramp overshoots both limits, so either may come first there.
  while ((pass.slid || pass.toppled) && rate > settings.tilt_rate_deg) {
    const double margin = 2.0 * overshootDeg(rate, settings) + 0.2;
    rate = std::max(rate / kRateFactor, settings.tilt_rate_deg);
    double start = std::max(0.0, pass.angle_deg - margin);
    pass = ramp(start, rate);
    while ((pass.slid || pass.toppled) && start > 0.0 && pass.angle_deg < start + 0.25 * margin) {
      start = std::max(0.0, start - margin);
      pass = ramp(start, rate);
    }
  }
  return pass;
}

}  // namespace

TiltResult runTiltTest(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                       double angle_deg) {
  validateTribometerSettings(settings);
  // Every track's slow pass: mu_s is the mean of tan(tilt) when all of them slid.
  TiltResult result;
  double tan_sum = 0.0;
  bool all_slid = true;
  for (int track = 0; track < settings.tracks; ++track) {
    const TiltPass pass = tiltTrack(surfaces, settings, angle_deg, track);
    result.toppled = result.toppled || pass.toppled;
    all_slid = all_slid && pass.slid && !pass.toppled;
    tan_sum += std::tan(toRad(pass.angle_deg));
    result.angle_deg = std::max(result.angle_deg, pass.angle_deg);
  }
  if (!all_slid) return result;
  result.mu_s = tan_sum / settings.tracks;
  result.angle_deg = std::atan(*result.mu_s) * 180.0 / kPi;
  return result;
}

}  // namespace asperity
