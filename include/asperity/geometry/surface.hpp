// What a shape's faces look like, and so how they grip (SPEC 3, 6): a normal map mapped onto
// the face by analytic UVs (primitives) or mesh UVs, and the saliency gain k of Eq. 7.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "asperity/contact_area/mechanical.hpp"
#include "asperity/diagnostics.hpp"
#include "asperity/texture/color_image.hpp"
#include "asperity/texture/generators.hpp"
#include "asperity/texture/normal_map.hpp"
#include "asperity/texture/png_io.hpp"

namespace asperity {

// A per-texel gain mask (values >= 0) multiplying k; same UVs as the normal map.
struct GainMask {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // rows bottom-up like NormalMap
};

// What a user describes about a surface's look: where its normal map and gain mask come from.
// Scenes keep it so that they save back as they were written.
struct SurfaceSource {
  std::string normal_map_file;  // PNG path; empty when generated or flat
  GeneratorSpec generator;      // used when generator.name is not empty
  GreenConvention green = GreenConvention::OpenGL;
  std::string mask_file;  // optional gain mask PNG (grey); empty = none
  // The entry of the scene's "materials" table the surface was read from (saved back as that
  // name while the surface still equals the entry); empty = written out in full.
  std::string material;

  // True when it names a normal map (a file or a generator).
  bool namesNormalMap() const { return !normal_map_file.empty() || !generator.name.empty(); }
};

// A surface as the step uses it: the source it was described by and the data resolved from it.
// A World decodes no files: scenes resolve their surfaces in instantiate(), code that describes
// a surface by its source alone calls resolveSurfaces (shape.hpp) before World::createBody,
// which refuses an unresolved surface rather than make it silently flat.
struct Surface {
  SurfaceSource source;

  // Resolved data shared between shapes (null normal map = flat surface).
  std::shared_ptr<const NormalMap> normal_map;
  std::shared_ptr<const GainMask> mask;

  double gain = 1.0;                      // k of Eq. 7 (unit: 1)
  double texture_size = 0.25;             // metres covered by one repeat of the texture (u and v)
  double texture_rotation = 0.0;          // radians, rotates the texture within the face's UV plane
  Vec3 base_color = Vec3(0.7, 0.7, 0.7);  // linear RGB albedo the renderer shades with (0..1)
  // An asset's base colour texture, which the renderer multiplies base_color by (display only;
  // it follows the mesh's UVs). Null: none.
  std::shared_ptr<const ColorImage> base_color_texture;
  // The material's elastic and plastic values, which the contact-area friction model reads
  // (friction/friction_model.hpp); a scene fills them from the surface's or its material's
  // "mechanical". None: a contact on it cannot use that model.
  std::optional<Mechanical> mechanical;
};

// The normal map `source` names, read or generated; null when it names none. Paths are used as
// given. A read map whose slopes contradict source.green, or whose texels are not all normals
// (SPEC 10), is reported to `diagnostics`. Throws asperity::Error naming the file or the
// generator parameter.
std::shared_ptr<const NormalMap> loadNormalMap(const SurfaceSource& source,
                                               Diagnostics& diagnostics);

// A grey PNG as a gain mask (values in [0, 1]). Throws asperity::Error naming the file.
GainMask loadGainMask(const std::string& path);

// The resolver: fills the surface's normal map and mask from its source where they are still
// null (reads the files, runs the generator). Warnings go to `diagnostics`. For a body's shapes
// use resolveSurfaces (shape.hpp). Throws asperity::Error naming the file.
void resolveSurface(Surface& surface, Diagnostics& diagnostics);

// What the surface names but has not resolved (`normal map "x.png"`, `normal map generator
// "sawtooth"`, `mask "m.png"`), or "" when nothing is missing.
std::string unresolvedPart(const Surface& surface);

}  // namespace asperity
