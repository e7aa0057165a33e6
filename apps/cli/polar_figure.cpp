#include "polar_figure.hpp"

#include <algorithm>
#include <cmath>

namespace asperity::cli {
namespace {

using plot::Align;
using plot::text;

using namespace plot;  // the shared layout (polar_plot.hpp)

// The figure's size (pixels), as the cone figure's.
constexpr int kWidth = 900;
constexpr int kHeight = 420;

// The largest coefficient shown, so that the plot fits every curve.
double extent(const PolarFigure& f) {
  double m = 0.0;
  for (const PolarCurve& c : f.curves)
    for (double v : c.values)
      if (std::isfinite(v)) m = std::max(m, v);
  return m > 1e-12 ? m : 0.1;
}

// The legend: one entry per curve, then the notes.
void drawLegend(cairo_t* cr, const PolarFigure& f) {
  double y = 100.0;
  for (const PolarCurve& c : f.curves) {
    plot::drawLegendEntry(cr, kLegendX, y, c.style, c.label);
    y += 27.0;
  }
  y += 20.0;
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  for (const std::string& note : f.notes) {
    text(cr, note, kLegendX, y, 12.0, Align::Left);
    y += 18.0;
  }
}

// The whole figure: title, thumbnails, axes, curves, tick labels, legend.
void drawFigure(cairo_t* cr, const PolarFigure& f) {
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  text(cr, f.title, kThumbX, 30.0, 16.0, Align::Left, true);
  text(cr, f.subtitle, kThumbX, 52.0, 12.0, Align::Left);
  const auto label = [](const char* side, const std::string& name) {
    return std::string(side) + (name.empty() ? "flat" : plot::shortName(name, 18));
  };
  plot::drawThumbnail(cr, f.plate, label("B: ", f.plate_name), kThumbX, kThumbBY, kThumb);
  plot::drawThumbnail(cr, f.block, label("A: ", f.block_name), kThumbX, kThumbAY, kThumb);
  const plot::PolarAxes axes = plot::polarAxes(kPolarCx, kPolarCy, kPolarRadius, extent(f));
  plot::drawAxes(cr, axes, "u", "v");
  for (const PolarCurve& c : f.curves) {
    std::vector<double> radians;
    for (double a : c.angles_deg) radians.push_back(a * kPi / 180.0);
    plot::drawCurve(cr, axes, radians, c.values, c.style);
  }
  plot::drawTickLabels(cr, axes);
  drawLegend(cr, f);
}

}  // namespace

void writePolarFigure(const PolarFigure& figure, const std::string& path, bool svg) {
  plot::writeFigure(path, svg, kWidth, kHeight, [&](cairo_t* cr) { drawFigure(cr, figure); });
}

}  // namespace asperity::cli
