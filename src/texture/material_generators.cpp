// Look-alikes of the paper's materials (Sec. 5: acrylic, oak, cut PVC in Fig. 15; stone, metal,
// plastic in Fig. 16; plaster on the boxes of Fig. 9). Each is a height field scaled to a root
// mean square slope, so that roughness orders as the experiments need:
// acrylic < oak < cut_pvc and plastic < metal < stone (docs/textures.md).
#include <algorithm>
#include <cmath>

#include "asperity/math/types.hpp"
#include "texture/generator_support.hpp"
#include "texture/height_field.hpp"
#include "texture/profile.hpp"

namespace asperity::texgen {

namespace {

// Smooth isotropic bumps of about `radius` texels, unit variance.
Field bumps(int n, Rng& rng, int radius) {
  Field f = whiteNoise(n, n, rng);
  boxBlur(f, radius, radius);
  standardise(f);
  return f;
}

// Streaks along +u: long along, fine across.
Field streaks(int n, Rng& rng, int length) {
  Field f = whiteNoise(n, n, rng);
  boxBlur(f, std::max(1, length / 2), 0);
  standardise(f);
  return f;
}

// Scales to the target slope and turns the texture toward `axis` (heightEntry takes normals).
Field finish(Field heights, double rms_slope, double axis) {
  scaleToRmsSlope(heights, rms_slope, Edge::Wrap);
  if (axis != 0.0) {
    heights = rotated(heights, axis);
  }
  return heights;
}

// a += w * b, with b first scaled to unit rms slope.
void addScaled(Field& a, Field b, double w) {
  scaleToRmsSlope(b, 1.0, Edge::Wrap);
  for (size_t k = 0; k < a.values.size(); ++k) a.values[k] += w * b.values[k];
}

Field makeIsotropic(const GeneratorContext& ctx, int radius) {
  Rng rng(ctx.seed());
  return finish(bumps(ctx.size(), rng, radius), ctx.number("slope"), 0.0);
}

// oak: fibres (streaks along the grain) plus growth rings (waves across it that wander).
Field makeOak(const GeneratorContext& ctx) {
  const int n = ctx.size();
  const double ring_period = ctx.number("ring_period");
  Rng rng(ctx.seed());
  Field fibres = streaks(n, rng, ctx.integer("fibre_length"));
  // Ring offset: a slow random wander along the grain, about half a ring period.
  Field wander = whiteNoise(n, 1, rng);
  boxBlur(wander, std::max(1, n / 4), 0);
  standardise(wander);
  Field rings(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      rings.at(i, j) =
          std::cos(2.0 * kPi * (j + 0.5 * ring_period * wander.at(i, 0)) / ring_period);
    }
  }
  const double share = ctx.number("ring_share");
  Field heights(n, n);
  addScaled(heights, std::move(fibres), 1.0 - share);
  addScaled(heights, std::move(rings), share);
  return finish(std::move(heights), ctx.number("slope"), ctx.axisRadians("axis"));
}

// cut_pvc: tool marks across the axis (asymmetric grooves of random depth) plus fine noise.
Field makeCutPvc(const GeneratorContext& ctx) {
  const int n = ctx.size();
  const double period = ctx.number("mark_period");
  const double rise = std::tan(ctx.number("mark_angle") * kPi / 180.0);
  // Each groove: a cut rising over 3/4 of the period, a face three times steeper falling back.
  const PeriodicProfile groove({{0.75 * period, rise}, {0.25 * period, -3.0 * rise}});
  Rng rng(ctx.seed());
  const auto grooves = static_cast<int>(std::ceil(n / period));
  std::vector<double> depth(static_cast<size_t>(grooves));
  for (double& d : depth) d = 0.5 + rng.uniform();
  Field heights(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = i + 0.5;
      const auto k = static_cast<int>(std::floor(x / period)) % grooves;
      heights.at(i, j) = depth[static_cast<size_t>(k)] * groove.height(x);
    }
  }
  // Fine noise on top, at its own slope.
  Field noise = bumps(n, rng, 1);
  scaleToRmsSlope(noise, ctx.number("noise_slope"), Edge::Wrap);
  for (size_t k = 0; k < heights.values.size(); ++k) heights.values[k] += noise.values[k];
  if (const double axis = ctx.axisRadians("axis"); axis != 0.0) {
    heights = rotated(heights, axis);
  }
  return heights;
}

