// Two doubles in one vector register (SSE2 on x86-64, NEON on AArch64): two contact rows of
// islands swept side by side (the solver), two query points moved into a distance field's
// frame (the collision stage). Each lane takes exactly the IEEE operations the scalar code
// takes, in the same order, so a lane gives the bits of the scalar code it stands for. Neither
// may be contracted into fused multiply-adds: the users are built with -ffp-contract=off (FMA
// is baseline on AArch64; baseline x86-64 has none).
#pragma once

#include <Eigen/Geometry>

#include "asperity/math/types.hpp"

namespace asperity::lanes {

using Lanes = double __attribute__((vector_size(16)));
using Mask = decltype(Lanes{} < Lanes{});  // per lane all ones (true) or zero

inline Lanes of(double x, double y) {
  return Lanes{x, y};
}
inline Lanes splat(double x) {
  return Lanes{x, x};
}

// a where the mask is set, b elsewhere (a bit select: exact).
inline Lanes select(Mask mask, Lanes a, Lanes b) {
  return reinterpret_cast<Lanes>((mask & reinterpret_cast<Mask>(a)) |
                                 (~mask & reinterpret_cast<Mask>(b)));
}
// std::max(0.0, v) per lane: (0 < v) ? v : 0, NaN to 0 as there.
inline Lanes max0(Lanes v) {
  const Lanes zero{0.0, 0.0};
  return select(zero < v, v, zero);
}
inline bool any(Mask m) {
  return (m[0] | m[1]) != 0;
}
inline bool all(Mask m) {
  return (m[0] & m[1]) != 0;
}
// |v| per lane: the sign bit cleared, as std::abs.
inline Lanes abs(Lanes v) {
  return reinterpret_cast<Lanes>(reinterpret_cast<Mask>(v) & ~reinterpret_cast<Mask>(splat(-0.0)));
}
// std::clamp(v, lo, hi) per lane.
inline Lanes clamp(Lanes v, double lo, double hi) {
  return select(v < splat(lo), splat(lo), select(splat(hi) < v, splat(hi), v));
}

// A 3-vector per lane, component by component.
struct Lanes3 {
  Lanes x, y, z;
};

inline Lanes3 of(const Vec3& a, const Vec3& b) {
  return {of(a.x(), b.x()), of(a.y(), b.y()), of(a.z(), b.z())};
}
inline Lanes3 operator+(const Lanes3& a, const Lanes3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Lanes3 operator-(const Lanes3& a, const Lanes3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Lanes3 operator*(Lanes s, const Lanes3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
// Eigen's order: (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x).
inline Lanes3 cross(const Lanes3& a, const Lanes3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// Eigen's order for a 3-vector: (x + y) + z.
inline Lanes dot(const Lanes3& a, const Lanes3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

inline Lanes3 splat(const Vec3& a) {
  return {splat(a.x()), splat(a.y()), splat(a.z())};
}
inline Mask none() {
  return splat(0.0) < splat(0.0);
}

// A rigid transform in both lanes, made once for many points.
struct Transform2 {
  Lanes3 axis, position;  // the quaternion's vector part; the translation
  Lanes w;

  explicit Transform2(const Transform& t)
      : axis(splat(t.rotation.vec())), position(splat(t.position)), w(splat(t.rotation.w())) {}
  // Transform::apply per lane: Eigen's quaternion product (uv = q x v, uv += uv, then
  // (v + w uv) + q x uv), then the translation.
  Lanes3 apply(const Lanes3& v) const {
    Lanes3 uv = cross(axis, v);
    uv = uv + uv;
    return ((v + w * uv) + cross(axis, uv)) + position;
  }
};

// An axis-aligned box in both lanes.
struct Box2 {
  Lanes3 lo, hi;

  explicit Box2(const Eigen::AlignedBox3d& box) : lo(splat(box.min())), hi(splat(box.max())) {}
  // Per lane, whether the point lies outside: !box.contains(p), so NaN is outside too.
  Mask outside(const Lanes3& p) const {
    return ~((lo.x <= p.x) & (lo.y <= p.y) & (lo.z <= p.z) & (p.x <= hi.x) & (p.y <= hi.y) &
             (p.z <= hi.z));
  }
};

inline Vec3 lane(const Lanes3& a, int k) {
  return {a.x[k], a.y[k], a.z[k]};
}

}  // namespace asperity::lanes
