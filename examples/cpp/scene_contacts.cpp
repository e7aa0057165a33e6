// Loads a scene file, steps it, and prints every contact of the last step with its friction
// coefficients along t, b, -t and -b (more when the scene samples more directions).
//   scene_contacts SCENE.json [STEPS]
#include <asperity/asperity.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: scene_contacts SCENE.json [STEPS]\n");
    return 2;
  }
  try {
    const asperity::SceneDesc scene = asperity::loadScene(argv[1]);
    const std::unique_ptr<asperity::World> world = asperity::instantiate(scene);
    // The library prints nothing: its warnings (deprecated keys, ...) are the world's to show.
    world->diagnostics().setSink([](const std::string& w) {
      std::fprintf(stderr, "scene_contacts: warning: %s\n", w.c_str());
    });
    const int steps = argc > 2 ? std::stoi(argv[2]) : 100;
    for (int i = 0; i < steps; ++i) world->step();
    std::printf("t = %.3f s, %zu contacts, sampler %s\n", world->time(), world->contacts().size(),
                world->frictionProvider().name().c_str());
    for (const asperity::Contact& c : world->contacts()) {
      std::printf("%s / %s at (%.3f %.3f %.3f) phi %.2e |P| %d mu",
                  world->body(c.body_a).name.c_str(), world->body(c.body_b).name.c_str(),
                  c.point.x(), c.point.y(), c.point.z(), c.phi, c.covered_pixels);
      for (int k = 0; k < c.mu.count; ++k) std::printf(" %.3f", c.mu.mu[k]);
      std::printf("\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scene_contacts: %s\n", e.what());
    return 1;
  }
}
