// Fills the debug draw list from contacts (see include/asperity/world/debug_draw.hpp).
#include "asperity/world/debug_draw.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/world/world.hpp"

namespace asperity {

void DebugDrawList::clear() {
  lines.clear();
  points.clear();
  polygons.clear();
}

uint32_t parseDebugLayers(const std::string& list) {
  uint32_t layers = 0;
  std::stringstream stream(list);
  std::string name;
  // Comma separated names; blanks around names are allowed.
  while (std::getline(stream, name, ',')) {
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (name.empty() || name == "none") continue;
    if (name == "contacts") {
      layers |= kLayerContacts;
    } else if (name == "frames") {
      layers |= kLayerFrames;
    } else if (name == "cones") {
      layers |= kLayerCones;
    } else if (name == "patches") {
      layers |= kLayerPatches;
    } else if (name == "all") {
      layers |= kLayerContacts | kLayerFrames | kLayerCones | kLayerPatches;
    } else {
      throw Error("layers: unknown layer '" + name +
                  "' (expected contacts, frames, cones, patches, all or none)");
    }
  }
  return layers;
}

Vec3 directionColor(double angle) {
  // HSV with full saturation and value; hue follows the angle.
  double h = angle / (2.0 * kPi);
  h -= std::floor(h);
  const double x = h * 6.0;
  const int sector = std::min(static_cast<int>(x), 5);
  const double f = x - sector;
  switch (sector) {
    case 0:
      return {1.0, f, 0.0};
    case 1:
      return {1.0 - f, 1.0, 0.0};
    case 2:
      return {0.0, 1.0, f};
    case 3:
      return {0.0, 1.0 - f, 1.0};
    case 4:
      return {f, 0.0, 1.0};
    default:
      return {1.0, 0.0, 1.0 - f};
  }
}

namespace {

// The friction limit polygon of one contact: vertex k at mu_k d_k times the normal force
// (SPEC 4, polygon), each spoke and the edge leaving it coloured by d_k's direction.
void appendCone(const Contact& c, double dt, const DebugDrawOptions& o, DebugDrawList& out) {
  const int n = c.mu.count;
  if (n < kMinDirections || dt <= 0.0) return;
  const double force = std::max(c.lambda_n, 0.0) / dt;  // N
  const double scale = force * o.cone_scale;
  if (scale <= 0.0) return;
  std::vector<Vec3> loop;
  loop.reserve(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * kPi * k / n;
    const Vec3 d = std::cos(angle) * c.t + std::sin(angle) * c.b;
    loop.push_back(c.point + d * (static_cast<double>(c.mu.mu[static_cast<size_t>(k)]) * scale));
  }
  for (int k = 0; k < n; ++k) {
    const Vec3 color = directionColor(2.0 * kPi * k / n);
    out.lines.push_back({c.point, loop[static_cast<size_t>(k)], color});
    out.lines.push_back(
        {loop[static_cast<size_t>(k)], loop[static_cast<size_t>((k + 1) % n)], color});
  }
}

// The w x w square centred on the contact in its (t, b) plane (SPEC 3, viewing volume).
void appendPatch(const Contact& c, double w, const DebugDrawOptions& o, DebugDrawList& out) {
  const Vec3 t = c.t * (0.5 * w), b = c.b * (0.5 * w);
  out.polygons.push_back(
      {{c.point - t - b, c.point + t - b, c.point + t + b, c.point - t + b}, o.patch_color, false});
}

}  // namespace

void appendContactLayers(std::span<const Contact> contacts, double dt,
                         const DebugDrawOptions& options, DebugDrawList& out) {
  for (const Contact& c : contacts) {
    // Points: fallbacks (empty patch) stand out in their own colour.
    if (options.layers & kLayerContacts)
      out.points.push_back(
          {c.point, c.fallback ? options.fallback_color : options.contact_color, 8.0f});
    // Frame axes t, b, n in red, green, blue.
    if (options.layers & kLayerFrames) {
      const double l = options.frame_length;
      out.lines.push_back({c.point, c.point + c.t * l, Vec3(1.0, 0.15, 0.15)});
      out.lines.push_back({c.point, c.point + c.b * l, Vec3(0.15, 1.0, 0.15)});
      out.lines.push_back({c.point, c.point + c.normal * l, Vec3(0.2, 0.4, 1.0)});
    }
    if (options.layers & kLayerPatches)
      appendPatch(c, options.patch_width > 0.0 ? options.patch_width : 0.02, options, out);
    if (options.layers & kLayerCones) appendCone(c, dt, options, out);
  }
}

void appendWorldLayers(const World& world, const DebugDrawOptions& options, DebugDrawList& out) {
  DebugDrawOptions o = options;
  if (o.patch_width <= 0.0) o.patch_width = world.settings().friction.patch_width;
  appendContactLayers(world.contacts(), world.settings().dt, o, out);
}

}  // namespace asperity
