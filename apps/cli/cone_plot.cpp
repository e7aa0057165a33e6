#include "cone_plot.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include "asperity/error.hpp"

namespace asperity::cli {
namespace {

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

// Layout of the figure (pixels): thumbnails at the left, polar plot, legend at the right.
constexpr double kThumb = 140.0;
constexpr double kThumbX = 24.0;
constexpr double kThumbBY = 92.0;
constexpr double kThumbAY = 268.0;
constexpr double kPolarCx = 382.0;
constexpr double kPolarCy = 240.0;
constexpr double kPolarRadius = 140.0;  // pixels for the outermost tick
constexpr double kLegendX = 590.0;

// Colours: polygon blue, box red (colour-blind safe pair), greys for axes and grid.
constexpr double kBlue[3] = {0.12, 0.42, 0.72};
constexpr double kRed[3] = {0.84, 0.20, 0.16};

enum class Align { Left, Center, Right };

// Draws one line of text with its baseline at y, aligned horizontally at x.
void text(cairo_t* cr, const std::string& s, double x, double y, double size, Align align,
          bool bold = false, bool italic = false) {
  cairo_select_font_face(cr, "DejaVu Sans",
                         italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  double left = x;
  if (align == Align::Center) left = x - ext.x_advance / 2.0;
  if (align == Align::Right) left = x - ext.x_advance;
  cairo_move_to(cr, left, y);
  cairo_show_text(cr, s.c_str());
}

// The file name without its folders, shortened to at most `max_chars` characters.
std::string shortName(const std::string& path, size_t max_chars) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.size() > max_chars) name = name.substr(0, max_chars - 3) + "...";
  return name;
}

// A normal map shown as RGB colours ((m + 1) / 2), box-filtered to side x side pixels. Rows
// are stored bottom-up, so the top pixel row reads the map's last row.
SurfacePtr thumbnail(const NormalMap& map, int side) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, side, side),
                     &cairo_surface_destroy);
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const int64_t w = map.width(), h = map.height();
  for (int py = 0; py < side; ++py) {
    const int64_t r0 = py * h / side, r1 = std::max(r0 + 1, (py + 1) * h / side);
    auto* row = reinterpret_cast<uint32_t*>(data + static_cast<ptrdiff_t>(py) * stride);
    for (int px = 0; px < side; ++px) {
      const int64_t c0 = px * w / side, c1 = std::max(c0 + 1, (px + 1) * w / side);
      // Mean normal over the pixel's texels, then its colour.
      Vec3f sum = Vec3f::Zero();
      for (int64_t r = r0; r < r1; ++r)
        for (int64_t c = c0; c < c1; ++c)
          sum += map.at(static_cast<int>(c), static_cast<int>(h - 1 - r));
      const Vec3f m = sum / static_cast<float>((r1 - r0) * (c1 - c0));
      uint32_t pixel = 0;
      for (int k = 0; k < 3; ++k) {
        const float v = std::clamp((m[k] + 1.0f) * 0.5f, 0.0f, 1.0f);
        pixel = (pixel << 8) | static_cast<uint32_t>(std::lround(v * 255.0f));
      }
      row[px] = pixel;
    }
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

// One labelled thumbnail, or a grey square for a flat (absent) surface.
void drawThumbnail(cairo_t* cr, const NormalMap* map, const std::string& label, double y) {
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  text(cr, label, kThumbX, y - 8.0, 13.0, Align::Left, true);
  if (map != nullptr && !map->empty()) {
    SurfacePtr thumb = thumbnail(*map, static_cast<int>(kThumb));
    cairo_set_source_surface(cr, thumb.get(), kThumbX, y);
    cairo_paint(cr);
  } else {
    cairo_set_source_rgb(cr, 0.5, 0.5, 1.0);  // the colour of the flat normal (0, 0, 1)
    cairo_rectangle(cr, kThumbX, y, kThumb, kThumb);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(cr, "flat", kThumbX + kThumb / 2.0, y + kThumb / 2.0 + 5.0, 13.0, Align::Center);
  }
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, kThumbX + 0.5, y + 0.5, kThumb - 1.0, kThumb - 1.0);
  cairo_stroke(cr);
}

// Tick spacing: 1, 2, 2.5 or 5 times a power of ten, giving about three ticks up to `extent`.
double tickStep(double extent) {
  const double raw = extent / 3.0;
  const double scale = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0})
    if (m * scale >= raw) return m * scale;
  return 10.0 * scale;
}

// A tick label with just enough decimals for the step.
std::string tickLabel(double value, double step) {
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (std::abs(step / std::pow(10.0, -decimals) - std::round(step / std::pow(10.0, -decimals))) >
      1e-6)
    ++decimals;  // 2.5 x 10^k needs one more
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, value);
  return buf;
}

