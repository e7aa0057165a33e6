#include "polar_plot.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"

namespace asperity::cli::plot {
namespace {

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void setColour(cairo_t* cr, const Colour& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

// Strokes the current path in a curve's colour, width and dash, leaving no dash set.
void strokeInStyle(cairo_t* cr, const CurveStyle& style) {
  const double dash[2] = {7.0, 4.0};
  cairo_set_dash(cr, dash, style.dashed ? 2 : 0, 0.0);
  setColour(cr, style.colour);
  cairo_set_line_width(cr, style.width);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
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

// Arrow heads at the ends of the t and b axes, `len` pixels from the centre.
void drawArrowHeads(cairo_t* cr, const PolarAxes& a, double len) {
  cairo_move_to(cr, a.cx + len + 6.0, a.cy);
  cairo_line_to(cr, a.cx + len - 4.0, a.cy - 4.0);
  cairo_line_to(cr, a.cx + len - 4.0, a.cy + 4.0);
  cairo_close_path(cr);
  cairo_move_to(cr, a.cx, a.cy - len - 6.0);
  cairo_line_to(cr, a.cx - 4.0, a.cy - len + 4.0);
  cairo_line_to(cr, a.cx + 4.0, a.cy - len + 4.0);
  cairo_close_path(cr);
  cairo_fill(cr);
}

}  // namespace

void text(cairo_t* cr, const std::string& s, double x, double y, double size, Align align,
          bool bold, bool italic) {
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

std::string shortName(const std::string& path, size_t max_chars) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.size() > max_chars) name = name.substr(0, max_chars - 3) + "...";
  return name;
}

void drawThumbnail(cairo_t* cr, const NormalMap* map, const std::string& label, double x, double y,
                   double side) {
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  text(cr, label, x, y - 8.0, 13.0, Align::Left, true);
  if (map != nullptr && !map->empty()) {
    SurfacePtr thumb = thumbnail(*map, static_cast<int>(side));
    cairo_set_source_surface(cr, thumb.get(), x, y);
    cairo_paint(cr);
  } else {
    cairo_set_source_rgb(cr, 0.5, 0.5, 1.0);  // the colour of the flat normal (0, 0, 1)
    cairo_rectangle(cr, x, y, side, side);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(cr, "flat", x + side / 2.0, y + side / 2.0 + 5.0, 13.0, Align::Center);
  }
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, x + 0.5, y + 0.5, side - 1.0, side - 1.0);
  cairo_stroke(cr);
}

PolarAxes polarAxes(double cx, double cy, double radius, double extent) {
  // Equal aspect: one scale (pixels per unit of mu) for both axes.
  PolarAxes a{cx, cy, radius, 1.0, 1, 1.0};
  a.step = tickStep(extent);
  a.ticks = static_cast<int>(std::ceil(extent / a.step - 1e-9));
  a.scale = radius / (a.step * a.ticks);
  return a;
}

void drawAxes(cairo_t* cr, const PolarAxes& a, const std::string& t_label,
              const std::string& b_label) {
  // Grid circles (light) at every tick radius.
  cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
  cairo_set_line_width(cr, 1.0);
  for (int i = 1; i <= a.ticks; ++i) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, a.cx, a.cy, i * a.step * a.scale, 0.0, 2.0 * kPi);
  }
  cairo_stroke(cr);
  // Axis lines with arrow heads and their names.
  const double len = a.radius + 22.0;
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 1.2);
  cairo_move_to(cr, a.cx - len, a.cy);
  cairo_line_to(cr, a.cx + len, a.cy);
  cairo_move_to(cr, a.cx, a.cy + len);
  cairo_line_to(cr, a.cx, a.cy - len);
  cairo_stroke(cr);
  drawArrowHeads(cr, a, len);
  text(cr, t_label, a.cx + len + 10.0, a.cy + 5.0, 16.0, Align::Left, true, true);
  text(cr, b_label, a.cx + 8.0, a.cy - len - 2.0, 16.0, Align::Left, true, true);
  // Tick marks on both axes, both signs (mu is dimensionless); labels come last.
  for (int i = -a.ticks; i <= a.ticks; ++i) {
    if (i == 0) continue;
    const double off = i * a.step * a.scale;
    cairo_move_to(cr, a.cx + off, a.cy - 4.0);
    cairo_line_to(cr, a.cx + off, a.cy + 4.0);
    cairo_move_to(cr, a.cx - 4.0, a.cy - off);
    cairo_line_to(cr, a.cx + 4.0, a.cy - off);
    cairo_stroke(cr);
  }
}

