// The engine demos' shared set-ups and measurements (engine_setups.hpp).
#include "engine_setups.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/math/enum_names.hpp"
#include "asperity/world/builders.hpp"

namespace asperity::engine_setups {

namespace {

// A dynamic 0.2 m box (density 1000: 8 kg) at `position` launched with `velocity`.
BodyDesc launchedBox(const std::string& name, const Vec3& position, const Vec3& velocity) {
  BodyDesc box = boxDesc(name, Vec3(0.1, 0.1, 0.1), {position, Quat::Identity()});
  box.linear_velocity = velocity;
  return box;
}

// The body of that name in the scene; throws when it has none.
BodyDesc& bodyNamed(SceneDesc& scene, const std::string& name) {
  for (BodyDesc& b : scene.bodies)
    if (b.name == name) return b;
  throw Error(scene.source_file + ": no body named \"" + name + "\"");
}

// A static slab whose top face is z = 0, `half` its half extents, with `surface`.
BodyDesc slab(const std::string& name, const Vec3& center, const Vec3& half,
              const Surface& surface) {
  Shape s;
  s.type = ShapeType::Box;
  s.half_extents = half;
  s.surface = surface;
  BodyDesc desc;
  desc.name = name;
  desc.type = BodyType::Static;
  desc.pose.position = Vec3(center.x(), center.y(), -half.z());
  desc.shapes.push_back(s);
  return desc;
}

}  // namespace

std::string scenesFolder() {
  const char* env = std::getenv("ASPERITY_SCENES");
  return env != nullptr ? env : ASPERITY_SCENES_DIR;
}

SceneDesc sawtoothLaunch(double speed) {
  SceneDesc scene = loadScene(scenesFolder() + "/sawtooth_plane.json");
  scene.springs.clear();
  // Up the ramps (+x), against the steep faces (-x), along the ridges (+y).
  bodyNamed(scene, "box_ramp").linear_velocity = Vec3(speed, 0.0, 0.0);
  bodyNamed(scene, "box_steep").linear_velocity = Vec3(-speed, 0.0, 0.0);
  bodyNamed(scene, "box_along").linear_velocity = Vec3(0.0, speed, 0.0);
  return scene;
}

SceneDesc boxesOnMaterials() {
  return loadScene(scenesFolder() + "/boxes_on_materials.json");
}

SceneDesc gaussianLaunch(double speed) {
  SceneDesc scene;
  scene.settings.friction.mu0 = 0.2;
  scene.friction_provider = "cpu";
  Surface rough;
  rough.source.generator = {"gaussian", {{"sx", "0.2"}, {"sy", "1"}}, 256, 3};
  rough.gain = 2.0;
  rough.texture_size = 0.256;
  scene.bodies.push_back(slab("slab", Vec3::Zero(), Vec3(2.0, 2.0, 0.05), rough));
  scene.bodies.push_back(launchedBox("box_along", Vec3(-1.0, -1.0, 0.1), Vec3(speed, 0, 0)));
  scene.bodies.push_back(launchedBox("box_across", Vec3(1.0, -1.0, 0.1), Vec3(0, speed, 0)));
  return scene;
}

SceneDesc sawtoothIncline(double degrees, double speed) {
  SceneDesc scene = sawtoothLaunch();
  const Surface sawtooth = bodyNamed(scene, "plane_ramp").shapes[0].surface;
  scene.bodies.clear();
  // The slab's +x turned up by `degrees` about y; the box on its top face, 1 m from its centre.
  const Quat tilt(Eigen::AngleAxisd(-degrees * kPi / 180.0, Vec3::UnitY()));
  BodyDesc slope = slab("slab", Vec3::Zero(), Vec3(2.0, 0.5, 0.05), sawtooth);
  slope.pose = {tilt * Vec3(0.0, 0.0, -0.05), tilt};
  scene.bodies.push_back(slope);
  const Vec3 uphill = tilt * Vec3::UnitX();
  BodyDesc box = launchedBox("box_uphill", tilt * Vec3(-1.0, 0.0, 0.1), speed * uphill);
  box.pose.rotation = tilt;
  scene.bodies.push_back(box);
  return scene;
}

SceneDesc sawtoothBoxes(int count) {
  SceneDesc scene = sawtoothLaunch();
  BodyDesc ground = groundPlaneDesc();
  ground.name = "ground";
  ground.shapes[0].surface = bodyNamed(scene, "plane_ramp").shapes[0].surface;
  scene.bodies = {ground};
  // Six boxes a row, 0.4 m apart, each launched at 1 m/s along the ridges.
  for (int i = 0; i < count; ++i) {
    const Vec3 at(-1.0 + 0.4 * (i % 6), -1.0 + 0.4 * (i / 6), 0.1);
    scene.bodies.push_back(launchedBox("box_" + std::to_string(i), at, Vec3(0.0, 1.0, 0.0)));
  }
  return scene;
}

// The surfaces file: the scene's friction settings and each normal-mapped body's surface as
// the scene writes it.
nlohmann::json surfacesFile(const SceneDesc& scene) {
  const WorldSettings& w = scene.settings;
  nlohmann::json settings = {
      {"directions", w.friction.directions},
      {"mu_max", w.friction.mu_max},
      {"patch_width", w.friction.patch_width},
      {"patch_resolution", w.friction.patch_resolution},
      {"reuse_pixels", w.friction.reuse_pixels},
      {"friction_provider", scene.friction_provider},
      {"frame_mode", nameOf(w.frame.mode, kFrameModeNames)},
      {"world_axis", {w.frame.world_axis.x(), w.frame.world_axis.y(), w.frame.world_axis.z()}}};
  const nlohmann::json written = sceneToJson(scene);
  nlohmann::json surfaces = nlohmann::json::object();
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    if (!scene.bodies[i].shapes[0].surface.source.namesNormalMap()) continue;
    // A shape that names one of the scene's materials gets that material's surface object.
    const nlohmann::json& surface = written["bodies"][i]["shapes"][0]["surface"];
    surfaces[scene.bodies[i].name] =
        surface.is_string() ? written["materials"][surface.get<std::string>()] : surface;
  }
  return {{"settings", settings}, {"surfaces", surfaces}};
}

