// The model's terms for calibration (calibrate.hpp, modelTerms): per sliding direction, what the
// block's and the plate's textures add to mu with unit gains, as the sampler gives them to the
// tribometer's sliding block, or as the whole-texture cone has them.
#include <algorithm>
#include <cmath>
#include <map>

#include "asperity/error.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/tribometer/calibrate.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

namespace {

constexpr int kConeDirections = 64;

// The surfaces with unit gain on one side only (0: the block's, 1: the plate's).
TribometerSurfaces oneSide(const TribometerSurfaces& surfaces, int side) {
  TribometerSurfaces s = surfaces;
  s.block.gain = side == 0 ? 1.0 : 0.0;
  s.plate.gain = side == 1 ? 1.0 : 0.0;
  return s;
}

// The sampler's terms at each angle: the drag test's mu_model with unit gain on one side (none
// for a flat side), mu0 = 0; the angles' and sides' runs side by side on the pool.
ModelTerms samplerTerms(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                        std::span<const double> angles) {
  TribometerSettings zero = settings;
  zero.friction.mu0 = 0.0;
  zero.tilt = false;
  zero.drag = true;
  std::vector<double> jobs(2 * angles.size(), 0.0);
  const ThreadPool pool(settings.threads);
  pool.forEach(jobs.size(), 1, [&](size_t job) {
    const int side = static_cast<int>(job % 2);
    if (!(side == 0 ? surfaces.block : surfaces.plate).normal_map) return;
    jobs[job] = runDragTest(oneSide(surfaces, side), zero, angles[job / 2]).mu_model;
  });
  ModelTerms terms;
  for (size_t i = 0; i < angles.size(); ++i) {
    terms.block.push_back(jobs[2 * i]);
    terms.plate.push_back(jobs[2 * i + 1]);
  }
  return terms;
}

// One texture's whole-texture cone (flatPatchCone) on its side, unit gain; zero when flat.
DirectionalMu sideCone(const Surface& surface, bool block, const FrictionSettings& friction) {
  if (!surface.normal_map) return DirectionalMu::uniform(kConeDirections, 0.0f);
  PatchConeOptions opt;
  opt.directions = kConeDirections;
  opt.gains = {0.0, block ? 1.0 : 0.0, block ? 0.0 : 1.0};
  opt.mu_max = friction.mu_max;
  const NormalMap flat(1, 1);
  return block ? flatPatchCone(surface.normal_map.get(), flat, opt)
               : flatPatchCone(nullptr, *surface.normal_map, opt);
}

// The cones' terms. Sliding along a resists with the cone's coefficient along a + pi (SPEC 1),
// read in each texture's axes: the plate's u is at its rotation r, so at a + pi - r; the
// block's bottom face mirrors v (u at -r, v at -r - pi/2), which flatPatchCone's A side already
// does for r = 0, so at a + pi + r.
ModelTerms coneTerms(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                     std::span<const double> angles) {
  const DirectionalMu block = sideCone(surfaces.block, true, settings.friction);
  const DirectionalMu plate = sideCone(surfaces.plate, false, settings.friction);
  ModelTerms terms;
  for (double deg : angles) {
    const double a = deg * kPi / 180.0 + kPi;
    terms.block.push_back(block.along(a + surfaces.block.texture_rotation));
    terms.plate.push_back(plate.along(a - surfaces.plate.texture_rotation));
  }
  return terms;
}

}  // namespace

ModelTerms modelTerms(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                      std::span<const double> angles_deg, ModelKind kind) {
  validateTribometerSettings(settings);
  // Each distinct angle once, then the terms row by row.
  std::map<double, size_t> index;
  std::vector<double> distinct;
  for (double a : angles_deg)
    if (index.emplace(a, distinct.size()).second) distinct.push_back(a);
  const ModelTerms once = kind == ModelKind::Cone ? coneTerms(surfaces, settings, distinct)
                                                  : samplerTerms(surfaces, settings, distinct);
  ModelTerms terms;
  for (double a : angles_deg) {
    terms.block.push_back(once.block[index[a]]);
    terms.plate.push_back(once.plate[index[a]]);
  }
  return terms;
}

}  // namespace asperity
