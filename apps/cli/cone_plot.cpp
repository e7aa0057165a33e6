#include "cone_plot.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "polar_plot.hpp"

namespace asperity::cli {
namespace {

using plot::Align;
using plot::text;

using namespace plot;  // the shared layout (polar_plot.hpp)

// The polygon of mu_d (translucent fill, dots at the samples) and the box (dashed).
constexpr plot::CurveStyle kPolygonStyle{plot::kBlue, 0.22, 2.0, false, 3.5, true};
constexpr plot::CurveStyle kBoxStyle{plot::kRed, 0.0, 2.0, true, 0.0, true};

// The largest coefficient shown (polygon and box), so the plot fits everything.
double plotExtent(const ConePlot& plot) {
  double m = std::max({plot.box.mu_pos_t, plot.box.mu_pos_b, plot.box.mu_neg_t, plot.box.mu_neg_b});
  for (int k = 0; k < plot.mu.count; ++k) m = std::max(m, static_cast<double>(plot.mu.mu[k]));
  return m > 1e-12 ? m : 0.1;
}

// The star polygon through mu_k d_k (SPEC 4).
void drawPolygon(cairo_t* cr, const plot::PolarAxes& axes, const DirectionalMu& mu) {
  std::vector<double> angles, values;
  for (int k = 0; k < mu.count; ++k) {
    angles.push_back(2.0 * kPi * k / mu.count);
    values.push_back(mu.mu[k]);
  }
  plot::drawCurve(cr, axes, angles, values, kPolygonStyle);
}

// The box (Eq. 9): lambda_t in [-mu_{-t}, mu_{+t}], lambda_b in [-mu_{-b}, mu_{+b}], dashed.
void drawBox(cairo_t* cr, const plot::PolarAxes& axes, const BoxLimit& box) {
  const double s = axes.scale;
  const double dash[2] = {7.0, 4.0};
  cairo_set_dash(cr, dash, 2, 0.0);
  cairo_set_source_rgb(cr, plot::kRed.r, plot::kRed.g, plot::kRed.b);
  cairo_set_line_width(cr, 2.0);
  cairo_rectangle(cr, axes.cx - box.mu_neg_t * s, axes.cy - box.mu_pos_b * s,
                  (box.mu_neg_t + box.mu_pos_t) * s, (box.mu_neg_b + box.mu_pos_b) * s);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// Legend (polygon, box) and the box's four coefficients.
void drawLegend(cairo_t* cr, const ConePlot& plot) {
  const double x = kLegendX, y = 100.0;
  plot::drawLegendEntry(cr, x, y, kPolygonStyle,
                        "polygon: mu_d, N = " + std::to_string(plot.mu.count) + " directions");
  plot::drawLegendEntry(cr, x, y + 27.0, kBoxStyle, "box (Eq. 9): +t, +b, -t, -b");
  // The box's coefficients, as numbers.
  const std::pair<const char*, double> rows[4] = {{"mu(+t)", plot.box.mu_pos_t},
                                                  {"mu(+b)", plot.box.mu_pos_b},
                                                  {"mu(-t)", plot.box.mu_neg_t},
                                                  {"mu(-b)", plot.box.mu_neg_b}};
  for (int i = 0; i < 4; ++i) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%s = %.4f", rows[i].first, rows[i].second);
    text(cr, buf, x + 38.0, y + 70.0 + 20.0 * i, 13.0, Align::Left);
  }
  text(cr, "axes: mu along t and b (dimensionless)", x, y + 165.0, 12.0, Align::Left);
  text(cr, "directions from t toward b", x, y + 183.0, 12.0, Align::Left);
}

// The one drawing routine behind both outputs.
void drawConePlot(cairo_t* cr, const ConePlot& plot) {
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  text(cr,
       "Friction limit surface: B = " + plot::shortName(plot.b_name, 40) +
           ", A = " + (plot.a ? plot::shortName(plot.a_name, 40) : std::string("flat")),
       kThumbX, 30.0, 16.0, Align::Left, true);
  text(cr, plot.subtitle, kThumbX, 52.0, 12.0, Align::Left);
  plot::drawThumbnail(cr, plot.b, "B: " + plot::shortName(plot.b_name, 18), kThumbX, kThumbBY,
                      kThumb);
  plot::drawThumbnail(cr, plot.a, plot.a ? "A: " + plot::shortName(plot.a_name, 18) : "A: flat",
                      kThumbX, kThumbAY, kThumb);
  const plot::PolarAxes axes = plot::polarAxes(kPolarCx, kPolarCy, kPolarRadius, plotExtent(plot));
  plot::drawAxes(cr, axes);
  drawPolygon(cr, axes, plot.mu);
  drawBox(cr, axes, plot.box);
  plot::drawTickLabels(cr, axes);
  drawLegend(cr, plot);
}

}  // namespace

void writeConePlotSvg(const ConePlot& plot, const std::string& path) {
  plot::writeFigure(path, true, kConePlotWidth, kConePlotHeight,
                    [&](cairo_t* cr) { drawConePlot(cr, plot); });
}

void writeConePlotPng(const ConePlot& plot, const std::string& path) {
  plot::writeFigure(path, false, kConePlotWidth, kConePlotHeight,
                    [&](cairo_t* cr) { drawConePlot(cr, plot); });
}

}  // namespace asperity::cli
