// The OpenGL sampler against the CPU reference over the contacts of every scene in the
// repository (scenes/ and scenes/examples/): each scene is stepped with the CPU sampler until
// it has contacts, then both samplers sample the same contacts and must agree within 2 % per
// direction (float targets; RGBA8 adds its quantisation step). Each scene's worst difference
// is printed, so that a run on another driver (an NVIDIA GPU, say) reports how far it is off;
// a scene that cannot run fails the test with its message, and the other scenes still run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/sampler/gl_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Every scene file of the repository, sorted so failures read the same every run.
std::vector<std::string> repositoryScenes() {
  std::vector<std::string> paths;
  for (const char* folder : {"scenes", "scenes/examples"}) {
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath(folder))) {
      if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

// The scene stepped with the CPU sampler until it has contacts (at most `max_steps` steps).
std::unique_ptr<World> steppedToContact(const std::string& path, int max_steps) {
  SceneDesc scene = loadScene(path);
  scene.friction_provider = "cpu";
  std::unique_ptr<World> world = instantiate(scene);
  for (int i = 0; i < max_steps && world->contacts().empty(); ++i) world->step();
  for (int i = 0; i < 5; ++i) world->step();  // let resting contacts settle in
  return world;
}

// |gl - cpu| <= 2 % of the CPU value plus the packing's own step.
void expectAgreement(const std::string& path, GlPatchSampler& gl, double packing_step) {
  std::unique_ptr<World> world = steppedToContact(path, 400);
  std::vector<Contact> cpu_contacts = world->contacts(), gl_contacts = cpu_contacts;
  if (cpu_contacts.empty()) return;
  FrictionSettings settings = world->settings().friction;
  settings.directions = std::max(4, settings.directions / 4 * 4);  // GL needs a multiple of 4
  CpuPatchSampler cpu;
  cpu.computeCoefficients(world->bodies(), cpu_contacts, settings);
  gl.computeCoefficients(world->bodies(), gl_contacts, settings);
  double worst = 0.0, worst_relative = 0.0;
  for (size_t i = 0; i < cpu_contacts.size(); ++i) {
    for (int k = 0; k < settings.directions; ++k) {
      const double expected = cpu_contacts[i].mu.mu[k];
      const double off = std::abs(gl_contacts[i].mu.mu[k] - expected);
      worst = std::max(worst, off);
      if (expected > 0.0) worst_relative = std::max(worst_relative, off / expected);
      EXPECT_TRUE(test::near(gl_contacts[i].mu.mu[k], expected, 0.02, packing_step + 1e-4))
          << path << ": contact " << i << " direction " << k;
    }
  }
  std::printf(
      "[ agreement ] %s on %s: %zu contacts x %d directions, worst |gl - cpu| %.5f (%.2f %%)\n",
      std::filesystem::path(path).filename().c_str(), gl.renderer().c_str(), cpu_contacts.size(),
      settings.directions, worst, 100.0 * worst_relative);
}

TEST(GlSceneAgreement, FloatTargetsAgreeWithCpuOnEveryScene) {
  GlSamplerOptions options;
  options.float_targets = true;
  GlPatchSampler gl(options);
  for (const std::string& path : repositoryScenes()) {
    SCOPED_TRACE(path);
    EXPECT_NO_THROW(expectAgreement(path, gl, 0.0));
  }
}

TEST(GlSceneAgreement, Rgba8AgreesWithCpuOnEveryScene) {
  GlPatchSampler gl;
  for (const std::string& path : repositoryScenes()) {
    SCOPED_TRACE(path);
    EXPECT_NO_THROW({
      // One RGBA8 step (mu_max / 255) scaled by the largest surface gain of the scene.
      double gain = 1.0;
      std::unique_ptr<World> world = instantiate(loadScene(path));
      for (const Body& b : world->bodies())
        for (const Shape& s : b.shapes) gain = std::max(gain, s.surface.gain);
      expectAgreement(path, gl, gain * world->settings().friction.mu_max / 255.0);
    });
  }
}

}  // namespace
}  // namespace asperity
