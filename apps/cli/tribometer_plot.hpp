// The figure of `asperity tribometer`: thumbnails of the plate's (B) and the block's (A) normal
// maps, and polar curves of mu_s, mu_k and mu_model against the sliding direction, drawn with
// the cone figure's pieces (polar_plot.hpp).
#pragma once

#include <string>

#include "asperity/texture/normal_map.hpp"
#include "asperity/tribometer/tribometer.hpp"

namespace asperity::cli {

struct TribometerPlot {
  const NormalMap* plate = nullptr;  // null: flat
  const NormalMap* block = nullptr;  // null: flat
  std::string plate_name;
  std::string block_name;
  std::string subtitle;
  TribometerResult result;
};

// Throw asperity::Error naming the file when it cannot be written.
void writeTribometerPlot(const TribometerPlot& plot, const std::string& path, bool svg);

}  // namespace asperity::cli
