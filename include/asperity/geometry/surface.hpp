// What a shape's faces look like, and so how they grip (SPEC 3, 6): a normal map mapped onto
// the face by analytic UVs (primitives) or mesh UVs, and the saliency gain k of Eq. 7.
#pragma once

#include <memory>
#include <string>

#include "asperity/texture/generators.hpp"
#include "asperity/texture/normal_map.hpp"
#include "asperity/texture/png_io.hpp"

namespace asperity {

// A per-texel gain mask (values >= 0) multiplying k; same UVs as the normal map.
struct GainMask {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // rows bottom-up like NormalMap
  float sample(float u, float v) const;
};

struct Surface {
  // Where the normal map comes from (kept so a scene saves back as it was written).
  std::string normal_map_file;  // PNG path; empty when generated or flat
  GeneratorSpec generator;      // used when generator.name is not empty
  GreenConvention green = GreenConvention::OpenGL;
  std::string mask_file;  // optional gain mask PNG (grey); empty = none

  // Resolved data shared between shapes (null normal map = flat surface).
  std::shared_ptr<const NormalMap> normal_map;
  std::shared_ptr<const GainMask> mask;

  double gain = 1.0;           // k of Eq. 7 (unit: 1)
  double texture_size = 0.25;  // metres covered by one repeat of the texture (u and v)
  double texture_rotation = 0.0;  // radians, rotates the texture within the face's UV plane
  Vec3 base_color = Vec3(0.7, 0.7, 0.7);  // linear RGB albedo the renderer shades with (0..1)
};

}  // namespace asperity