void drawTickLabels(cairo_t* cr, const PolarAxes& a) {
  for (int i = -a.ticks; i <= a.ticks; ++i) {
    if (i == 0) continue;
    const double off = i * a.step * a.scale;
    const std::string label = tickLabel(i * a.step, a.step);
    haloLabel(cr, label, a.cx + off, a.cy + 18.0, Align::Center);
    haloLabel(cr, label, a.cx - 7.0, a.cy - off + 4.0, Align::Right);
  }
}

void drawCurve(cairo_t* cr, const PolarAxes& a, std::span<const double> angles,
               std::span<const double> mu, const CurveStyle& style) {
  const size_t n = std::min(angles.size(), mu.size());
  const auto point = [&](size_t k) {
    const double r = mu[k] * a.scale;
    return std::pair(a.cx + r * std::cos(angles[k]), a.cy - r * std::sin(angles[k]));
  };
  // The line: segments between neighbouring points that both exist.
  bool gaps = false, pen_down = false;
  for (size_t k = 0; k < n; ++k) {
    if (std::isnan(mu[k])) {
      gaps = true;
      pen_down = false;
      continue;
    }
    const auto [x, y] = point(k);
    pen_down ? cairo_line_to(cr, x, y) : cairo_move_to(cr, x, y);
    pen_down = true;
  }
  // Closed: back to the first point (a path without gaps closes on itself).
  if (style.closed && pen_down && !std::isnan(mu[0])) {
    if (gaps)
      cairo_line_to(cr, point(0).first, point(0).second);
    else
      cairo_close_path(cr);
  }
  // The fill (closed curves without gaps), then the line in its style.
  if (style.fill_alpha > 0.0 && !gaps) {
    setColour(cr, style.colour, style.fill_alpha);
    cairo_fill_preserve(cr);
  }
  strokeInStyle(cr, style);
  // Dots at the points.
  if (style.marker <= 0.0) return;
  for (size_t k = 0; k < n; ++k) {
    if (std::isnan(mu[k])) continue;
    cairo_new_sub_path(cr);
    cairo_arc(cr, point(k).first, point(k).second, style.marker, 0.0, 2.0 * kPi);
  }
  cairo_fill(cr);
}

void drawLegendEntry(cairo_t* cr, double x, double y, const CurveStyle& style,
                     const std::string& label) {
  // A short line (or a filled box for a filled curve) in the curve's style.
  if (style.fill_alpha > 0.0) {
    setColour(cr, style.colour, style.fill_alpha);
    cairo_rectangle(cr, x, y - 11.0, 28.0, 14.0);
    cairo_fill_preserve(cr);
  } else {
    cairo_move_to(cr, x, y - 5.0);
    cairo_line_to(cr, x + 28.0, y - 5.0);
  }
  strokeInStyle(cr, style);
  // A dot for curves drawn with dots (not for the cone's filled polygon, as before).
  if (style.marker > 0.0 && style.fill_alpha <= 0.0) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, x + 14.0, y - 5.0, style.marker, 0.0, 2.0 * kPi);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  text(cr, label, x + 38.0, y, 13.0, Align::Left);
}

void writeFigure(const std::string& path, bool svg, int width, int height,
                 const std::function<void(cairo_t*)>& draw) {
  // Written under a temporary name and renamed once whole (asperity/math/atomic_file.hpp).
  AtomicOutput output(path);
  SurfacePtr surface(svg ? cairo_svg_surface_create(output.temporaryPath().c_str(), width, height)
                         : cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height),
                     &cairo_surface_destroy);
  const char* kind = svg ? "SVG" : "PNG";
  const auto check = [&](cairo_status_t status) {
    if (status != CAIRO_STATUS_SUCCESS)
      throw Error(path + ": cannot write " + kind + " (" + cairo_status_to_string(status) + ")");
  };
  check(cairo_surface_status(surface.get()));
  // The page: white, then the drawing (antialiased at its best in the PNG).
  {
    ContextPtr cr(cairo_create(surface.get()), &cairo_destroy);
    if (!svg) cairo_set_antialias(cr.get(), CAIRO_ANTIALIAS_BEST);
    cairo_set_source_rgb(cr.get(), 1.0, 1.0, 1.0);
    cairo_paint(cr.get());
    draw(cr.get());
  }
  // An SVG is written as it is finished; a PNG from the finished drawing.
  if (!svg) {
    check(cairo_surface_write_to_png(surface.get(), output.temporaryPath().c_str()));
  } else {
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()));
  }
  output.commit();
}

}  // namespace asperity::cli::plot
