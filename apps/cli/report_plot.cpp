// Inline SVG line plots (and dot maps) for the experiment report.
#include "report_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace asperity::cli {

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string fmt(const char* format, double x) {
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), format, x);
  return buffer;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // Widened to a non-empty range with a little headroom.
  void finish() {
    if (!(lo <= hi)) lo = 0.0, hi = 1.0;
    if (hi - lo < 1e-12) lo -= 0.5, hi += 0.5;
  }
};

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about `count` ticks.
double tickStep(double span, int count) {
  const double raw = span / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

// Axis ticks and grid lines; `vertical` = the y axis.
std::string ticks(const Range& r, bool vertical, double x0, double y0, double w, double h) {
  std::string s;
  const double step = tickStep(r.hi - r.lo, 5);
  for (double v = std::ceil(r.lo / step) * step; v <= r.hi + 1e-9 * step; v += step) {
    const double f = (v - r.lo) / (r.hi - r.lo);
    const std::string label = fmt("%g", std::abs(v) < 1e-12 * step ? 0.0 : v);
    if (vertical) {
      const double y = y0 + h - f * h;
      s += "<line x1='" + fmt("%.1f", x0) + "' x2='" + fmt("%.1f", x0 + w) + "' y1='" +
           fmt("%.1f", y) + "' y2='" + fmt("%.1f", y) + "' class='grid'/>";
      s += "<text x='" + fmt("%.1f", x0 - 6) + "' y='" + fmt("%.1f", y + 4) +
           "' text-anchor='end'>" + label + "</text>";
    } else {
      const double x = x0 + f * w;
      s += "<line x1='" + fmt("%.1f", x) + "' x2='" + fmt("%.1f", x) + "' y1='" + fmt("%.1f", y0) +
           "' y2='" + fmt("%.1f", y0 + h) + "' class='grid'/>";
      s += "<text x='" + fmt("%.1f", x) + "' y='" + fmt("%.1f", y0 + h + 16) +
           "' text-anchor='middle'>" + label + "</text>";
    }
  }
  return s;
}

}  // namespace

std::string svgPlot(const experiments::Plot& plot, int width, int height) {
  // Data ranges over every series.
  Range rx, ry;
  for (const auto& s : plot.series) {
    for (double x : s.x) rx.add(x);
    for (double y : s.y) ry.add(y);
  }
  rx.finish();
  ry.finish();
  const double pad = 0.05 * (ry.hi - ry.lo);
  ry.lo -= pad;
  ry.hi += pad;
  // Plot area inside margins for tick labels, axis titles and the legend.
  const double x0 = 62, y0 = 30, w = width - 62 - 130, h = height - 30 - 46;
  std::string s = "<svg xmlns='http://www.w3.org/2000/svg' class='plot' width='" +
                  std::to_string(width) + "' height='" + std::to_string(height) +
                  "' viewBox='0 0 " + std::to_string(width) + " " + std::to_string(height) + "'>";
  s += "<text x='" + fmt("%.1f", x0) + "' y='18' class='title'>" + htmlEscape(plot.title) +
       "</text>";
  s += ticks(rx, false, x0, y0, w, h) + ticks(ry, true, x0, y0, w, h);
  s += "<rect x='" + fmt("%.1f", x0) + "' y='" + fmt("%.1f", y0) + "' width='" + fmt("%.1f", w) +
       "' height='" + fmt("%.1f", h) + "' class='frame'/>";
  s += "<text x='" + fmt("%.1f", x0 + w / 2) + "' y='" + fmt("%.1f", y0 + h + 36) +
       "' text-anchor='middle'>" + htmlEscape(plot.x_label) + "</text>";
  s += "<text transform='translate(14," + fmt("%.1f", y0 + h / 2) +
       ") rotate(-90)' text-anchor='middle'>" + htmlEscape(plot.y_label) + "</text>";
  // One polyline per series, and its legend entry.
  for (size_t i = 0; i < plot.series.size(); ++i) {
    const auto& ser = plot.series[i];
    const char* colour = kPalette[i % (sizeof(kPalette) / sizeof(kPalette[0]))];
    std::string points;
    for (size_t k = 0; k < ser.x.size() && k < ser.y.size(); ++k) {
      if (!std::isfinite(ser.x[k]) || !std::isfinite(ser.y[k])) continue;
      const double px = x0 + (ser.x[k] - rx.lo) / (rx.hi - rx.lo) * w;
      const double py = y0 + h - (ser.y[k] - ry.lo) / (ry.hi - ry.lo) * h;
      if (ser.dots) {
        s += "<circle cx='" + fmt("%.1f", px) + "' cy='" + fmt("%.1f", py) + "' r='5' fill='" +
             colour + "'/>";
      } else {
        points += fmt("%.1f", px) + "," + fmt("%.1f", py) + " ";
      }
    }
    if (!ser.dots) {
      s += "<polyline fill='none' stroke='" + std::string(colour) + "' stroke-width='2' points='" +
           points + "'/>";
    }
    const double ly = y0 + 8 + 20.0 * static_cast<double>(i);
    if (ser.dots) {
      s += "<circle cx='" + fmt("%.1f", x0 + w + 22) + "' cy='" + fmt("%.1f", ly) +
           "' r='5' fill='" + colour + "'/>";
    } else {
      s += "<line x1='" + fmt("%.1f", x0 + w + 12) + "' x2='" + fmt("%.1f", x0 + w + 32) +
           "' y1='" + fmt("%.1f", ly) + "' y2='" + fmt("%.1f", ly) + "' stroke='" + colour +
           "' stroke-width='3'/>";
    }
    s += "<text x='" + fmt("%.1f", x0 + w + 38) + "' y='" + fmt("%.1f", ly + 4) + "'>" +
         htmlEscape(ser.label) + "</text>";
  }
  s += "</svg>";
  return s;
}

}  // namespace asperity::cli
