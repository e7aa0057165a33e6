// The OpenGL patch sampler (asperity::gl) and the CPU one on the same contacts: a box resting on
// a rough generated surface. Prints both samplers' coefficients and exits 1 when they differ by
// more than 0.05 anywhere, or when no OpenGL context can be made.
#include <asperity/asperity.hpp>
#include <asperity/sampler/gl_patch_sampler.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  try {
    asperity::World world;
    world.setFrictionProvider(std::make_unique<asperity::CpuPatchSampler>());
    asperity::BodyDesc ground = asperity::groundPlaneDesc();
    ground.shapes[0].surface.source.generator = {"stone", {}, 256, 3};
    ground.shapes[0].surface.gain = 2.0;
    // The world reads no files and runs no generators: surfaces are resolved first.
    asperity::resolveSurfaces(ground.shapes, world.diagnostics());
    world.createBody(ground);
    asperity::Transform pose;
    pose.position = asperity::Vec3(0.0, 0.0, 0.099);
    world.createBody(asperity::boxDesc("box", asperity::Vec3(0.1, 0.1, 0.1), pose));
    world.step();

    // The same contacts, frames included, through the GPU sampler.
    std::vector<asperity::Contact> gl_contacts = world.contacts();
    asperity::GlPatchSampler gl;
    gl.computeCoefficients(world.bodies(), gl_contacts, world.settings().friction);
    std::printf("OpenGL renderer: %s\n", gl.renderer().c_str());

    double worst = 0.0;
    for (size_t i = 0; i < gl_contacts.size(); ++i) {
      const asperity::Contact& cpu = world.contacts()[i];
      std::printf("contact %zu: cpu", i);
      for (int k = 0; k < cpu.mu.count; ++k) std::printf(" %.3f", cpu.mu.mu[k]);
      std::printf("  gl");
      for (int k = 0; k < gl_contacts[i].mu.count; ++k) {
        std::printf(" %.3f", gl_contacts[i].mu.mu[k]);
        worst = std::max(worst, double(std::abs(gl_contacts[i].mu.mu[k] - cpu.mu.mu[k])));
      }
      std::printf("\n");
    }
    std::printf("%zu contacts, largest difference %.4f\n", gl_contacts.size(), worst);
    return !gl_contacts.empty() && worst <= 0.05 ? 0 : 1;
  } catch (const asperity::Error& e) {
    std::fprintf(stderr, "gl_sampler: %s\n", e.what());
    return 1;
  }
}
