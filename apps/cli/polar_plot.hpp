// Drawing pieces shared by the CLI's polar figures (`asperity cone`, `tribometer`, `calibrate`):
// text, normal-map thumbnails, polar axes with ticks, curves of a coefficient against the
// direction, and one routine that writes a drawing as SVG or PNG. cairo underneath.
#pragma once

#include <cairo.h>

#include <functional>
#include <span>
#include <string>

#include "asperity/texture/normal_map.hpp"

namespace asperity::cli::plot {

// The layout every polar figure shares (pixels): thumbnails at the left, the polar plot, the
// legend at the right (asperity cone's, the tribometer's and the calibration's figures).
constexpr double kThumb = 140.0;
constexpr double kThumbX = 24.0;
constexpr double kThumbBY = 92.0;   // surface B's thumbnail
constexpr double kThumbAY = 268.0;  // surface A's thumbnail
constexpr double kPolarCx = 382.0;
constexpr double kPolarCy = 240.0;
constexpr double kPolarRadius = 140.0;  // the outermost tick
constexpr double kLegendX = 590.0;

enum class Align { Left, Center, Right };

struct Colour {
  double r = 0.0, g = 0.0, b = 0.0;
};
// A colour-blind safe set: blue, red, green, and the greys of axes and grid.
inline constexpr Colour kBlue{0.12, 0.42, 0.72};
inline constexpr Colour kRed{0.84, 0.20, 0.16};
inline constexpr Colour kGreen{0.20, 0.60, 0.25};

// One line of text with its baseline at y, aligned horizontally at x.
void text(cairo_t* cr, const std::string& s, double x, double y, double size, Align align,
          bool bold = false, bool italic = false);

// The file name without its folders, shortened to at most `max_chars` characters.
std::string shortName(const std::string& path, size_t max_chars);

// A labelled thumbnail of a normal map (RGB = (m + 1) / 2), side `side` pixels with its top-left
// corner at (x, y); a grey square marked "flat" when `map` is null or empty.
void drawThumbnail(cairo_t* cr, const NormalMap* map, const std::string& label, double x, double y,
                   double side);

// Polar axes: t to the right and b up through (cx, cy), ticks every `step` out to `radius`
// pixels; `scale` is pixels per unit of the coefficient.
struct PolarAxes {
  double cx = 0.0, cy = 0.0, radius = 0.0;
  double step = 1.0;
  int ticks = 1;
  double scale = 1.0;
};
// Axes that show coefficients up to `extent` (> 0) within `radius` pixels.
PolarAxes polarAxes(double cx, double cy, double radius, double extent);
// Grid circles, the axes with arrows and labels `t_label` and `b_label`, tick marks.
void drawAxes(cairo_t* cr, const PolarAxes& axes, const std::string& t_label = "t",
              const std::string& b_label = "b");
// Numeric tick labels on both axes (drawn last, above the curves).
void drawTickLabels(cairo_t* cr, const PolarAxes& axes);

// How a curve through points mu_k at angles a_k looks.
struct CurveStyle {
  Colour colour = kBlue;
  double fill_alpha = 0.0;  // 0: no fill
  double width = 2.0;
  bool dashed = false;
  double marker = 3.5;  // radius of the dots at the points; 0: none
  bool closed = true;   // joins the last point to the first
};
// The curve through mu[k] (angle[k], radians from t toward b). NaN values are gaps: the curve
// breaks there and no dot is drawn.
void drawCurve(cairo_t* cr, const PolarAxes& axes, std::span<const double> angles,
               std::span<const double> mu, const CurveStyle& style);
// A legend entry: a short sample of the curve's line and its label, baseline at y.
void drawLegendEntry(cairo_t* cr, double x, double y, const CurveStyle& style,
                     const std::string& label);

// Writes `draw` on a white width x height page as SVG or PNG (by `svg`). Throws
// asperity::Error naming the file when it cannot be written.
void writeFigure(const std::string& path, bool svg, int width, int height,
                 const std::function<void(cairo_t*)>& draw);

}  // namespace asperity::cli::plot