// stone: octaves of bumps of radius 1, 2, 4, ..., each contributing equal slope.
Field makeStone(const GeneratorContext& ctx) {
  const int n = ctx.size();
  Rng rng(ctx.seed());
  Field heights(n, n);
  for (int o = 0; o < ctx.integer("octaves"); ++o) {
    addScaled(heights, bumps(n, rng, 1 << o), 1.0);
  }
  return finish(std::move(heights), ctx.number("slope"), 0.0);
}

// metal: brushed, fine scratches along the axis.
Field makeMetal(const GeneratorContext& ctx) {
  Rng rng(ctx.seed());
  Field heights = streaks(ctx.size(), rng, ctx.integer("streak_length"));
  return finish(std::move(heights), ctx.number("slope"), ctx.axisRadians("axis"));
}

GeneratorParam slopeParam(double value) {
  return numberParam("slope", value, 0.0, 10.0,
                     "root mean square of the slope magnitude (-); 0 gives a flat map");
}

}  // namespace

std::vector<GeneratorEntry> materialGenerators() {
  std::vector<GeneratorEntry> e;
  e.push_back(heightEntry({"acrylic", "acrylic: near-flat, tiny fine noise (Fig. 15)", {slopeParam(0.01)}},
               [](const GeneratorContext& ctx) { return makeIsotropic(ctx, 1); }));
  e.push_back(heightEntry(
      {"oak",
        "oak: grain along the axis (slopes across the grain much larger than along it) with "
        "wandering growth-ring streaks (Fig. 15)",
        {slopeParam(0.25),
         numberParam("fibre_length", 24, 1, 8192, "fibre streak length, a whole number (texels)"),
         numberParam("ring_period", 20, 2, 8192, "spacing of growth rings (texels)"),
         numberParam("ring_share", 0.5, 0, 1, "fraction of the slope from rings (-)"),
         axisParam("0", "grain direction")}},
       makeOak));
  e.push_back(heightEntry({"cut_pvc",
                "cut PVC: tool marks across the axis (asymmetric grooves of random depth) and fine "
                "noise; the roughest of acrylic < oak < cut_pvc (Fig. 15)",
                {numberParam("mark_period", 8, 2, 1024, "tool mark spacing (texels)"),
                 numberParam("mark_angle", 20, 0, 80, "tilt of the long face of a mark (degrees)"),
                 numberParam("noise_slope", 0.15, 0, 10, "rms slope of the fine noise (-)"),
                 axisParam("0", "direction across the marks")}},
               makeCutPvc));
  e.push_back(heightEntry(
      {"plaster",
        "plaster: smooth-ish isotropic bumps (Fig. 9's boxes)",
        {slopeParam(0.2),
         numberParam("bump_radius", 3, 1, 256, "bump radius, a whole number (texels)")}},
       [](const GeneratorContext& ctx) { return makeIsotropic(ctx, ctx.integer("bump_radius")); }));
  e.push_back(heightEntry(
      {"stone",
        "stone: rough isotropic multi-scale bumps (Fig. 16)",
        {slopeParam(0.8), numberParam("octaves", 5, 1, 8, "number of scales, a whole number (-)")}},
       makeStone));
  e.push_back(heightEntry(
      {"metal",
        "metal: brushed, fine anisotropic scratches, low (Fig. 16)",
        {slopeParam(0.08),
         numberParam("streak_length", 48, 1, 8192, "scratch length, a whole number (texels)"),
         axisParam("0", "brushing direction")}},
       makeMetal));
  e.push_back(heightEntry({"plastic",
                "plastic: smooth, very low bumps (Fig. 16); slope 0 is the perfectly smooth "
                "plastic of Fig. 9 (Ra = 0)",
                {slopeParam(0.02)}},
               [](const GeneratorContext& ctx) { return makeIsotropic(ctx, 4); }));
  return e;
}

}  // namespace asperity::texgen
