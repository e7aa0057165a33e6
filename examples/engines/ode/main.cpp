// asperity-ode-demo: the paper's sawtooth plane (Sec. 5.2) in ODE with Asperity's friction:
// 0.2 m boxes launched at 1 m/s up the ramps, against the steep faces and along the ridges, and
// how far each slides in 2 s. Other scenes: materials (boxes on four materials), gaussian
// (anisotropic slopes), incline (a sawtooth slope where a symmetric cone is wrong). --compare
// adds ODE alone (mu0 only) and Asperity's own World on the same scene.
//   asperity-ode-demo [--json] [--compare] [--scene sawtooth|materials|gaussian|incline]
//                     [--seconds 2]
#include <string>
#include <vector>

#include "common/engine_setups.hpp"
#include "ode_scene.hpp"

int main(int argc, char** argv) {
  using namespace asperity;
  // The scene as ODE bodies and geoms, the near callback handing contacts to Asperity.
  const auto run = [](const SceneDesc& scene, double seconds, bool with_asperity) {
    return ode_scene::run(scene, seconds, with_asperity).positions;
  };
  return engine_setups::demoMain("asperity-ode-demo", "ODE 0.16", {argv + 1, argv + argc}, run);
}
