// The figure of `asperity tribometer` and `asperity calibrate`: thumbnails of the plate's (B)
// and the block's (A) normal maps, and polar curves of coefficients against the sliding
// direction with their legend, drawn with the cone figure's pieces (polar_plot.hpp).
#pragma once

#include <string>
#include <vector>

#include "asperity/texture/normal_map.hpp"
#include "polar_plot.hpp"

namespace asperity::cli {

// One curve: a coefficient per angle (degrees from the plate's u toward v; NaN: a gap).
struct PolarCurve {
  std::vector<double> angles_deg;
  std::vector<double> values;
  plot::CurveStyle style;
  std::string label;
};

struct PolarFigure {
  const NormalMap* plate = nullptr;  // null: flat
  const NormalMap* block = nullptr;  // null: flat
  std::string plate_name;            // empty: "flat"
  std::string block_name;
  std::string title;
  std::string subtitle;
  std::vector<PolarCurve> curves;  // drawn in order, the last on top
  std::vector<std::string> notes;  // lines under the legend
};

// Throw asperity::Error naming the file when it cannot be written.
void writePolarFigure(const PolarFigure& figure, const std::string& path, bool svg);

}  // namespace asperity::cli
