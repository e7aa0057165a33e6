// Shared pieces of the patch samplers (patch_common.hpp) and the settings check.
#include "sampler/patch_common.hpp"

#include <array>
#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/sampler/patch_sampler.hpp"

namespace asperity {

void validatePatchSettings(const FrictionSettings& s, const std::string& who,
                           bool directions_multiple_of_4) {
  // Each parameter against its documented range, named in the message.
  const double w = s.patch_width;
  if (!std::isfinite(w) || w < kMinPatchWidth || w > kMaxPatchWidth) {
    throw Error(who + ": patch_width must be in [1e-6, 100] m, got " + std::to_string(w));
  }
  if (s.patch_resolution < 1 || s.patch_resolution > kMaxPatchResolution) {
    throw Error(who + ": patch_resolution must be in [1, 256], got " +
                std::to_string(s.patch_resolution));
  }
  if (s.directions < kMinDirections || s.directions > kMaxDirections) {
    throw Error(who + ": directions must be in [4, 64], got " + std::to_string(s.directions));
  }
  if (directions_multiple_of_4 && s.directions % 4 != 0) {
    throw Error(who + ": directions must be a multiple of 4 (one RGBA target per 4), got " +
                std::to_string(s.directions));
  }
  if (!std::isfinite(s.mu_max) || !(s.mu_max > 0.0f)) {
    throw Error(who + ": mu_max must be positive and finite, got " + std::to_string(s.mu_max));
  }
  if (!std::isfinite(s.mu0) || s.mu0 < 0.0) {
    throw Error(who + ": mu0 must be finite and >= 0, got " + std::to_string(s.mu0));
  }
  if (!std::isfinite(s.reuse_pixels) || s.reuse_pixels < 0.0) {
    throw Error(who + ": reuse_pixels must be finite and >= 0, got " +
                std::to_string(s.reuse_pixels));
  }
}

namespace patch {

Volume makeVolume(const Contact& c, const FrictionSettings& settings) {
  // Right-handed (t, b, n) even if the frame stage left t slightly off the plane.
  Volume v;
  const Vec3 n = c.normal.normalized();
  Vec3 t = c.t - c.t.dot(n) * n;
  if (!(t.squaredNorm() > 1e-24)) t = n.unitOrthogonal();
  t.normalize();
  v.axes.col(0) = t;
  v.axes.col(1) = n.cross(t);
  v.axes.col(2) = n;
  v.origin = c.point;
  v.width = settings.patch_width;
  v.resolution = settings.patch_resolution;
  v.pixel = v.width / v.resolution;
  v.reading = settings.texel_reading;
  // SPEC 3: depth phi + 0.01 w, centred on the contact (|phi| for reported gaps).
  v.half_depth = 0.5 * (std::abs(c.phi) + 0.01 * v.width);
  return v;
}

ShapeRange shapesOf(std::span<const Body> bodies, const Contact& c, Side side) {
  const BodyId id = side == Side::A ? c.body_a : c.body_b;
  const int shape = side == Side::A ? c.shape_a : c.shape_b;
  const char* which = side == Side::A ? "body_a" : "body_b";
  if (id >= bodies.size()) {
    throw Error(std::string("patch sampler: contact ") + which + " " + std::to_string(id) +
                " is not a body (" + std::to_string(bodies.size()) + " bodies)");
  }
  const Body& body = bodies[id];
  const int count = static_cast<int>(body.shapes.size());
  if (shape < -1 || shape >= count) {
    throw Error(std::string("patch sampler: contact shape of ") + which + " (" + body.name +
                ") is " + std::to_string(shape) + ", body has " + std::to_string(count));
  }
  if (shape == -1) return {&body, 0, count};
  return {&body, shape, shape + 1};
}

double gainOf(const ShapeRange& range) {
  return range.first < range.last
             ? range.body->shapes[static_cast<size_t>(range.first)].surface.gain
             : 0.0;
}

PatchGains gainsOf(const ShapeRange& a, const ShapeRange& b, double mu0) {
  return {mu0, gainOf(a), gainOf(b)};
}

void finishContact(Contact& c, std::span<const double> sums_a, std::span<const double> sums_b,
                   int count, const PatchGains& gains) {
  const int n = static_cast<int>(sums_a.size());
  c.covered_pixels = count;
  // Empty P: the nominal coefficient, counted as a fallback (SPEC 3).
  if (count == 0) {
    c.mu = DirectionalMu::uniform(n, static_cast<float>(gains.mu0));
    c.fallback = true;
    return;
  }
  // Eq. 8: means over P; Eq. 7 through the friction module.
  std::array<double, kMaxDirections> mean_a{}, mean_b{};
  for (int k = 0; k < n; ++k) {
    mean_a[static_cast<size_t>(k)] = sums_a[static_cast<size_t>(k)] / count;
    mean_b[static_cast<size_t>(k)] = sums_b[static_cast<size_t>(k)] / count;
  }
  c.mu = combinePatch(std::span<const double>(mean_a.data(), static_cast<size_t>(n)),
                      std::span<const double>(mean_b.data(), static_cast<size_t>(n)), gains);
  c.fallback = false;
}

Transform shapePose(const Body& body, int index) {
  return body.pose * body.shapes[static_cast<size_t>(index)].local;
}

}  // namespace patch
}  // namespace asperity
