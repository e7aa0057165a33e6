// Chain bolas (Sec. 5.1, Figs. 10 and 11): a chain thrown at a rough and at a smooth rod.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "experiment_support.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity::experiments {

namespace {

const PaperRow kBolasRoughRow = paperRow(1, 1, 0.1, 0.02, 1, 45, 41.6, 1.4, 6.5);
const PaperRow kBolasSmoothRow = paperRow(1, 1, 0.1, 0.02, 1, 23, 34.1, 0.7, 3.2);

// Heights of the chain's centre of mass above the ground after the run: held on the rod (which
// is 1.5 m up) above the first, fallen to the ground below the second.
constexpr double kHeldHeight = 0.5;    // m
constexpr double kFallenHeight = 0.2;  // m

// A throw changed from the scene's (issue's robustness check): speed times `speed`, the whole
// chain moved `rise` m up and `along` m along the rod, its velocities turned `heading_deg`
// about the vertical.
struct Jitter {
  double speed;
  double rise;
  double along;
  double heading_deg;
};

// Ten throws around the scene's: each column takes ten evenly spaced levels (speed x0.85 to
// x1.15, shifts -10 to 10 mm, heading -5 to 5 degrees) in a fixed shuffled order (a Latin
// hypercube), the same for both rods.
constexpr std::array<Jitter, 10> kJitters{{{0.850, -0.0056, 0.0078, -0.56},
                                           {1.050, 0.0078, 0.0033, -1.67},
                                           {0.917, -0.0078, -0.0011, 2.78},
                                           {0.950, 0.0011, -0.0033, 3.89},
                                           {1.117, 0.0033, -0.0078, -5.00},
                                           {0.983, -0.0011, -0.0056, -2.78},
                                           {1.083, -0.0100, 0.0011, 5.00},
                                           {1.150, -0.0033, 0.0100, -3.89},
                                           {1.017, 0.0056, -0.0100, 1.67},
                                           {0.883, 0.0100, 0.0056, 0.56}}};
// Of the ten, the rough rod must hold at least this many and the smooth rod at most kMaxSmooth.
constexpr int kMinRoughHeld = 8;
constexpr int kMaxSmoothHeld = 2;
// The chain's final centre-of-mass height for each jittered throw (m).
using Heights = std::array<double, kJitters.size()>;

// The rod's axis in the world: its cylinder's local z.
Vec3 rodAxis(const SceneDesc& scene, const std::string& file) {
  for (const BodyDesc& b : scene.bodies)
    if (b.name == "rod" && !b.shapes.empty())
      return b.pose.rotation * (b.shapes.front().local.rotation * Vec3::UnitZ());
  throw Error(file + ": experiment needs a body named 'rod' with a shape");
}

void applyJitter(SceneDesc& scene, const Jitter& j, const Vec3& axis) {
  const Quat turn(Eigen::AngleAxisd(j.heading_deg * kPi / 180, Vec3::UnitZ()));
  for (BodyDesc& b : scene.bodies) {
    if (b.type != BodyType::Dynamic) continue;
    b.pose.position += j.rise * Vec3::UnitZ() + j.along * axis;
    b.linear_velocity = j.speed * (turn * b.linear_velocity);
    b.angular_velocity = j.speed * (turn * b.angular_velocity);
  }
}

// Mass-weighted centre of the recorded bodies at sample k.
Vec3 centreOfMass(const Recording& rec, size_t k) {
  Vec3 sum = Vec3::Zero();
  double mass = 0.0;
  for (size_t i = 0; i < rec.bodies.size(); ++i) {
    const Body& b = rec.world->body(rec.world->findBody(rec.bodies[i]));
    const double m = b.inverse_mass > 0.0 ? 1.0 / b.inverse_mass : 0.0;
    sum += m * rec.poses[i][k].position;
    mass += m;
  }
  return mass > 0.0 ? Vec3(sum / mass) : Vec3(Vec3::Zero());
}

// Final heights of the chain's centre of mass for the ten jittered throws of one scene, run
// side by side on the run's threads (every core unless it says; each world is independent, so
// the numbers do not depend on the threads).
Heights jitteredHeights(const SceneRun& run, const RunOptions& options) {
  const SceneDesc scene = loadExperimentScene(run.file, options);
  const Vec3 axis = rodAxis(scene, run.file);
  RunOptions quiet = options;
  quiet.record_every = 1 << 30;  // only the first and the last state
  Heights heights{};
  const ThreadPool pool(options.threads.value_or(0));
  pool.forEach(kJitters.size(), 1, [&](size_t i) {
    SceneDesc jittered = scene;
    applyJitter(jittered, kJitters[i], axis);
    const Recording rec = simulate(jittered, run.file, run.seconds, quiet);
    heights[i] = centreOfMass(rec, rec.time.size() - 1).z();
  });
  return heights;
}

int heldCount(const Heights& heights) {
  return static_cast<int>(
      std::count_if(heights.begin(), heights.end(), [](double z) { return z > kHeldHeight; }));
}

// The ten throws, one row each, with both rods' outcomes.
Table jitterTable(const Heights& rough, const Heights& smooth) {
  Table t{"Ten jittered throws: the chain's centre of mass above the ground after 3 s",
          {"throw", "speed (x scene)", "rise (mm)", "along the rod (mm)", "heading (deg)",
           "rough rod (m)", "smooth rod (m)"},
          {}};
  auto outcome = [](double z) { return num(z) + (z > kHeldHeight ? " held" : " fell"); };
  for (size_t i = 0; i < kJitters.size(); ++i) {
    const Jitter& j = kJitters[i];
    t.rows.push_back({std::to_string(i + 1), num(j.speed), num(j.rise * 1e3), num(j.along * 1e3),
                      num(j.heading_deg), outcome(rough[i]), outcome(smooth[i])});
  }
  return t;
}

// Chain bolas: the same throw at each rod; on the rough rod (Ra 1 mm) the chain wraps and
// stays up, off the smooth one (Ra 0.01 mm) it slips to the ground. The height of the chain's
// centre of mass over time.
Outcome evaluateChainBolas(const Experiment& e, const RunOptions& options) {
  Outcome out;
  out.passed = true;
  Plot height{"Chain's centre of mass: height above the ground", "time (s)", "z (m)", {}};
  for (const SceneRun& run : e.scenes) {
    const bool rough = run.file.find("rough") != std::string::npos;
    const std::string label = rough ? "rough" : "smooth";
    // Every dynamic body is the chain's: links and weights.
    Recording rec = simulate(run.file, run.seconds, options);
    out.profiles.push_back(rec.profile);
    height.series.push_back(
        makeSeries(label, rec.time, [&](size_t k) { return centreOfMass(rec, k).z(); }));
    const double z = centreOfMass(rec, rec.time.size() - 1).z();
    out.measures.push_back({"height_" + label, z, "m"});
    const bool ok = rough ? z > kHeldHeight : z < kFallenHeight;
    out.passed = out.passed && ok;
    out.explanation += (out.explanation.empty() ? "" : "; ") + label + " rod: centre of mass " +
                       num(z) + " m above the ground after " + num(rec.time.back()) + " s" +
                       (ok ? (rough ? " (held on the rod)" : " (slipped off)")
                           : (rough ? " (NOT held)" : " (did NOT slip off)"));
  }
  // The same ten jittered throws at both rods.
  const auto rough = jitteredHeights(e.scenes[0], options);
  const auto smooth = jitteredHeights(e.scenes[1], options);
  const int rough_held = heldCount(rough), smooth_held = heldCount(smooth);
  out.tables.push_back(jitterTable(rough, smooth));
  out.measures.push_back({"jittered_held_rough", double(rough_held), "of 10"});
  out.measures.push_back({"jittered_held_smooth", double(smooth_held), "of 10"});
  const bool robust = rough_held >= kMinRoughHeld && smooth_held <= kMaxSmoothHeld;
  out.passed = out.passed && robust;
  out.explanation += "; ten jittered throws: held on the rough rod in " +
                     std::to_string(rough_held) + ", on the smooth rod in " +
                     std::to_string(smooth_held) + (robust ? "" : " (NOT robust)");
  // The same chain at rest over each rod (1.44:1): the grip the throw relies on, which the
  // rods do show. Reported beside the thrown outcome; the criterion stays the thrown one.
  Plot drop{"Draped chain: drop of the heavy ball", "time (s)", "drop (m)", {}};
  for (const char* label : {"rough", "smooth"}) {
    const Recording rec =
        simulate(std::string("chain_draped_") + label + ".json", 3.0, options, {"ball_0"});
    const std::vector<Transform>& heavy = rec.of("ball_0");
    auto dropAt = [&](size_t k) { return heavy.front().position.z() - heavy[k].position.z(); };
    drop.series.push_back(makeSeries(label, rec.time, dropAt));
    const double d = dropAt(rec.time.size() - 1);
    out.measures.push_back({std::string("draped_drop_") + label, d, "m"});
    out.explanation += std::string("; draped over the ") + label + " rod, the heavy ball drops " +
                       num(d) + " m in 3 s";
  }
  out.plots = {height, drop};
  return out;
}

}  // namespace

Experiment chainBolas() {
  return {"chain_bolas",
          "Chain bolas",
          "Sec. 5.1, Figs. 10 and 11: a chain bolas thrown at a rod grips and wraps around "
          "the rough rod (Ra 1 mm) and cannot get a grip on the smooth one (Ra 0.01 mm).",
          "after 3 s the chain's centre of mass is more than 0.5 m above the ground with the "
          "rough rod (held on it, 1.5 m up) and less than 0.2 m above it with the smooth rod",
          // Frames at 0.8 s: wound on the rough rod, sliding off the smooth rod's lower end.
          {{"chain_bolas_rough.json", 3.0, kBolasRoughRow, 0.8},
           {"chain_bolas_smooth.json", 3.0, kBolasSmoothRow, 0.8}},
          evaluateChainBolas};
}

}  // namespace asperity::experiments
