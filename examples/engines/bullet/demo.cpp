// asperity-bullet-demo: the paper's sawtooth plane (Sec. 5.2) in Bullet with Asperity's friction.
// Three 0.2 m boxes are launched at 1 m/s over sawtooth planes (k_A 4, k_B 1, mu0 0.2): up the
// ramps, against the steep faces, and along the ridges; the demo prints how far each slid in
// 2 s. --scene materials runs the boxes on four materials (Sec. 5.1) instead. --engine asperity
// runs the same scene in Asperity's own World (the numbers to put beside Bullet's), --engine
// plain in Bullet with mu0 alone.
//
//   asperity-bullet-demo --json                      {"ramps": m, "steep": m, "along": m}
//   asperity-bullet-demo --scene materials --engine asperity
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>

#include "asperity/engines/bullet_scene.hpp"
#include "asperity/error.hpp"

namespace {

// The scene files of the two set-ups, in the source tree.
std::string sceneFile(const std::string& scene) {
  const std::string root = ASPERITY_SOURCE_DIR;
  if (scene == "materials") return root + "/scenes/boxes_on_materials.json";
  return root + "/examples/engines/sawtooth_launch.json";
}

// A box's name without its "box_" prefix: the JSON key of its distance.
std::string key(const std::string& name) {
  return name.rfind("box_", 0) == 0 ? name.substr(4) : name;
}

// The distances as a JSON object or a small table.
void print(const std::vector<std::pair<std::string, double>>& distances, bool json,
           const std::string& engine) {
  if (json) {
    // One line: {"ramps": 0.0777, ...} in the scene's order.
    std::string line = "{";
    for (const auto& [name, d] : distances) {
      char value[32];
      std::snprintf(value, sizeof value, "%.4f", d);
      line += (line.size() > 1 ? ", \"" : "\"") + key(name) + "\": " + value;
    }
    std::cout << line << "}\n";
    return;
  }
  std::cout << "distance slid (m), " << engine << ":\n";
  for (const auto& [name, d] : distances) std::printf("  %-10s %.4f\n", key(name).c_str(), d);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The sawtooth plane (or boxes on materials) in Bullet with Asperity's friction",
               "asperity-bullet-demo"};
  std::string scene = "sawtooth", engine = "bullet", file;
  double seconds = 2.0;
  bool json = false;
  app.add_option("--scene", scene, "sawtooth or materials")
      ->check(CLI::IsMember({"sawtooth", "materials"}));
  app.add_option("--engine", engine,
                 "bullet (Asperity's friction), asperity (its own World) or "
                 "plain (Bullet with mu0)")
      ->check(CLI::IsMember({"bullet", "asperity", "plain"}));
  app.add_option("--file", file, "Another scene file (bodies only)");
  app.add_option("--seconds", seconds, "Simulated time (s)")->check(CLI::PositiveNumber);
  app.add_flag("--json", json, "Print the distances as one JSON object");
  CLI11_PARSE(app, argc, argv);
  // Load, run in the chosen engine, print.
  try {
    const asperity::SceneDesc desc = asperity::loadScene(file.empty() ? sceneFile(scene) : file);
    const auto which =
        asperity::parseName<asperity::SceneEngine>(engine, asperity::kSceneEngineNames, "--engine");
    print(asperity::slideDistances(desc, which, seconds), json, engine);
  } catch (const asperity::Error& e) {
    std::cerr << "asperity-bullet-demo: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
