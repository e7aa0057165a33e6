// Tumbling bunnies (Sec. 5.4, Fig. 16): bunnies launched down an incline with an embossed logo.
#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "experiment_support.hpp"

namespace asperity::experiments {

namespace {

const PaperRow kBunniesRow = paperRow(4, 1, 0.1, 0.02, 10, 10, 3.5, 0.13, 1.7);

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
  const Surface& s = world.body(id).shapes.at(0).surface;
  double scale = 0.8;  // the emboss generator's default logo width (fraction of the tile)
  const auto it = s.source.generator.params.find("scale");
  if (it != s.source.generator.params.end()) scale = std::stod(it->second);
  return s.texture_size * (0.5 - 0.5 * scale);
}

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

}  // namespace

Experiment tumblingBunnies() {
  return {"tumbling_bunnies",
          "Tumbling bunnies",
          "Sec. 5.4, Fig. 16: bunnies launched down an incline that is smooth but for an "
          "embossed teapot logo (plane gain 10): the rough stone bunny sticks at once and "
          "falls over; the metal and plastic bunnies slide, then tumble at the logo's "
          "ridge.",
          "the stone bunny travels less than a third of the others' runs and rotates over 45 "
          "degrees; metal "
          "and plastic stay under 45 degrees until they reach the logo and exceed it on it",
          {{"tumbling_bunnies.json", 2.5, kBunniesRow}},
          evaluateBunnies};
}

}  // namespace asperity::experiments
