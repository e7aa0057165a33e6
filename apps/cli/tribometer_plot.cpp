#include "tribometer_plot.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "polar_plot.hpp"

namespace asperity::cli {
namespace {

using plot::Align;
using plot::text;

// Layout (pixels), as the cone figure's: thumbnails, polar plot, legend.
constexpr int kWidth = 900;
constexpr int kHeight = 420;
constexpr double kThumb = 140.0;
constexpr double kThumbX = 24.0;
constexpr double kPolarCx = 382.0;
constexpr double kPolarCy = 240.0;
constexpr double kPolarRadius = 140.0;
constexpr double kLegendX = 590.0;

// mu_k solid blue with dots, mu_s red with smaller dots, mu_model dashed green.
constexpr plot::CurveStyle kKineticStyle{plot::kBlue, 0.0, 2.0, false, 3.5, true};
constexpr plot::CurveStyle kStaticStyle{plot::kRed, 0.0, 1.5, false, 3.0, true};
constexpr plot::CurveStyle kModelStyle{plot::kGreen, 0.0, 2.0, true, 0.0, true};

// One coefficient per direction, NaN where the test gave none.
std::vector<double> column(const TribometerResult& r,
                           std::optional<double> TribometerDirection::*f) {
  std::vector<double> values;
  for (const TribometerDirection& d : r.directions) values.push_back((d.*f).value_or(std::nan("")));
  return values;
}

// The largest coefficient shown, so that the plot fits every curve.
double extent(const TribometerResult& r) {
  double m = 0.0;
  for (const TribometerDirection& d : r.directions)
    m = std::max({m, d.mu_model.value_or(0.0), d.mu_s.value_or(0.0), d.mu_k.value_or(0.0)});
  return m > 1e-12 ? m : 0.1;
}

// The legend: the three curves, and what the axes and directions mean.
void drawLegend(cairo_t* cr, const TribometerResult& r) {
  const double x = kLegendX, y = 100.0;
  plot::drawLegendEntry(cr, x, y, kStaticStyle, "mu_s: tilt table");
  plot::drawLegendEntry(cr, x, y + 27.0, kKineticStyle, "mu_k: drag test");
  plot::drawLegendEntry(cr, x, y + 54.0, kModelStyle, "mu_model: the contacts' mu");
  int gaps = 0;
  for (const TribometerDirection& d : r.directions) gaps += !d.mu_s || !d.mu_k;
  if (gaps > 0) text(cr, "gaps: no slide / no steady sliding", x, y + 90.0, 12.0, Align::Left);
  text(cr, "radius: mu against sliding toward", x, y + 165.0, 12.0, Align::Left);
  text(cr, "that direction; u, v: the plate's axes", x, y + 183.0, 12.0, Align::Left);
}

// The whole figure.
void drawTribometerPlot(cairo_t* cr, const TribometerPlot& p) {
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  text(cr,
       "Tribometer: block A = " +
           (p.block ? plot::shortName(p.block_name, 36) : std::string("flat")) +
           " on plate B = " + (p.plate ? plot::shortName(p.plate_name, 36) : std::string("flat")),
       kThumbX, 30.0, 16.0, Align::Left, true);
  text(cr, p.subtitle, kThumbX, 52.0, 12.0, Align::Left);
  const auto label = [](const char* side, const std::string& name) {
    return std::string(side) + (name.empty() ? "flat" : plot::shortName(name, 18));
  };
  plot::drawThumbnail(cr, p.plate, label("B: ", p.plate_name), kThumbX, 92.0, kThumb);
  plot::drawThumbnail(cr, p.block, label("A: ", p.block_name), kThumbX, 268.0, kThumb);
  // Curves over the axes (mu_model dashed on top, where it mostly covers mu_k), tick labels
  // above them.
  const plot::PolarAxes axes = plot::polarAxes(kPolarCx, kPolarCy, kPolarRadius, extent(p.result));
  plot::drawAxes(cr, axes, "u", "v");
  std::vector<double> angles;
  for (const TribometerDirection& d : p.result.directions)
    angles.push_back(d.angle_deg * kPi / 180.0);
  plot::drawCurve(cr, axes, angles, column(p.result, &TribometerDirection::mu_s), kStaticStyle);
  plot::drawCurve(cr, axes, angles, column(p.result, &TribometerDirection::mu_k), kKineticStyle);
  plot::drawCurve(cr, axes, angles, column(p.result, &TribometerDirection::mu_model), kModelStyle);
  plot::drawTickLabels(cr, axes);
  drawLegend(cr, p.result);
}

}  // namespace

void writeTribometerPlot(const TribometerPlot& plot, const std::string& path, bool svg) {
  plot::writeFigure(path, svg, kWidth, kHeight, [&](cairo_t* cr) { drawTribometerPlot(cr, plot); });
}

}  // namespace asperity::cli
