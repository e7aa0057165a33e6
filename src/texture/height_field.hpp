// Private height fields for the generators: heights in texel units (a height of 1 equals one
// texel's width), turned into normal maps by central differences.
#pragma once

#include <cmath>
#include <vector>

#include "asperity/texture/normal_map.hpp"
#include "texture/generator_support.hpp"

namespace asperity::texgen {

// How central differences treat the border: Wrap for tiling textures, Clamp for pictures.
enum class Edge { Wrap, Clamp };

// Bilinear value of a tiling grid at texel coordinates (x, y) (texel centres at integers), in
// the grid's own scalar type; `at(i, j)` reads texel (i, j). The base index is reduced first so
// huge coordinates stay in int range.
template <typename Real, typename At>
Real bilinearWrapped(Real x, Real y, int width, int height, const At& at) {
  const Real fx = std::floor(x);
  const Real fy = std::floor(y);
  const Real wx = x - fx;
  const Real wy = y - fy;
  const int i = wrapTexel(static_cast<int>(std::fmod(fx, static_cast<Real>(width))), width);
  const int j = wrapTexel(static_cast<int>(std::fmod(fy, static_cast<Real>(height))), height);
  const int i1 = wrapTexel(i + 1, width);
  const int j1 = wrapTexel(j + 1, height);
  return (1 - wy) * ((1 - wx) * at(i, j) + wx * at(i1, j)) +
         wy * ((1 - wx) * at(i, j1) + wx * at(i1, j1));
}

// A scalar field over texels; (i, j) as in NormalMap (i along +u, j along +v).
struct Field {
  int width = 0;
  int height = 0;
  std::vector<double> values;

  Field() = default;
  Field(int w, int h, double fill = 0.0);
  double& at(int i, int j) { return values[static_cast<size_t>(j) * width + i]; }
  double at(int i, int j) const { return values[static_cast<size_t>(j) * width + i]; }
  // Index with wrap-around or clamping.
  double get(int i, int j, Edge edge) const;
  // Bilinear value at continuous texel coordinates (texel centres at integers), wrapping.
  double sampleWrapped(double x, double y) const;
};

// Independent N(0, 1) heights per texel, in row order (deterministic for the Rng's seed).
Field whiteNoise(int width, int height, Rng& rng);

// Separable box blur with wrap-around: radius rx along i and ry along j (0 = none), repeated
// `passes` times (three passes approximate a Gaussian).
void boxBlur(Field& field, int rx, int ry, int passes = 3);

// Scales so the mean is zero and the standard deviation is one (flat fields stay zero).
void standardise(Field& field);

// The field rotated by `radians` (texture content turned from +u toward +v), sampled with
// wrap-around. Multiples of 90 degrees map texels exactly and keep the texture tileable.
Field rotated(const Field& field, double radians);

// Slopes (dh/di, dh/dj) by central differences.
double slopeU(const Field& h, int i, int j, Edge edge);
double slopeV(const Field& h, int i, int j, Edge edge);

// Root mean square of the slope magnitude over the field.
double rmsSlope(const Field& h, Edge edge);

// Scales the heights so that rmsSlope() equals `target` (a flat field stays flat).
void scaleToRmsSlope(Field& h, double target, Edge edge);

// Normal map m = normalize(-dh/di, -dh/dj, 1) with heights multiplied by `scale`.
NormalMap normalsFromHeights(const Field& h, double scale, Edge edge);

}  // namespace asperity::texgen
