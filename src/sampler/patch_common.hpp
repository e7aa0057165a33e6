// What the CPU and OpenGL patch samplers share: the viewing volume of a contact (SPEC 3), the
// surfaces and gains of its two bodies.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "asperity/collision/contact.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "sampler/patch_raster.hpp"

namespace asperity::patch {

// The contact's volume: centre contact.point; axes t (orthogonalised against n), b = n x t, n;
// w x w x (|phi| + 0.01 w).
Volume makeVolume(const Contact& contact, const FrictionSettings& settings);

// The shapes of one side of a contact: [first, last) indices into the body's shapes (the
// contact's shape, or all of them when its index is -1). Throws asperity::Error for a body or
// shape index out of range.
struct ShapeRange {
  const Body* body = nullptr;
  int first = 0;
  int last = 0;
};
ShapeRange shapesOf(std::span<const Body> bodies, const Contact& contact, Side side);

// mu0 and the gains k_A, k_B of Eq. 7 (the gain of the contact's shape, or of the body's first
// shape when the index is -1).
PatchGains gainsOf(const ShapeRange& a, const ShapeRange& b, double mu0);
// The gain k of one surface (its first shape's; 0 for none).
double gainOf(const ShapeRange& range);
// The surface of a side's first shape (null for none): the one its model and gain are of.
const Surface* firstSurface(const ShapeRange& range);

// The world pose of shape `index` of `body`.
Transform shapePose(const Body& body, int index);

}  // namespace asperity::patch
