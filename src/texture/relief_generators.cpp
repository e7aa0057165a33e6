// Relief generators: a grayscale height map from a PNG file, and a built-in embossed logo (the
// teapot of the tumbling-bunnies scene, Fig. 16), both turned into normals by central
// differences.
#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "asperity/texture/height_map.hpp"
#include "asperity/texture/png_io.hpp"
#include "texture/generator_support.hpp"
#include "texture/height_field.hpp"
#include "texture/png_codec.hpp"

namespace asperity::texgen {

namespace {

// The grey levels g in [0, 1] of heightmap's file, with the file's size.
Field greyLevels(const GeneratorContext& ctx) {
  const std::string file = ctx.path("file");
  png::Image image;
  try {
    image = png::decode(png::readFile(file), file, kMaxTextureSize, 1);
  } catch (const Error& e) {
    ctx.fail(std::string("parameter 'file': ") + e.what());
  }
  // PNG row r (top first) is texel row H - 1 - r, as for normal maps.
  const int w = image.header.width;
  const int h = image.header.height;
  Field heights(w, h);
  for (int r = 0; r < h; ++r) {
    for (int i = 0; i < w; ++i) {
      heights.at(i, h - 1 - r) = image.samples[static_cast<size_t>(r) * w + i];
    }
  }
  return heights;
}

// heightmap: height g * height_scale texels; the picture's border uses one-sided differences
// (no wrap-around).
NormalMap makeHeightmap(const GeneratorContext& ctx) {
  return normalsFromHeights(greyLevels(ctx), ctx.number("height_scale"), Edge::Clamp);
}

Field heightmapHeights(const GeneratorContext& ctx) {
  Field heights = greyLevels(ctx);
  const double scale = ctx.number("height_scale");
  for (double& h : heights.values) h *= scale;
  return heights;
}

// height_map: a grey PNG of heights at physical scale (SPEC 13), the generator behind a
// surface's "height_map" key; normals at the texel size texture_size / width.
HeightMap physicalHeights(const GeneratorContext& ctx) {
  const std::string file = ctx.path("file");
  try {
    return loadHeightMap(file, ctx.number("height_scale"));
  } catch (const Error& e) {
    ctx.fail(std::string("parameter 'file': ") + e.what());
  }
}

NormalMap makePhysicalHeights(const GeneratorContext& ctx) {
  return normalsFromHeightMap(physicalHeights(ctx), ctx.number("texture_size"));
}

// The same heights in texel units.
Field physicalHeightsTexels(const GeneratorContext& ctx) {
  const HeightMap map = physicalHeights(ctx);
  const double per_texel = map.width / ctx.number("texture_size");
  Field heights(map.width, map.height);
  for (size_t k = 0; k < map.values.size(); ++k) heights.values[k] = map.values[k] * per_texel;
  return heights;
}

// Signed distances in logo units, positive inside each part.
double ellipseInside(double x, double y, double rx, double ry) {
  // First-order distance to an ellipse: (1 - k0) k0 / k1 (exact on the axes).
  const double k0 = std::hypot(x / rx, y / ry);
  const double k1 = std::hypot(x / (rx * rx), y / (ry * ry));
  return k1 > 0.0 ? (1.0 - k0) * k0 / k1 : std::min(rx, ry);
}

double capsuleInside(double x, double y, double ax, double ay, double bx, double by, double r) {
  const double dx = bx - ax;
  const double dy = by - ay;
  const double t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return r - std::hypot(x - ax - t * dx, y - ay - t * dy);
}

// The teapot silhouette: body, lid, knob, spout, handle and foot (logo radius 1, +y up).
double teapotInside(double x, double y) {
  double d = ellipseInside(x, y + 0.1, 0.55, 0.42);                          // body
  d = std::max(d, ellipseInside(x, y - 0.33, 0.3, 0.08));                    // lid
  d = std::max(d, 0.08 - std::hypot(x, y - 0.46));                           // knob
  d = std::max(d, capsuleInside(x, y, 0.4, -0.15, 0.82, 0.28, 0.07));        // spout
  d = std::max(d, 0.06 - std::abs(std::hypot(x + 0.6, y + 0.05) - 0.22));    // handle ring
  d = std::max(d, std::min(0.32 - std::abs(x), 0.05 - std::abs(y + 0.52)));  // foot
  return d;
}

// emboss: the teapot raised by `height` texels, with linear edges `edge_width` texels wide
// centred on the outline, on a flat background.
Field makeEmboss(const GeneratorContext& ctx) {
  const int n = ctx.size();
  const double height = ctx.number("height");
  const double edge = ctx.number("edge_width");
  const double radius = 0.5 * ctx.number("scale") * n;  // texels per logo unit
  Field heights(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      // Texel centre in logo units, then the inside distance in texels.
      const double x = (i + 0.5 - 0.5 * n) / radius;
      const double y = (j + 0.5 - 0.5 * n) / radius;
      const double inside = teapotInside(x, y) * radius;
      heights.at(i, j) = height * std::clamp(0.5 + inside / edge, 0.0, 1.0);
    }
  }
  return heights;
}

}  // namespace

std::vector<GeneratorEntry> reliefGenerators() {
  std::vector<GeneratorEntry> entries;
  entries.push_back(
      {{"heightmap",
        "normals from a grayscale PNG height map (8 or 16 bit; colour files are converted to "
        "grey); the map has the file's size, and `size` is only range-checked",
        {pathParam("file", "PNG height map: black = 0, white = height_scale"),
         numberParam("height_scale", 4.0, 0.0, 1000.0, "height of white (texels)")}},
       makeHeightmap, heightmapHeights});
  entries.push_back(
      {{"height_map",
        "normals from a grey PNG (8 or 16 bit) or float OpenEXR height map at physical scale: "
        "heights grey * height_scale metres (EXR: value * height_scale, 0 = 1) over a texture "
        "texture_size metres wide, central differences "
        "wrapping (SPEC 13); a surface's \"height_map\" key; the map has the file's size",
        {pathParam("file", "height map: grey PNG (black = 0, white = height_scale) or .exr"),
         numberParam("height_scale", 0.0, 0.0, 1e3,
                     "metres per full grey range (0: the scale stored in the file)"),
         numberParam("texture_size", 0.25, 1e-9, 1e6,
                     "metres covered by the map (the surface's texture_size)")}},
       makePhysicalHeights, physicalHeightsTexels});
  entries.push_back(heightEntry(
      {"emboss",
        "a teapot logo raised as a plateau with sloped edges on a flat background (Fig. 16)",
        {numberParam("height", 2.0, 0.0, 1000.0, "plateau height (texels)"),
         numberParam("edge_width", 4.0, 0.5, 1000.0,
                     "width of the sloped edge (texels); edge tilt = atan(height / edge_width)"),
         numberParam("scale", 0.8, 0.05, 1.0, "logo width as a fraction of the map")}},
       makeEmboss));
  return entries;
}

}  // namespace asperity::texgen
