// Profile generators: the sawtooth of Figs. 8 and 12, the screw thread of Fig. 13, and a field
// of identical cones (Bowden and Tabor's ploughing asperity, SPEC 12).
//
// Direction convention (SPEC 1): a facet whose normal tilts toward +a resists a body sliding
// over it toward -a. The sawtooth's ramps rise toward +axis, so ramp normals tilt toward -axis
// and steep-face normals toward +axis: sliding toward -axis is "against the steep faces".
#include <algorithm>
#include <cmath>

#include "asperity/math/types.hpp"
#include "texture/generator_support.hpp"
#include "texture/height_field.hpp"
#include "texture/profile.hpp"

namespace asperity::texgen {

namespace {

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// Fills a map from a profile along `axis`; `shear` adds that many profile texels per texel
// across the axis (the helix of a thread).
NormalMap profileMap(const PeriodicProfile& profile, int size, double axis, double shear,
                     double window) {
  // Exact components for multiples of 90 degrees (cos(pi / 2) is not 0 in floating point).
  const auto snap = [](double c) { return std::abs(c) < 1e-12 ? 0.0 : c; };
  const double ax = snap(std::cos(axis));
  const double ay = snap(std::sin(axis));
  // Across-axis direction b = (sin a, -cos a): +u when the axis is +v.
  const double bx = ay;
  const double by = -ax;
  NormalMap map(size, size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      // Profile coordinate of the texel centre.
      const double px = i + 0.5;
      const double py = j + 0.5;
      const double x = ax * px + ay * py + shear * (bx * px + by * py);
      const double s = profile.slope(x, window);
      // Gradient s (a + shear b).
      const double gx = s * (ax + shear * bx);
      const double gy = s * (ay + shear * by);
      map.at(i, j) = Vec3f(static_cast<float>(-gx), static_cast<float>(-gy), 1.0f).normalized();
    }
  }
  return map;
}

// The heights under profileMap: the profile's integral at each texel centre (the box filter of
// profileMap's `window` is not applied).
Field profileHeights(const PeriodicProfile& profile, int size, double axis, double shear) {
  const auto snap = [](double c) { return std::abs(c) < 1e-12 ? 0.0 : c; };
  const double ax = snap(std::cos(axis));
  const double ay = snap(std::sin(axis));
  Field heights(size, size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double px = i + 0.5;
      const double py = j + 0.5;
      heights.at(i, j) = profile.height(ax * px + ay * py + shear * (ay * px - ax * py));
    }
  }
  return heights;
}

// sawtooth: a ramp of ramp_width * period at ramp_angle rising toward +axis, then a steep face
// at steep_angle falling over the rest of the period.
NormalMap makeSawtooth(const GeneratorContext& ctx) {
  const double period = ctx.number("period");
  const double ramp_width = ctx.number("ramp_width");
  const double ramp = std::tan(radians(ctx.number("ramp_angle")));
  const double steep = std::tan(radians(ctx.number("steep_angle")));
  const PeriodicProfile profile(
      {{ramp_width * period, ramp}, {(1.0 - ramp_width) * period, -steep}});
  return profileMap(profile, ctx.size(), ctx.axisRadians("axis"), 0.0, ctx.number("smoothing"));
}

// sawtooth's heights. A ramp and a steep face of equal widths do not close (the ridge would
// climb or fall by (w tan ramp - w' tan steep) each period), so the height field keeps both
// facet angles and gives the ramp the share tan(steep) / (tan(ramp) + tan(steep)) of the
// period: the true sawtooth with those facets.
Field sawtoothHeights(const GeneratorContext& ctx) {
  const double period = ctx.number("period");
  const double ramp = std::tan(radians(ctx.number("ramp_angle")));
  const double steep = std::tan(radians(ctx.number("steep_angle")));
  const double share = ramp + steep > 0.0 ? steep / (ramp + steep) : 0.5;
  const PeriodicProfile profile({{share * period, ramp}, {(1.0 - share) * period, -steep}});
  return profileHeights(profile, ctx.size(), ctx.axisRadians("axis"), 0.0);
}

// thread: symmetric triangles; flanks at flank_angle from the radial direction (ISO metric:
// 30 degrees), so facet normals tilt 90 - flank_angle degrees toward +axis and -axis equally.
NormalMap makeThread(const GeneratorContext& ctx) {
  const double pitch = ctx.number("pitch_texels");
  const double slope = 1.0 / std::tan(radians(ctx.number("flank_angle")));
  const PeriodicProfile profile({{0.5 * pitch, slope}, {0.5 * pitch, -slope}});
  // A helix advances starts * pitch per turn, one turn being the map's width across the axis.
  const double shear = ctx.number("starts") * pitch / ctx.size();
  return profileMap(profile, ctx.size(), ctx.axisRadians("axis"), shear, 0.0);
}

