// The virtual tribometer's front: settings checked, and the runs of every direction side by
// side on a thread pool (tribometer.hpp).
#include "asperity/tribometer/tribometer.hpp"

#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/world/world.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

// Throws `tribometer: NAME must be in [lo, hi], got x` unless lo <= value <= hi (NaN fails).
void checkRange(const char* name, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    throw Error(std::string("tribometer: ") + name + " must be in [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "], got " + std::to_string(value));
}

}  // namespace

void validateTribometerSettings(const TribometerSettings& s) {
  // Counts, geometry and load, then the drive and the tilt.
  if (s.directions < 1 || s.directions > 360)
    throw Error("tribometer: directions must be in [1, 360], got " + std::to_string(s.directions));
  if (s.tracks < 1 || s.tracks > 64)
    throw Error("tribometer: tracks must be in [1, 64], got " + std::to_string(s.tracks));
  checkRange("block_size (m)", s.block_size, 1e-3, 10.0);
  checkRange("block_height (m)", s.block_height, 1e-3, 10.0);
  checkRange("load (N)", s.load, 1e-3, 1e6);
  checkRange("gravity (m/s^2)", s.gravity, 0.1, 1e3);
  checkRange("dt (s)", s.dt, 1e-5, 0.1);
  if (s.iterations < 1 || s.iterations > 10000)
    throw Error("tribometer: iterations must be in [1, 10000], got " +
                std::to_string(s.iterations));
  checkRange("drag_speed (m/s)", s.drag_speed, 1e-4, 10.0);
  checkRange("drag_settle (s)", s.drag_settle, 0.0, 100.0);
  checkRange("drag_window (s)", s.drag_window, s.dt, 100.0);
  checkRange("spring_frequency (Hz)", s.spring_frequency, 0.01, 0.25 / s.dt);
  checkRange("tilt_rate_deg (deg/s)", s.tilt_rate_deg, 1e-3, 90.0);
  checkRange("tilt_max_deg", s.tilt_max_deg, 0.0, 89.0);
  checkRange("slide_threshold (m)", s.slide_threshold, 1e-6, 1.0);
  checkRange("topple_deg", s.topple_deg, 0.1, 90.0);
  if (s.threads < 0 || s.threads > kMaxThreads)
    throw Error("tribometer: threads must be in [0, " + std::to_string(kMaxThreads) + "], got " +
                std::to_string(s.threads));
  if (s.sampler != "cpu" && s.sampler != "cone" && s.sampler != "constant")
    throw Error("tribometer: sampler \"" + s.sampler +
                "\" cannot run in the tribometer (available: constant, cone, cpu)");
}

TribometerResult runTribometer(const TribometerSurfaces& surfaces,
                               const TribometerSettings& settings) {
  validateTribometerSettings(settings);
  const int n = settings.directions;
  TribometerResult result;
  result.directions.resize(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) result.directions[static_cast<size_t>(k)].angle_deg = 360.0 * k / n;
  // Jobs: the tilt runs (the longer ones) first, then the drag runs, each its own world.
  const size_t tilts = settings.tilt ? static_cast<size_t>(n) : 0;
  const size_t drags = settings.drag ? static_cast<size_t>(n) : 0;
  const ThreadPool pool(settings.threads);
  pool.forEach(tilts + drags, 1, [&](size_t job) {
    TribometerDirection& d = result.directions[job < tilts ? job : job - tilts];
    if (job < tilts) {
      const TiltResult tilt = runTiltTest(surfaces, settings, d.angle_deg);
      d.mu_s = tilt.mu_s;
      d.toppled = tilt.toppled;
    } else {
      const DragResult drag = runDragTest(surfaces, settings, d.angle_deg);
      d.mu_k = drag.mu_k;
      d.mu_model = drag.mu_model;
    }
  });
  return result;
}

}  // namespace asperity
