// Shared pieces of the render tests: one headless context per test program, small scenes,
// and image statistics.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "asperity/gl/context.hpp"
#include "asperity/render/renderer.hpp"
#include "asperity/texture/generators.hpp"

namespace asperity::test {

// The headless context every GL test uses. Creating it must succeed (CI has llvmpipe): a
// failure is a test failure, never a skip.
inline gl::GlContext& sharedContext() {
  static std::unique_ptr<gl::GlContext> context = std::make_unique<gl::GlContext>();
  context->makeCurrent();
  return *context;
}

// A Gaussian-slope normal map (SPEC 2), rough enough to see.
inline std::shared_ptr<const NormalMap> roughMap(double slope = 0.8) {
  GeneratorSpec spec;
  spec.name = "gaussian";
  spec.params = {{"sx", std::to_string(slope)}, {"sy", std::to_string(slope)}};
  spec.size = 64;
  spec.seed = 3;
  return std::make_shared<const NormalMap>(generateNormalMap(spec));
}

// Mean absolute difference of two images of the same size, per channel (0..255).
inline double meanAbsDifference(const render::Image& a, const render::Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
  return sum / static_cast<double>(a.rgb.size());
}

// Standard deviation of the luminance (0..255): 0 for a blank image.
inline double luminanceDeviation(const render::Image& image) {
  double sum = 0.0, sum2 = 0.0;
  const size_t n = image.rgb.size() / 3;
  for (size_t i = 0; i < n; ++i) {
    const double y =
        0.3 * image.rgb[3 * i] + 0.59 * image.rgb[3 * i + 1] + 0.11 * image.rgb[3 * i + 2];
    sum += y;
    sum2 += y * y;
  }
  const double mean = sum / static_cast<double>(n);
  return std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
}

}  // namespace asperity::test