Field threadHeights(const GeneratorContext& ctx) {
  const double pitch = ctx.number("pitch_texels");
  const double slope = 1.0 / std::tan(radians(ctx.number("flank_angle")));
  const PeriodicProfile profile({{0.5 * pitch, slope}, {0.5 * pitch, -slope}});
  const double shear = ctx.number("starts") * pitch / ctx.size();
  return profileHeights(profile, ctx.size(), ctx.axisRadians("axis"), shear);
}

// Offset of texel `index`'s centre from the nearest cone apex, at (m + 1/2) period.
double apexOffset(int index, double period) {
  return std::fmod(index + 0.5, period) - 0.5 * period;
}

// cones: identical cones on a square grid of `period` texels, base radius base * period, flanks
// tilted flank_angle from the plane (height tan(alpha) (r0 - r)); normals tilt outward, away from
// the apex. Outside the cones (and at an apex) the map is flat. The model's value for it is
// mu_d = base^2 (2/pi) tan(alpha) in every direction (docs/textures.md).
NormalMap makeCones(const GeneratorContext& ctx) {
  const double period = ctx.number("period");
  const double radius = ctx.number("base") * period;
  const double slope = std::tan(radians(ctx.number("flank_angle")));
  const auto offset = [period](int index) { return apexOffset(index, period); };
  NormalMap map(ctx.size(), ctx.size());
  for (int j = 0; j < ctx.size(); ++j) {
    for (int i = 0; i < ctx.size(); ++i) {
      const double dx = offset(i), dy = offset(j);
      const double r = std::hypot(dx, dy);
      if (r >= radius || r < 1e-9) continue;  // flat (NormalMap's default texel)
      const Vec3f n(static_cast<float>(slope * dx / r), static_cast<float>(slope * dy / r), 1.0f);
      map.at(i, j) = n.normalized();
    }
  }
  return map;
}

// cones' heights: tan(alpha) (r0 - r) inside each base, 0 outside.
Field conesHeights(const GeneratorContext& ctx) {
  const double period = ctx.number("period");
  const double radius = ctx.number("base") * period;
  const double slope = std::tan(radians(ctx.number("flank_angle")));
  const auto offset = [period](int index) { return apexOffset(index, period); };
  Field heights(ctx.size(), ctx.size());
  for (int j = 0; j < ctx.size(); ++j)
    for (int i = 0; i < ctx.size(); ++i)
      heights.at(i, j) = slope * std::max(0.0, radius - std::hypot(offset(i), offset(j)));
  return heights;
}

}  // namespace

std::vector<GeneratorEntry> profileGenerators() {
  std::vector<GeneratorEntry> entries;
  entries.push_back(
      {{"sawtooth",
        "sawtooth ridges: ramps rising toward +axis (normals tilt toward -axis) and steep faces "
        "(normals tilt toward +axis); sliding toward -axis goes against the steep faces "
        "(Figs. 8, 12)",
        {numberParam("period", 32.0, 2.0, 8192.0, "ridge spacing (texels)"),
         numberParam("ramp_angle", 20.0, 0.0, 89.0, "tilt of the gentle ramp facets (degrees)"),
         numberParam("steep_angle", 70.0, 0.0, 89.0, "tilt of the steep facets (degrees)"),
         numberParam("ramp_width", 0.5, 0.0, 1.0,
                     "fraction of the period covered by the ramp; the steep face covers the rest "
                     "(tan(steep) / (tan(ramp) + tan(steep)) makes a true height profile)"),
         axisParam("0", "direction toward which the ramps rise"),
         numberParam("smoothing", 0.0, 0.0, 1024.0,
                     "width of a box filter over the slope profile (texels); 0 = sharp")}},
       makeSawtooth,
       sawtoothHeights});
  entries.push_back(
      {{"thread",
        "screw thread: symmetric triangular profile along the axis, facets facing +axis and "
        "-axis equally (Fig. 13)",
        {numberParam("pitch_texels", 16.0, 2.0, 8192.0, "thread pitch (texels)"),
         numberParam("flank_angle", 30.0, 1.0, 89.0,
                     "angle between a flank and the radial direction (degrees; ISO metric: 30); "
                     "facet normals tilt 90 - flank_angle from the surface normal"),
         axisParam("90", "thread axis in the texture"),
         numberParam("starts", 0.0, 0.0, 16.0,
                     "helix starts: the profile advances starts * pitch per map width across "
                     "the axis (0 = rings; whole numbers tile seamlessly)")}},
       makeThread,
       threadHeights});
  entries.push_back(
      {{"cones",
        "identical conical asperities on a square grid (Bowden and Tabor's ploughing cone): "
        "model mu_d = base^2 (2/pi) tan(flank_angle) in every direction",
        {numberParam("flank_angle", 20.0, 0.0, 89.0,
                     "attack angle alpha: tilt of the cones' flanks from the plane (degrees)"),
         numberParam("period", 16.0, 2.0, 8192.0, "spacing of the cones (texels)"),
         numberParam("base", 0.5, 0.0, 0.5,
                     "base radius as a fraction of the period (0.5: neighbours touch); the "
                     "cones cover pi base^2 of the plane")}},
       makeCones,
       conesHeights});
  return entries;
}

}  // namespace asperity::texgen
