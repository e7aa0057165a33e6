// The scene and actions the batch tests share: boxes pushed on a sawtooth plate, and the same
// worlds built and driven through the World API alone, as the batch promises to equal.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "asperity/batch/batch.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity::test {

// A box pushed on a sawtooth plate by a kinematic finger, a second box tied to it by a
// distance joint; mu0, the box's start speed and the texture's gain are varied.
inline BatchDesc pushedBoxes(int64_t worlds, int threads) {
  BatchDesc d;
  d.scene_json = R"({
    "settings": {"friction_provider": "cone", "mu0": 0.2, "dt": 0.01},
    "bodies": [
      {"name": "plate", "type": "static", "position": [0, 0, -0.05],
       "shapes": [{"type": "box", "half_extents": [2, 2, 0.05], "surface": {
         "normal_map": {"generator": "sawtooth", "params": {"period": 8}, "size": 32},
         "gain": 2, "texture_size": 0.05}}]},
      {"name": "box", "position": [0, 0, 0.05], "linear_velocity": [0.3, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.05, 0.05, 0.05]}]},
      {"name": "tail", "position": [-0.3, 0, 0.05],
       "shapes": [{"type": "box", "half_extents": [0.04, 0.04, 0.04]}]},
      {"name": "finger", "type": "kinematic", "position": [0, -0.2, 0.03],
       "shapes": [{"type": "sphere", "radius": 0.02}]}],
    "joints": [{"name": "tie", "type": "distance", "body_a": "box", "body_b": "tail"},
               {"name": "pin", "type": "ball", "body_a": "tail", "body_b": "plate",
                "anchor_a": [0, 0, 1], "anchor_b": [-0.3, 0, 1.1]}]})";
  d.scene_file = "pushed_boxes.json";
  d.vary = {parseVariation("/settings/mu0=uniform(0.1,0.4)"),
            parseVariation("/bodies/1/linear_velocity/0=normal(0.3,0.1)"),
            parseVariation("/bodies/0/shapes/0/surface/gain=choice(1,2,4)")};
  d.worlds = worlds;
  d.seed = 11;
  d.threads = threads;
  return d;
}

// Per-world actions of step s: a force and torque on the box, the finger's velocity, the tie's
// length.
inline std::vector<double> forces(int64_t n, int s) {
  std::vector<double> v;
  for (int64_t i = 0; i < n; ++i) v.insert(v.end(), {0.5 * static_cast<double>(i % 3), -1.0, 0});
  v[0] += 0.1 * s;
  return v;
}
inline std::vector<double> torques(int64_t n) {
  std::vector<double> v;
  for (int64_t i = 0; i < n; ++i) v.insert(v.end(), {0, 0, 0.01 * static_cast<double>(i)});
  return v;
}
inline std::vector<double> fingerVelocities(int64_t n) {
  std::vector<double> v;
  for (int64_t i = 0; i < n; ++i) v.insert(v.end(), {0, 0.1 + 0.05 * static_cast<double>(i), 0});
  return v;
}
inline std::vector<double> tieLengths(int64_t n) {
  std::vector<double> v;
  for (int64_t i = 0; i < n; ++i) v.push_back(0.25 + 0.01 * static_cast<double>(i));
  return v;
}

// Sets the actions of step s on a batch.
inline void act(Batch& batch, int s) {
  const int64_t n = batch.size();
  batch.setAction(BatchAction::Force, batch.bodyIndex("box"), forces(n, s));
  batch.setAction(BatchAction::Torque, batch.bodyIndex("box"), torques(n));
  batch.setAction(BatchAction::LinearVelocity, batch.bodyIndex("finger"), fingerVelocities(n));
  batch.setAction(BatchAction::JointTarget, batch.jointIndex("tie"), tieLengths(n));
}

// World i of `desc` built by hand: the scene with the batch's values written at every pointer.
inline std::unique_ptr<World> referenceWorld(const BatchDesc& desc,
                                             std::span<const double> values) {
  const nlohmann::json scene_json = nlohmann::json::parse(desc.scene_json);
  nlohmann::json json = scene_json;
  for (size_t j = 0; j < desc.vary.size(); ++j)
    for (const std::string& p : expandPath(scene_json, desc.vary[j].path))
      json[nlohmann::json::json_pointer(p)] = values[j];
  SceneDesc scene = parseScene(json, desc.scene_file);
  scene.settings.threads = 2;  // any count gives the same bits (SPEC 9)
  return instantiate(scene);
}

// One step of world i with act()'s actions, through the World API alone.
inline void referenceStep(World& w, int64_t n, int64_t i, int s) {
  const auto k = static_cast<size_t>(i);
  const std::vector<double> f = forces(n, s), t = torques(n), v = fingerVelocities(n);
  for (const auto& [kind, values] :
       {std::pair(LoadDesc::Kind::Force, f), std::pair(LoadDesc::Kind::Torque, t)}) {
    LoadDesc load;
    load.body = w.findBody("box");
    load.kind = kind;
    load.value = Vec3(values[3 * k], values[3 * k + 1], values[3 * k + 2]);
    load.start = w.time();
    load.end = w.time() + w.settings().dt;
    w.addLoad(load);
  }
  w.body(w.findBody("finger")).linear_velocity = Vec3(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
  w.setJointRestLength(0, tieLengths(n)[k]);
  w.step();
}

}  // namespace asperity::test
