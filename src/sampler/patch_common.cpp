// Shared pieces of the patch samplers (patch_common.hpp).
#include "sampler/patch_common.hpp"

#include <array>
#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/sampler/patch_sampler.hpp"

namespace asperity {

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

const Surface* firstSurface(const ShapeRange& range) {
  return range.first < range.last ? &range.body->shapes[static_cast<size_t>(range.first)].surface
                                  : nullptr;
}

double gainOf(const ShapeRange& range) {
  const Surface* surface = firstSurface(range);
  return surface != nullptr ? surface->gain : 0.0;
}

PatchGains gainsOf(const ShapeRange& a, const ShapeRange& b, double mu0) {
  return {mu0, gainOf(a), gainOf(b)};
}

Transform shapePose(const Body& body, int index) {
  return body.pose * body.shapes[static_cast<size_t>(index)].local;
}

}  // namespace patch
}  // namespace asperity
