// The 1000-cube pile of ../shared/peers (scene B: a 10 x 10 x 10 grid of 0.2 m, 1 kg cubes,
// 0.05 m gaps, the lowest layer 0.05 m above the ground, dropped; dt = 10 ms, 20 iterations,
// Coulomb mu = 0.5), shared by the benchmarks that run it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asperity/sampler/constant_provider.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"

namespace asperity::bench {

inline constexpr int kGrid = 10;
inline constexpr double kEdge = 0.2, kGap = 0.05;

inline std::vector<Vec3> gridCentres() {
  std::vector<Vec3> centres;
  const double pitch = kEdge + kGap, off = 0.5 * (kGrid - 1) * pitch;
  for (int k = 0; k < kGrid; ++k)
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i)
        centres.emplace_back(i * pitch - off, j * pitch - off, kGap + 0.5 * kEdge + k * pitch);
  return centres;
}

inline std::unique_ptr<World> pileWorld(int threads) {
  WorldSettings settings;
  settings.limit_surface = LimitSurfaceKind::Coulomb;
  settings.friction.mu0 = 0.5;
  settings.threads = threads;
  auto world = std::make_unique<World>(settings);
  world->setFrictionProvider(std::make_unique<ConstantProvider>());
  world->createBody(groundPlaneDesc());
  const double density = 1.0 / (kEdge * kEdge * kEdge);  // 1 kg cubes
  int index = 0;
  for (const Vec3& c : gridCentres())
    world->createBody(boxDesc("cube" + std::to_string(index++), Vec3::Constant(0.5 * kEdge),
                              {c, Quat::Identity()}, density));
  return world;
}

}  // namespace asperity::bench
