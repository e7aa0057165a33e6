// An Asperity scene rebuilt in MuJoCo: the MJCF model (static bodies as world geoms, dynamic
// ones as free bodies, the launch velocities in keyframe "start") and the surfaces file that
// gives the geoms their Asperity surfaces. Shapes: boxes, spheres, capsules, cylinders and
// planes, one per body; no joints, springs or loads.
#pragma once

#include <mujoco/mujoco.h>

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "asperity/engines/mujoco.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity::mjcf_scene {

struct MjcfScene {
  std::string xml;          // MJCF text; every geom named after its body
  nlohmann::json surfaces;  // a surfaces file (engine_surfaces.hpp) for the textured geoms
};

// MuJoCo's friction cone. Elliptic by default: a pyramid shares the normal force among its
// edges, so with strongly anisotropic coefficients the weak axis grips less than it should
// (docs/engines.md measures it).
enum class Cone { Elliptic, Pyramidal };

struct MjcfOptions {
  Cone cone = Cone::Elliptic;
  // Dynamic bodies on three slide joints instead of a free joint: they cannot turn, so their
  // faces stay parallel to what they slide on (a check of the adapter alone: a tilted flat
  // face ploughs a little in Asperity's model, SPEC 2).
  bool translation_only = false;
};

// Throws asperity::Error naming what MuJoCo's side cannot hold.
MjcfScene fromScene(const SceneDesc& scene, const MjcfOptions& options = {});

// A model compiled from MJCF text (MuJoCo's virtual file system); throws asperity::Error with
// MuJoCo's message.
struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;
ModelPtr loadModel(const std::string& xml);

// The scene in MuJoCo from keyframe "start" for `seconds`, with Asperity's friction when
// `with_asperity` (else MuJoCo's own).
struct RunResult {
  std::map<std::string, Vec3> positions;  // each dynamic body's at the end, by name
  std::vector<double> trajectory;         // qpos after every step, one after the other
  MujocoFrictionStats stats;              // of the last step (zero without Asperity)
};
RunResult run(const SceneDesc& scene, double seconds, bool with_asperity,
              const MjcfOptions& options = {});

}  // namespace asperity::mjcf_scene