// The largest coefficient shown (polygon and box), so the plot fits everything.
double plotExtent(const ConePlot& plot) {
  double m = std::max({plot.box.mu_pos_t, plot.box.mu_pos_b, plot.box.mu_neg_t, plot.box.mu_neg_b});
  for (int k = 0; k < plot.mu.count; ++k) m = std::max(m, static_cast<double>(plot.mu.mu[k]));
  return m > 1e-12 ? m : 0.1;
}

// Axes t (right) and b (up) through the origin, circles and ticks with labels at each step.
void drawAxes(cairo_t* cr, double step, int ticks) {
  const double s = kPolarRadius / (step * ticks);
  // Grid circles (light) at every tick radius.
  cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
  cairo_set_line_width(cr, 1.0);
  for (int i = 1; i <= ticks; ++i) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, kPolarCx, kPolarCy, i * step * s, 0.0, 2.0 * kPi);
  }
  cairo_stroke(cr);
  // Axis lines with arrow heads.
  const double len = kPolarRadius + 22.0;
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 1.2);
  cairo_move_to(cr, kPolarCx - len, kPolarCy);
  cairo_line_to(cr, kPolarCx + len, kPolarCy);
  cairo_move_to(cr, kPolarCx, kPolarCy + len);
  cairo_line_to(cr, kPolarCx, kPolarCy - len);
  cairo_stroke(cr);
  cairo_move_to(cr, kPolarCx + len + 6.0, kPolarCy);
  cairo_line_to(cr, kPolarCx + len - 4.0, kPolarCy - 4.0);
  cairo_line_to(cr, kPolarCx + len - 4.0, kPolarCy + 4.0);
  cairo_close_path(cr);
  cairo_move_to(cr, kPolarCx, kPolarCy - len - 6.0);
  cairo_line_to(cr, kPolarCx - 4.0, kPolarCy - len + 4.0);
  cairo_line_to(cr, kPolarCx + 4.0, kPolarCy - len + 4.0);
  cairo_close_path(cr);
  cairo_fill(cr);
  text(cr, "t", kPolarCx + len + 10.0, kPolarCy + 5.0, 16.0, Align::Left, true, true);
  text(cr, "b", kPolarCx + 8.0, kPolarCy - len - 2.0, 16.0, Align::Left, true, true);
  // Tick marks on both axes, both signs (mu is dimensionless); labels come last.
  for (int i = -ticks; i <= ticks; ++i) {
    if (i == 0) continue;
    const double off = i * step * s;
    cairo_move_to(cr, kPolarCx + off, kPolarCy - 4.0);
    cairo_line_to(cr, kPolarCx + off, kPolarCy + 4.0);
    cairo_move_to(cr, kPolarCx - 4.0, kPolarCy - off);
    cairo_line_to(cr, kPolarCx + 4.0, kPolarCy - off);
    cairo_stroke(cr);
  }
}

// A tick label over a translucent white patch, so lines under it do not hide it.
void haloLabel(cairo_t* cr, const std::string& s, double x, double y, Align align) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12.0);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  const double left = align == Align::Center  ? x - ext.x_advance / 2.0
                      : align == Align::Right ? x - ext.x_advance
                                              : x;
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.75);
  cairo_rectangle(cr, left - 2.0, y + ext.y_bearing - 1.0, ext.x_advance + 4.0, ext.height + 2.0);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  text(cr, s, x, y, 12.0, align);
}

// Numeric tick labels on both axes (drawn last, above the polygon and the box).
void drawTickLabels(cairo_t* cr, double step, int ticks) {
  const double s = kPolarRadius / (step * ticks);
  for (int i = -ticks; i <= ticks; ++i) {
    if (i == 0) continue;
    const double off = i * step * s;
    const std::string label = tickLabel(i * step, step);
    haloLabel(cr, label, kPolarCx + off, kPolarCy + 18.0, Align::Center);
    haloLabel(cr, label, kPolarCx - 7.0, kPolarCy - off + 4.0, Align::Right);
  }
}

// The star polygon through mu_k d_k (closed, translucent fill, markers at the samples).
void drawPolygon(cairo_t* cr, const DirectionalMu& mu, double s) {
  const std::vector<Vec2> dirs = sampleDirections(mu.count);
  for (int k = 0; k < mu.count; ++k) {
    const double r = mu.mu[k] * s;
    const double x = kPolarCx + r * dirs[k].x(), y = kPolarCy - r * dirs[k].y();
    if (k == 0)
      cairo_move_to(cr, x, y);
    else
      cairo_line_to(cr, x, y);
  }
  cairo_close_path(cr);
  cairo_set_source_rgba(cr, kBlue[0], kBlue[1], kBlue[2], 0.22);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, kBlue[0], kBlue[1], kBlue[2]);
  cairo_set_line_width(cr, 2.0);
  cairo_stroke(cr);
  for (int k = 0; k < mu.count; ++k) {
    const double r = mu.mu[k] * s;
    cairo_new_sub_path(cr);
    cairo_arc(cr, kPolarCx + r * dirs[k].x(), kPolarCy - r * dirs[k].y(), 3.5, 0.0, 2.0 * kPi);
  }
  cairo_fill(cr);
}

