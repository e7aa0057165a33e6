// Scenes are pure data: load a JSON file (docs/scene-format.md), instantiate a World from it,
// save it back. Errors name the file and the JSON pointer of the culprit:
//   scenes/x.json: /bodies/2/shapes/0/half_extents/1: must be a positive number, got -0.1
// Units: metres, kilograms, seconds, radians inside the structs (degrees only in the JSON keys
// whose names end in _deg). z is up.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "asperity/dynamics/body.hpp"
#include "asperity/dynamics/driver.hpp"
#include "asperity/dynamics/joint.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/friction_providers.hpp"
#include "asperity/world/world.hpp"

namespace asperity {

namespace scene {
struct ResourcesAccess;  // src/scene/scene_resources.hpp
}

// Joints, springs and loads name their bodies; instantiate() turns the names into BodyIds
// (the BodyId fields of `desc` are ignored).
struct SceneJoint {
  std::string body_a;
  std::string body_b;
  JointDesc desc;
};

struct SceneSpring {
  std::string body;
  SpringDesc desc;
};

struct SceneLoad {
  std::string body;
  LoadDesc desc;
};

// A shape whose triangles come from an OBJ file: bodies[body].shapes[shape] (a ConvexHull or
// TriangleMesh). instantiate() loads it; saving writes the file name back as written.
struct SceneMesh {
  size_t body = 0;
  size_t shape = 0;
  std::string file;    // as written in the scene: relative to base_dir, or absolute
  double scale = 1.0;  // uniform scale applied to the OBJ's coordinates (1)
  int simplify = 0;    // target triangle count; 0 = keep every triangle
  std::string node;    // one node or mesh of a multi-mesh asset by name; empty = all of them
  // The shape's surface names no base_color: the asset's base colour (factor and texture) is
  // shown instead.
  bool asset_base_color = true;
};

// The view a scene is best seen from ("camera" in the JSON): `asperity render` and
// `asperity report` use it when no --camera is given, `asperity-viewer` opens with it. z is up.
struct SceneCamera {
  Vec3 eye = Vec3(1.2, -1.8, 1.0);    // m
  Vec3 target = Vec3::Zero();         // m, differs from eye
  double fov_y = 35.0 * kPi / 180.0;  // vertical field of view (rad), in (0, pi)
};

// An entry of the scene's "materials" table: a surface that shapes name instead of spelling it
// out ("surface": "oak"). Each such shape holds a copy, with Surface::source.material = the name.
struct SceneMaterial {
  Surface surface;
  // "mechanical": a preset name or {"E", "nu", "H", "tau"}: what the contact-area friction
  // model needs of the material (docs/contact-area.md). Absent: none.
  std::optional<Mechanical> mechanical;
  // The entry gives "base_color" (else a shape's asset shows its own colour, as inline).
  bool names_base_color = false;
};

// An entry of the scene's "pairs": the friction model of contacts between surfaces that name
// two materials (in either order; both may be the same), overriding the scene's
// "friction_model" for them.
struct ScenePair {
  std::array<std::string, 2> materials;
  FrictionModel friction_model = FrictionModel::Paper;
};

struct SceneDesc {
  WorldSettings settings;
  // The friction provider by name ("friction_provider"; InstantiateOptions::providers).
  std::string friction_provider = kDefaultFrictionProvider;
  // "friction_model": the paper's, or the real area of contact (provider "cpu" only; every
  // surface then has mechanical values, its own or its material's). "pairs" override it.
  FrictionModel friction_model = FrictionModel::Paper;
  std::map<std::string, SceneMaterial> materials;  // "materials", by name
  std::vector<ScenePair> pairs;                    // "pairs": per pair friction models
  // The "mechanical" values of surfaces written inline in a shape (not through "materials"),
  // by (body index, shape index).
  std::map<std::pair<size_t, size_t>, Mechanical> surface_mechanical;
  std::vector<BodyDesc> bodies;  // shapes' normal maps unresolved (files / generator specs)
  std::vector<SceneJoint> joints;
  std::vector<SceneSpring> springs;
  std::vector<SceneLoad> loads;
  std::vector<SceneMesh> meshes;
  std::optional<SceneCamera> camera;  // absent: front ends frame the bodies themselves
  std::string source_file;            // the file it came from, for messages ("" = built in code)
  std::string base_dir;               // folder that relative paths resolve against ("" = current)
  // What loading found that is not an error (deprecated keys), one line each naming the file
  // and the JSON pointer; instantiate() hands them to the world's diagnostics.
  std::vector<std::string> warnings;
};

// Reads and validates a scene file. Throws asperity::Error `file: /pointer: what` (or
// `file:line:column: what` for a JSON syntax error). Deprecated keys are read, with a warning
// in SceneDesc::warnings (`file: /settings/frame: deprecated, use "frame_mode"`).
SceneDesc loadScene(const std::string& path);
// Validates parsed JSON; relative paths resolve against the folder of file_for_messages.
SceneDesc parseScene(const nlohmann::json& json, const std::string& file_for_messages);

// The JSON of a scene (every setting written out under its current key; surfaces keep their file
// or generator spec, or the name of their material while they still equal its entry).
nlohmann::json sceneToJson(const SceneDesc& scene);
// Writes sceneToJson(scene) (indented, keys sorted). Relative file names are rewritten to
// stay correct from the new file's folder. Throws asperity::Error naming the path on failure.
void saveScene(const SceneDesc& scene, const std::string& path);
// The id a checkpoint file names its scene by (asperity/world/state_file.hpp): FNV-1a of the
// scene's canonical JSON (sceneToJson) and its body count, the thread count and the friction
// provider left out (threads change no result; the state names its provider itself).
uint64_t sceneStateId(const SceneDesc& scene);

// Normal maps, masks and asset meshes that instantiate() loads or generates, kept for reuse:
// worlds instantiated with the same SceneResources share one copy of each, so an ensemble of
// runs (asperity sweep) reads every file and generates every texture once. Worlds only read
// what they share. Safe to use from several threads at once.
class SceneResources {
 public:
  SceneResources();
  ~SceneResources();
  SceneResources(const SceneResources&) = delete;
  SceneResources& operator=(const SceneResources&) = delete;

 private:
  friend struct scene::ResourcesAccess;  // the scene library's one way in
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct InstantiateOptions {
  InstantiateOptions() = default;
  // Implicit, so that instantiate(scene, {providers}) reads naturally.
  InstantiateOptions(FrictionProviders table, std::shared_ptr<SceneResources> shared = nullptr)
      : providers(std::move(table)), resources(std::move(shared)) {}

  FrictionProviders providers = FrictionProviders::builtIn();  // the names scenes may ask for
  // Shared across instantiations when set; null: this world's own, dropped afterwards.
  std::shared_ptr<SceneResources> resources;
};
// Builds a World: resolves normal maps (PNG files, generators; equal surfaces share one
// NormalMap), masks and meshes (the one place scenes resolve), creates bodies, joints, springs
// and loads, and installs the friction provider `scene.friction_provider` from
// options.providers. The world's diagnostics() holds scene.warnings and what resolving found
// (a map loaded once for shared resources is warned about once). Throws asperity::Error naming
// the file and culprit.
std::unique_ptr<World> instantiate(const SceneDesc& scene, const InstantiateOptions& options = {});

}  // namespace asperity
