// Inline SVG line plots for `asperity report`: one plot of experiments::Plot, with axes, ticks,
// a legend and the series in a fixed palette. No scripts, no external files.
#pragma once

#include <string>

#include "experiments/experiment_outcomes.hpp"

namespace asperity::cli {

// An <svg> element (width x height pixels) drawing every series of `plot`.
std::string svgPlot(const experiments::Plot& plot, int width = 560, int height = 300);

// Text escaped for HTML element content and attribute values.
std::string htmlEscape(const std::string& text);

}  // namespace asperity::cli