// The box (Eq. 9): lambda_t in [-mu_{-t}, mu_{+t}], lambda_b in [-mu_{-b}, mu_{+b}], dashed.
void drawBox(cairo_t* cr, const BoxLimit& box, double s) {
  const double dash[2] = {7.0, 4.0};
  cairo_set_dash(cr, dash, 2, 0.0);
  cairo_set_source_rgb(cr, kRed[0], kRed[1], kRed[2]);
  cairo_set_line_width(cr, 2.0);
  cairo_rectangle(cr, kPolarCx - box.mu_neg_t * s, kPolarCy - box.mu_pos_b * s,
                  (box.mu_neg_t + box.mu_pos_t) * s, (box.mu_neg_b + box.mu_pos_b) * s);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// Legend (polygon, box) and the box's four coefficients.
void drawLegend(cairo_t* cr, const ConePlot& plot) {
  const double x = kLegendX, y = 100.0;
  cairo_set_source_rgba(cr, kBlue[0], kBlue[1], kBlue[2], 0.22);
  cairo_rectangle(cr, x, y - 11.0, 28.0, 14.0);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, kBlue[0], kBlue[1], kBlue[2]);
  cairo_set_line_width(cr, 2.0);
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  text(cr, "polygon: mu_d, N = " + std::to_string(plot.mu.count) + " directions", x + 38.0, y, 13.0,
       Align::Left);
  const double dash[2] = {7.0, 4.0};
  cairo_set_dash(cr, dash, 2, 0.0);
  cairo_set_source_rgb(cr, kRed[0], kRed[1], kRed[2]);
  cairo_move_to(cr, x, y + 22.0);
  cairo_line_to(cr, x + 28.0, y + 22.0);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  text(cr, "box (Eq. 9): +t, +b, -t, -b", x + 38.0, y + 27.0, 13.0, Align::Left);
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
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  text(cr,
       "Friction limit surface: B = " + shortName(plot.b_name, 40) +
           ", A = " + (plot.a ? shortName(plot.a_name, 40) : std::string("flat")),
       kThumbX, 30.0, 16.0, Align::Left, true);
  text(cr, plot.subtitle, kThumbX, 52.0, 12.0, Align::Left);
  drawThumbnail(cr, plot.b, "B: " + shortName(plot.b_name, 18), kThumbBY);
  drawThumbnail(cr, plot.a, plot.a ? "A: " + shortName(plot.a_name, 18) : "A: flat", kThumbAY);
  // Equal aspect: one scale s (pixels per unit of mu) for both axes.
  const double extent = plotExtent(plot);
  const double step = tickStep(extent);
  const int ticks = static_cast<int>(std::ceil(extent / step - 1e-9));
  const double s = kPolarRadius / (step * ticks);
  drawAxes(cr, step, ticks);
  drawPolygon(cr, plot.mu, s);
  drawBox(cr, plot.box, s);
  drawTickLabels(cr, step, ticks);
  drawLegend(cr, plot);
}

}  // namespace

void writeConePlotSvg(const ConePlot& plot, const std::string& path) {
  SurfacePtr surface(cairo_svg_surface_create(path.c_str(), kConePlotWidth, kConePlotHeight),
                     &cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw Error(path + ": cannot write SVG (" +
                cairo_status_to_string(cairo_surface_status(surface.get())) + ")");
  {
    ContextPtr cr(cairo_create(surface.get()), &cairo_destroy);
    drawConePlot(cr.get(), plot);
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw Error(path + ": cannot write SVG (" +
                cairo_status_to_string(cairo_surface_status(surface.get())) + ")");
}

void writeConePlotPng(const ConePlot& plot, const std::string& path) {
  SurfacePtr surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, kConePlotWidth, kConePlotHeight),
      &cairo_surface_destroy);
  {
    ContextPtr cr(cairo_create(surface.get()), &cairo_destroy);
    cairo_set_antialias(cr.get(), CAIRO_ANTIALIAS_BEST);
    drawConePlot(cr.get(), plot);
  }
  const cairo_status_t status = cairo_surface_write_to_png(surface.get(), path.c_str());
  if (status != CAIRO_STATUS_SUCCESS)
    throw Error(path + ": cannot write PNG (" + cairo_status_to_string(status) + ")");
}

}  // namespace asperity::cli
