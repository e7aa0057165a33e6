// Random-slope generators: Gaussian slopes (Fig. 8) and Ra roughness (Sec. 5.1) with presets.
#include <cmath>

#include "asperity/math/types.hpp"
#include "texture/generator_support.hpp"
#include "texture/noise_generators.hpp"

namespace asperity::texgen {

namespace {

// gaussian: slopes s ~ N(0, diag(sx^2, sy^2)) per texel, m = normalize(-s_x, -s_y, 1) (SPEC 2).
NormalMap makeGaussian(const GeneratorContext& ctx) {
  const double sx = ctx.number("sx");
  const double sy = ctx.number("sy");
  Rng rng(ctx.seed());
  NormalMap map(ctx.size(), ctx.size());
  for (int j = 0; j < ctx.size(); ++j) {
    for (int i = 0; i < ctx.size(); ++i) {
      // Two draws per texel, x first, in row order.
      const double gx = sx * rng.gaussian();
      const double gy = sy * rng.gaussian();
      map.at(i, j) = Vec3f(static_cast<float>(-gx), static_cast<float>(-gy), 1.0f).normalized();
    }
  }
  return map;
}

// Heights in mm -> normals, with the texel pitch converting mm to texel units.
NormalMap roughnessMap(const GeneratorContext& ctx, double ra_mm) {
  const double texel_mm = ctx.number("texel_mm");
  const Field heights = roughnessHeightsMm(ra_mm, ctx.size(), ctx.seed());
  return normalsFromHeights(heights, 1.0 / texel_mm, Edge::Wrap);
}

// The same heights in texel units (normals by central differences give roughnessMap).
Field roughnessTexels(const GeneratorContext& ctx, double ra_mm) {
  Field heights = roughnessHeightsMm(ra_mm, ctx.size(), ctx.seed());
  const double per_texel = 1.0 / ctx.number("texel_mm");
  for (double& h : heights.values) h *= per_texel;
  return heights;
}

GeneratorParam texelParam() {
  return numberParam("texel_mm", 1.0, 1e-3, 1e3, "width of one texel (mm)");
}

// A fixed-Ra preset of the roughness generator (Sec. 5.1's materials).
GeneratorEntry preset(const std::string& name, double ra_mm, const std::string& doc) {
  return {{name, doc, {texelParam()}},
          [ra_mm](const GeneratorContext& ctx) { return roughnessMap(ctx, ra_mm); },
          [ra_mm](const GeneratorContext& ctx) { return roughnessTexels(ctx, ra_mm); }};
}

}  // namespace

Field roughnessHeightsMm(double ra_mm, int size, uint64_t seed) {
  // sigma from Ra = sigma sqrt(2 / pi).
  const double sigma = ra_mm / std::sqrt(2.0 / kPi);
  Rng rng(seed);
  Field heights = whiteNoise(size, size, rng);
  for (double& h : heights.values) {
    h *= sigma;
  }
  return heights;
}

std::vector<GeneratorEntry> noiseGenerators() {
  std::vector<GeneratorEntry> entries;
  entries.push_back(
      {{"gaussian",
        "independent Gaussian slopes per texel, s ~ N(0, diag(sx^2, sy^2)), "
        "m = normalize(-s_x, -s_y, 1) (Fig. 8)",
        {numberParam("sx", 1.0, 0.0, 100.0, "standard deviation of the slope along u (-)"),
         numberParam("sy", 1.0, 0.0, 100.0, "standard deviation of the slope along v (-)")}},
       makeGaussian, nullptr});  // independent slopes: no height field
  entries.push_back(
      {{"roughness",
        "i.i.d. Gaussian heights per texel with mean absolute deviation Ra, normals by "
        "central differences (wrap-around) (Sec. 5.1)",
        {numberParam("ra_mm", 0.15, 0.0, 100.0, "mean absolute height deviation Ra (mm)"),
         texelParam()}},
       [](const GeneratorContext& ctx) { return roughnessMap(ctx, ctx.number("ra_mm")); },
       [](const GeneratorContext& ctx) { return roughnessTexels(ctx, ctx.number("ra_mm")); }});
  entries.push_back(preset("concrete", 1.0, "concrete: roughness with Ra = 1 mm (Sec. 5.1)"));
  entries.push_back(preset("cast_iron", 0.15, "cast iron: roughness with Ra = 0.15 mm (Sec. 5.1)"));
  entries.push_back(preset("steel", 0.01, "steel: roughness with Ra = 0.01 mm (Sec. 5.1)"));
  return entries;
}

}  // namespace asperity::texgen
