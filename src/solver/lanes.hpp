// Two doubles in one vector register (SSE2 on x86-64, NEON on AArch64), one per contact row of
// two islands swept side by side. Each lane takes exactly the IEEE operations the scalar code
// takes, in the same order, so a lane gives the bits of the scalar row it stands for. Neither
// may be contracted into fused multiply-adds: contact_solver.cpp, the one user, is built with
// -ffp-contract=off (FMA is baseline on AArch64; baseline x86-64 has none).
#pragma once

#include "asperity/math/types.hpp"

namespace asperity::lanes {

using Lanes = double __attribute__((vector_size(16)));
using Mask = decltype(Lanes{} < Lanes{});  // per lane all ones (true) or zero

inline Lanes of(double x, double y) {
  return Lanes{x, y};
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

inline Vec3 lane(const Lanes3& a, int k) {
  return {a.x[k], a.y[k], a.z[k]};
}

}  // namespace asperity::lanes
