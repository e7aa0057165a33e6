// What the engine adapters' tests share: the set-ups on which an engine with Asperity's
// friction must agree with Asperity's own solver, the agreement check, and small files.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
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

// Every box of the engine's run slides within `tolerance` (relative) of Asperity's World.
inline void expectAgreement(const std::string& setup, const engine_setups::Distances& engine,
                            const engine_setups::Distances& asperity, double tolerance) {
  ASSERT_EQ(engine.size(), asperity.size()) << setup;
  for (const auto& [name, d] : asperity) {
    EXPECT_TRUE(near(engine.at(name), d, tolerance))
        << setup << " " << name << ": engine " << engine.at(name) << " m, Asperity " << d << " m";
  }
}

// Writes `text` to `path`.
inline void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace asperity::test
