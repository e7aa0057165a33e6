// The contact-frame stage (SPEC 5): how each contact's tangent t is chosen; b = n x t.
#pragma once

#include "asperity/collision/contact.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

// `axis` projected on the plane of `n`, normalised; `fallback` when that projection is
// shorter than 1e-6 |axis|; any unit vector perpendicular to n when both vanish.
Vec3 projectedTangent(const Vec3& n, const Vec3& axis, const Vec3& fallback);

// Sets c.t from a desired tangent (projected on the contact plane, with `fallback` as in
// projectedTangent) and c.b = n x t.
void setContactFrame(Contact& c, const Vec3& desired_t, const Vec3& fallback);

}  // namespace asperity
