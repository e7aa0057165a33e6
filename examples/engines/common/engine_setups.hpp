// The set-ups that the engine demos, the adapters' tests and the benchmark share: Asperity
// scenes (pure data) that each engine's bridge rebuilds in that engine, and what is measured on
// them (how far each box slides). Asperity's own World runs the same scene for comparison.
#pragma once

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "asperity/scene/scene.hpp"

namespace asperity::engine_setups {

// The folder of the repository's scenes/ (compiled in; ASPERITY_SCENES overrides it).
std::string scenesFolder();

// The sawtooth plane of Sec. 5.2 (scenes/sawtooth_plane.json: gains 4 and 1, mu0 0.2, w 0.02,
// dt 10 ms) without its springs: 0.2 m boxes launched at `speed` m/s up the ramps (box_ramp,
// +x), against the steep faces (box_steep, -x) and along the ridges (box_along, +y).
SceneDesc sawtoothLaunch(double speed = 1.0);

// Boxes on four materials (scenes/boxes_on_materials.json): launched at 2 m/s along +x.
SceneDesc boxesOnMaterials();

// A slab with anisotropic Gaussian slopes (sx 0.2 along x, sy 1 along y; gain 2, mu0 0.2) and
// two 0.2 m boxes launched at `speed` m/s: box_along (+x, the smooth axis) and box_across (+y).
SceneDesc gaussianLaunch(double speed = 1.0);

// Where the symmetric cones of MuJoCo and ODE are wrong (SPEC 11): the sawtooth slab tilted by
// `degrees` so that its ramps rise uphill (+x), and box_uphill launched up it at `speed` m/s.
// The box slides up the ramps, stops, and gravity then pulls it against the steep faces, which
// hold it (Asperity's box limit); an engine that keeps the coefficient of the sense it last slid
// in lets it creep back down.
SceneDesc sawtoothIncline(double degrees = 35.0, double speed = 1.0);

// The benchmark's scene: a ground plane with sawtoothLaunch's texture under `count` 0.2 m boxes
// in rows of six, 0.4 m apart, all launched at 1 m/s along the ridges (+y), so that every
// contact slides (and is sampled afresh) for about half a second.
SceneDesc sawtoothBoxes(int count);

// The surfaces file (asperity/engines/engine_surfaces.hpp) of a scene rebuilt in an engine
// whose objects are named after the scene's bodies: the friction settings and each
// normal-mapped body's surface as the scene writes it.
nlohmann::json surfacesFile(const SceneDesc& scene);

// Horizontal distance (m) from its start of each dynamic body, by name.
using Distances = std::map<std::string, double>;
Distances horizontalDistances(const SceneDesc& scene, const std::map<std::string, Vec3>& now);

// Runs the scene in Asperity's own World for `seconds` and measures the distances.
Distances asperityDistances(const SceneDesc& scene, double seconds);

// {"ramps": m, ...}: each body's distance under its name without the "box_" prefix.
std::string distancesJson(const Distances& distances);

// The demos' command line: --json, --compare, --scene sawtooth|materials|gaussian|incline,
// --seconds.
struct DemoOptions {
  bool json = false;
  bool compare = false;  // also the engine alone and Asperity's own World
  std::string scene = "sawtooth";
  double seconds = 2.0;
};
// Throws asperity::Error naming a bad argument.
DemoOptions parseDemoOptions(const std::vector<std::string>& args);
// The scene the options name.
SceneDesc demoScene(const DemoOptions& options);

// One engine run of a scene for `seconds` (with Asperity's friction or the engine's own):
// each dynamic body's position at the end, by name.
using EngineRun = std::function<std::map<std::string, Vec3>(const SceneDesc& scene, double seconds,
                                                            bool with_asperity)>;
// A demo's main: the options in `args` (argv without the program), the run, and --json or a
// table (--compare: beside the engine alone and Asperity's own World). Returns the exit code;
// errors go to stderr under `program`.
int demoMain(const std::string& program, const std::string& engine,
             const std::vector<std::string>& args, const EngineRun& run);

}  // namespace asperity::engine_setups
