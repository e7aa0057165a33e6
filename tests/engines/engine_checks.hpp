// What the engine adapters' tests share: the set-ups on which an engine with Asperity's
// friction must agree with Asperity's own solver, the agreement check, and small files.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "common/engine_setups.hpp"
#include "support/test_support.hpp"

namespace asperity::test {

// Each set-up of issue 32's agreement tests: anisotropic Gaussian along and across, the
// sawtooth in both senses (and along its ridges), boxes on four materials.
inline std::vector<std::pair<std::string, SceneDesc>> agreementSetups() {
  return {{"gaussian", engine_setups::gaussianLaunch()},
          {"sawtooth", engine_setups::sawtoothLaunch()},
          {"materials", engine_setups::boxesOnMaterials()}};
}

// Boxes launched over a slab whose normal map is flat (Ra 0), gain 2, one of them diagonally.
inline SceneDesc flatSlab() {
  SceneDesc scene = engine_setups::gaussianLaunch();
  Surface& slab = scene.bodies[0].shapes[0].surface;
  slab.source.generator = {"roughness", {{"ra_mm", "0"}}, 64, 1};
  scene.bodies[1].linear_velocity = Vec3(1.0, 0.6, 0.0);
  return scene;
}

// Every box of the engine's run slides within `tolerance` (relative) of Asperity's World.
inline void expectAgreement(const std::string& setup, const engine_setups::Distances& engine,
                            const engine_setups::Distances& asperity, double tolerance) {
  ASSERT_EQ(engine.size(), asperity.size()) << setup;
  for (const auto& [name, d] : asperity) {
    EXPECT_TRUE(near(engine.at(name), d, tolerance))
        << setup << " " << name << ": engine " << engine.at(name) << " m, Asperity " << d << " m";
  }
}

// Each dynamic body's final position by name after `seconds` in an engine with Asperity's friction.
using EngineRun =
    std::function<std::map<std::string, Vec3>(const SceneDesc& scene, double seconds)>;

// Issue 32's agreement in 2 s on every set-up, within `tolerance` of Asperity's World.
inline void expectAgreementOnEverySetup(const EngineRun& run, double tolerance) {
  for (const auto& [name, scene] : agreementSetups()) {
    expectAgreement(name, engine_setups::horizontalDistances(scene, run(scene, 2.0)),
                    engine_setups::asperityDistances(scene, 2.0), tolerance);
  }
}

// The sense and the anisotropy show in the engine: up the sawtooth's ramps slides farther
// than against its steep faces, along the Gaussian's gentle axis farther than across it.
inline void expectSenseAndAnisotropy(const EngineRun& run) {
  const SceneDesc sawtooth = engine_setups::sawtoothLaunch();
  const auto saw = engine_setups::horizontalDistances(sawtooth, run(sawtooth, 2.0));
  EXPECT_GT(saw.at("box_ramp"), 3.0 * saw.at("box_steep"));
  const SceneDesc gaussian = engine_setups::gaussianLaunch();
  const auto gauss = engine_setups::horizontalDistances(gaussian, run(gaussian, 2.0));
  EXPECT_GT(gauss.at("box_along"), 1.5 * gauss.at("box_across"));
}

// Writes `text` to `path`.
inline void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace asperity::test
