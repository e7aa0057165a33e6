// The experiments with mesh bodies: the tumbling bunnies on an inclined plane with an embossed
// logo (Sec. 5.4, Fig. 16), and the M4 nut on a threaded rod (Sec. 5.2, Fig. 13).
#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "experiment_evaluations.hpp"

namespace asperity::experiments {

namespace {

constexpr double kTipDegrees = 45.0;  // rotation that counts as "fallen over" / "tumbling"
// "Near where it lands": the stone bunny travels less than this share of the shorter of the
// other two bunnies' runs (falling over a bunny of 0.12 m moves it by about its height).
constexpr double kStuckShare = 1.0 / 3.0;

// Angle (degrees) of the rotation from the first sample to sample k.
double rotationDegrees(const std::vector<Transform>& poses, size_t k) {
  const Quat q = poses.front().rotation.conjugate() * poses[k].rotation;
  return 2.0 * std::acos(std::min(1.0, std::abs(q.w()))) * 180.0 / kPi;
}

// Where the logo starts along the incline's x axis (shape-local metres): the emboss generator
// centres the logo in each texture tile, which spans u in [0, 1] from the face centre.
double logoStart(const World& world) {
  const BodyId id = world.findBody("incline");
  if (id == kNoBody) throw Error("tumbling bunnies: no body named 'incline'");
  const Surface& s = world.bodyDesc(id).shapes.at(0).surface;
  double scale = 0.8;  // the emboss generator's default logo width (fraction of the tile)
  const auto it = s.source.generator.params.find("scale");
  if (it != s.source.generator.params.end()) scale = std::stod(it->second);
  return s.texture_size * (0.5 - 0.5 * scale);
}

}  // namespace

// Tumbling bunnies: the stone bunny sticks where it lands and falls over; the metal and plastic
// bunnies slide down to the logo and tumble there.
Outcome evaluateBunnies(const Experiment& e, const RunOptions& options) {
  const SceneRun& run = e.scenes.at(0);
  const char* names[3] = {"stone", "metal", "plastic"};
  std::vector<std::string> bodies;
  for (const char* n : names) bodies.push_back(std::string("bunny_") + n);
  Recording rec = simulate(run.file, run.seconds, options, bodies);
  Outcome out;
  out.profiles.push_back(rec.profile);
  const World& world = *rec.world;
  const Transform incline = world.body(world.findBody("incline")).descriptionPose();
  const double logo = logoStart(world);
  Plot travel{"Distance travelled down the incline", "time (s)", "distance (m)", {}};
  Plot turn{"Rotation of the bunnies", "time (s)", "rotation (deg)", {}};
  double dist[3], before[3], after[3];
  for (int i = 0; i < 3; ++i) {
    const auto& p = rec.of(bodies[static_cast<size_t>(i)]);
    // Position along the incline's x (downhill) in its frame; rotation before/after the logo.
    auto along = [&](size_t k) { return incline.applyInverse(p[k].position).x(); };
    before[i] = after[i] = 0.0;
    for (size_t k = 0; k < p.size(); ++k) {
      double& slot = along(k) < logo ? before[i] : after[i];
      slot = std::max(slot, rotationDegrees(p, k));
    }
    dist[i] = along(p.size() - 1) - along(0);
    travel.series.push_back(
        makeSeries(names[i], rec.time, [&](size_t k) { return along(k) - along(0); }));
    turn.series.push_back(
        makeSeries(names[i], rec.time, [&](size_t k) { return rotationDegrees(p, k); }));
    out.measures.push_back({std::string("travel_") + names[i], dist[i], "m"});
    out.measures.push_back({std::string("rotation_before_logo_") + names[i], before[i], "deg"});
    out.measures.push_back({std::string("rotation_on_logo_") + names[i], after[i], "deg"});
  }
  out.plots = {travel, turn};
  // Stone: least travel, fallen over near where it landed. Metal, plastic: reach the logo
  // upright (sliding), then tumble on it.
  const bool stone = dist[0] < kStuckShare * std::min(dist[1], dist[2]) &&
                     std::max(before[0], after[0]) > kTipDegrees;
  const bool metal = before[1] < kTipDegrees && after[1] > kTipDegrees;
  const bool plastic = before[2] < kTipDegrees && after[2] > kTipDegrees;
  out.passed = stone && metal && plastic;
  out.explanation = "travel stone " + num(dist[0]) + " m (rotated " +
                    num(std::max(before[0], after[0])) + " deg), metal " + num(dist[1]) +
                    " m, plastic " + num(dist[2]) + " m; rotation before / on the logo: metal " +
                    num(before[1]) + " / " + num(after[1]) + " deg, plastic " + num(before[2]) +
                    " / " + num(after[2]) + " deg" +
                    (stone ? "" : " (stone did NOT stick and tip)") +
                    (metal && plastic ? "" : " (NOT both sliding then tumbling at the logo)");
  return out;
}

namespace {

constexpr double kPitch = 0.0007;         // m, M4 coarse thread
constexpr double kPitchTolerance = 0.15;  // relative
constexpr double kNoSlide = 0.0001;       // m: the pushed nut moves less than this

// Twist angle (rad) of each sample about `axis`, unwrapped from the first sample.
std::vector<double> twist(const std::vector<Transform>& poses, const Vec3& axis) {
  std::vector<double> out;
  double previous = 0.0, offset = 0.0;
  for (const Transform& pose : poses) {
    const Quat q = poses.front().rotation.conjugate() * pose.rotation;
    const Vec3 local_axis = poses.front().rotation.conjugate() * axis;
    double a = 2.0 * std::atan2(q.vec().dot(local_axis), q.w());
    // Unwrap jumps of 2 pi (4 pi for the quaternion's double cover).
    while (a + offset - previous > kPi) offset -= 2.0 * kPi;
    while (a + offset - previous < -kPi) offset += 2.0 * kPi;
    previous = a + offset;
    out.push_back(previous);
  }
  return out;
}

}  // namespace

// Nut and bolt: the thread lives only in the normal maps and the contact frames follow it; a
// torque about the rod screws the nut along at one pitch per turn, a push along the rod does not
// move it.
Outcome evaluateNutBolt(const Experiment& e, const RunOptions& options) {
  Outcome out;
  Plot turn{"Nut under a torque about the rod", "turns", "advance along the rod (mm)", {}};
  Plot push{"Nut under a push along the rod", "time (s)", "displacement (mm)", {}};
  double per_turn = 0.0, turns = 0.0, pushed = 0.0;
  for (const SceneRun& run : e.scenes) {
    const bool pushing = run.file.find("push") != std::string::npos;
    Recording rec = simulate(run.file, run.seconds, options, {"nut"});
    out.profiles.push_back(rec.profile);
    const World& world = *rec.world;
    const Body& bolt = world.body(world.findBody("bolt"));
    const Vec3 axis = bolt.pose.rotation * Vec3::UnitZ();
    const auto& p = rec.of("nut");
    auto advance = [&](size_t k) { return (p[k].position - p[0].position).dot(axis); };
    if (pushing) {
      push.series.push_back(
          makeSeries("pushed", rec.time, [&](size_t k) { return 1e3 * advance(k); }));
      for (size_t k = 0; k < p.size(); ++k) pushed = std::max(pushed, std::abs(advance(k)));
      continue;
    }
    const std::vector<double> angle = twist(p, axis);
    Series s{"torque", {}, {}};
    for (size_t k = 0; k < p.size(); ++k) {
      s.x.push_back(angle[k] / (2.0 * kPi));
      s.y.push_back(1e3 * advance(k));
    }
    turn.series.push_back(s);
    turns = angle.back() / (2.0 * kPi);
    per_turn = std::abs(turns) > 1e-9 ? advance(p.size() - 1) / turns : 0.0;
  }
  out.plots = {turn, push};
  out.measures = {{"turns", turns, "turn"},
                  {"advance_per_turn", per_turn, "m"},
                  {"pushed_displacement", pushed, "m"}};
  // One pitch per turn (either hand), at least one turn; the push does not slide the nut.
  const bool screws =
      std::abs(turns) >= 1.0 && std::abs(std::abs(per_turn) - kPitch) <= kPitchTolerance * kPitch;
  const bool holds = pushed < kNoSlide;
  out.passed = screws && holds;
  out.explanation = "torque: " + num(turns) + " turns, " + num(per_turn * 1e3) +
                    " mm per turn (pitch 0.7 mm)" + (screws ? "" : " (NOT a screw motion)") +
                    "; push: moved " + num(pushed * 1e3) + " mm" + (holds ? " (held)" : " (slid)");
  return out;
}

}  // namespace asperity::experiments
