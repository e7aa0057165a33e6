// A surface's normal map as an image (rgb = 0.5 n + 0.5) and its flat-patch friction cone
// (flatPatchCone, the paper's Fig. 8) drawn as a polar polygon with ImGui's draw list.
#pragma once

#include <memory>

#include "asperity/friction/patch_cone.hpp"
#include "asperity/texture/normal_map.hpp"
#include "gl/objects.hpp"

namespace asperity::viewer {

class SurfacePreview {
 public:
  // Shows `map` (null: a flat surface) with gain k and nominal mu0 in the current ImGui window.
  void draw(const std::shared_ptr<const NormalMap>& map, double gain, double mu0, int directions);

 private:
  void upload(const NormalMap& map);

  std::weak_ptr<const NormalMap> shown_;
  gl::Texture texture_;
  DirectionalMu cone_;
  double cone_gain_ = -1.0, cone_mu0_ = -1.0;
  int cone_directions_ = 0;
};

}  // namespace asperity::viewer
