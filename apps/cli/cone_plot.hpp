// The friction-cone figure of `asperity cone` (after the paper's Fig. 8): thumbnails of the
// normal maps of B and A, and the polar polygon of mu_{d_k} with the box limit surface over
// it. One cairo drawing routine renders both the SVG and the PNG, so they look the same.
#pragma once

#include <string>

#include "asperity/friction/directions.hpp"
#include "asperity/friction/limit_surface.hpp"
#include "asperity/texture/normal_map.hpp"

namespace asperity::cli {

struct ConePlot {
  const NormalMap* b = nullptr;  // required
  const NormalMap* a = nullptr;  // null: flat A
  std::string b_name;            // labels (file names)
  std::string a_name;
  std::string subtitle;  // e.g. the gains
  DirectionalMu mu;
  BoxLimit box;
};

// Figure size in pixels (SVG: points).
inline constexpr int kConePlotWidth = 900;
inline constexpr int kConePlotHeight = 420;

// Throw asperity::Error naming the file when it cannot be written.
void writeConePlotSvg(const ConePlot& plot, const std::string& path);
void writeConePlotPng(const ConePlot& plot, const std::string& path);

}  // namespace asperity::cli