Distances horizontalDistances(const SceneDesc& scene, const std::map<std::string, Vec3>& now) {
  Distances out;
  for (const BodyDesc& b : scene.bodies) {
    if (b.type != BodyType::Dynamic) continue;
    const Vec3 moved = now.at(b.name) - b.pose.position;
    out[b.name] = moved.head<2>().norm();
  }
  return out;
}

Distances asperityDistances(const SceneDesc& scene, double seconds) {
  std::unique_ptr<World> world = instantiate(scene);
  const auto steps = static_cast<int64_t>(std::llround(seconds / scene.settings.dt));
  while (world->stepCount() < steps) world->step();
  std::map<std::string, Vec3> now;
  for (const Body& b : world->bodies()) now[b.name] = b.descriptionPose().position;
  return horizontalDistances(scene, now);
}

std::string distancesJson(const Distances& distances) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, d] : distances) {
    // box_ramp slides up the ramps; the other boxes are named after what they slide on.
    const std::string label = name.rfind("box_", 0) == 0 ? name.substr(4) : name;
    out[label == "ramp" ? "ramps" : label] = std::round(d * 1e4) / 1e4;
  }
  return out.dump();
}

DemoOptions parseDemoOptions(const std::vector<std::string>& args) {
  DemoOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    // Flags first, then options that take a value.
    if (arg == "--json" || arg == "--compare") {
      (arg == "--json" ? o.json : o.compare) = true;
    } else if ((arg == "--scene" || arg == "--seconds") && i + 1 < args.size()) {
      const std::string& value = args[++i];
      if (arg == "--scene") o.scene = value;
      if (arg == "--seconds") o.seconds = std::stod(value);
    } else {
      throw Error("unknown argument \"" + arg +
                  "\" (expected --json, --compare, --scene sawtooth|materials|gaussian|incline, "
                  "--seconds S)");
    }
  }
  const std::vector<std::string> scenes{"sawtooth", "materials", "gaussian", "incline"};
  if (std::find(scenes.begin(), scenes.end(), o.scene) == scenes.end())
    throw Error("--scene must be sawtooth, materials, gaussian or incline, got \"" + o.scene +
                "\"");
  if (!(o.seconds > 0.0)) throw Error("--seconds must be positive");
  return o;
}

SceneDesc demoScene(const DemoOptions& options) {
  if (options.scene == "incline") return sawtoothIncline();
  if (options.scene == "gaussian") return gaussianLaunch();
  return options.scene == "materials" ? boxesOnMaterials() : sawtoothLaunch();
}

namespace {

// One line per box: the distances of each run side by side.
void printTable(const std::vector<std::pair<std::string, Distances>>& runs) {
  std::printf("%-16s", "box");
  for (const auto& run : runs) std::printf(" %22s", run.first.c_str());
  std::printf("\n");
  for (const auto& entry : runs[0].second) {
    std::printf("%-16s", entry.first.c_str());
    for (const auto& run : runs) std::printf(" %20.4f m", run.second.at(entry.first));
    std::printf("\n");
  }
}

}  // namespace

int demoMain(const std::string& program, const std::string& engine,
             const std::vector<std::string>& args, const EngineRun& run) {
  try {
    const DemoOptions options = parseDemoOptions(args);
    const SceneDesc scene = demoScene(options);
    const Distances distances = horizontalDistances(scene, run(scene, options.seconds, true));
    if (options.json) {
      std::printf("%s\n", distancesJson(distances).c_str());
      return 0;
    }
    std::printf("%s, %s scene, distances slid in %.2f s:\n", engine.c_str(), options.scene.c_str(),
                options.seconds);
    std::vector<std::pair<std::string, Distances>> runs{{"with Asperity", distances}};
    // The engine alone (mu0) and Asperity's own solver on the same scene.
    if (options.compare) {
      runs.emplace_back("alone", horizontalDistances(scene, run(scene, options.seconds, false)));
      runs.emplace_back("Asperity's World", asperityDistances(scene, options.seconds));
    }
    printTable(runs);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), e.what());
    return 1;
  }
}

}  // namespace asperity::engine_setups
