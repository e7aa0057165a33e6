// asperity-mujoco-demo: the paper's sawtooth plane (Sec. 5.2) in MuJoCo with Asperity's
// friction: 0.2 m boxes launched at 1 m/s up the ramps, against the steep faces and along the
// ridges, and how far each slides in 2 s. Other scenes: materials (boxes on four materials),
// gaussian (anisotropic slopes), incline (a sawtooth slope where a symmetric cone is wrong).
// --compare adds MuJoCo alone (mu0 only) and Asperity's own World on the same scene;
// --pyramidal uses MuJoCo's pyramidal cone instead of the elliptic one.
//   asperity-mujoco-demo [--json] [--compare] [--pyramidal]
//                        [--scene sawtooth|materials|gaussian|incline] [--seconds 2]
#include <algorithm>
#include <string>
#include <vector>

#include "common/engine_setups.hpp"
#include "mjcf_scene.hpp"

int main(int argc, char** argv) {
  using namespace asperity;
  // --pyramidal is this demo's own; the rest is shared with the other engines' demos.
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto pyramidal = std::find(args.begin(), args.end(), "--pyramidal");
  mjcf_scene::MjcfOptions options;
  if (pyramidal != args.end()) options.cone = mjcf_scene::Cone::Pyramidal;
  if (pyramidal != args.end()) args.erase(pyramidal);
  // The scene as MJCF plus a surfaces file, stepped by MuJoCo.
  const auto run = [options](const SceneDesc& scene, double seconds, bool with_asperity) {
    return mjcf_scene::run(scene, seconds, with_asperity, options).positions;
  };
  return engine_setups::demoMain("asperity-mujoco-demo",
                                 std::string("MuJoCo ") + mj_versionString(), args, run);
}
