// The CPU patch rasteriser's curved primitives (spheres, cylinders, capsules): one ray per
// pixel centre along the contact normal, intersected with the shape's convex parts.
#include "sampler/patch_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace asperity::patch {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The ray's parameter interval inside a sphere of radius r centred at c (false: misses).
bool sphereInterval(const Vec3& o, const Vec3& a, const Vec3& c, double r, double& s0, double& s1) {
  const Vec3 oc = o - c;
  const double bq = oc.dot(a);
  const double disc = bq * bq - (oc.squaredNorm() - r * r);
  if (disc < 0.0) return false;
  const double root = std::sqrt(disc);
  s0 = -bq - root;
  s1 = -bq + root;
  return true;
}

// Inside the infinite cylinder x^2 + y^2 <= r^2 clipped to |z| <= h (false: misses).
bool finiteCylinderInterval(const Vec3& o, const Vec3& a, double r, double h, double& s0,
                            double& s1) {
  double lo = -kInf, hi = kInf;
  // Radial part.
  const double aa = a.x() * a.x() + a.y() * a.y();
  const double bb = o.x() * a.x() + o.y() * a.y();
  const double cc = o.x() * o.x() + o.y() * o.y() - r * r;
  if (aa < 1e-18) {
    if (cc > 0.0) return false;
  } else {
    const double disc = bb * bb - aa * cc;
    if (disc < 0.0) return false;
    const double root = std::sqrt(disc);
    lo = (-bb - root) / aa;
    hi = (-bb + root) / aa;
  }
  // Axial slab.
  if (std::abs(a.z()) < 1e-18) {
    if (std::abs(o.z()) > h) return false;
  } else {
    const double t0 = (-h - o.z()) / a.z(), t1 = (h - o.z()) / a.z();
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
  }
  if (lo > hi) return false;
  s0 = lo;
  s1 = hi;
  return true;
}

}  // namespace

bool castCurved(const Curved& prim, Side side, double x, double y, double& z) {
  // The ray in the shape frame: o + s a, with s the contact-frame z.
  const Vec3 o = prim.origin_local + prim.to_local.col(0) * x + prim.to_local.col(1) * y;
  const Vec3 a = prim.to_local.col(2);
  const Shape& s = *prim.shape;
  double lo = kInf, hi = -kInf, s0 = 0.0, s1 = 0.0;
  // Union of convex parts is convex: its interval spans the parts' intervals.
  auto add = [&](bool hit) {
    if (!hit) return;
    lo = std::min(lo, s0);
    hi = std::max(hi, s1);
  };
  switch (s.type) {
    case ShapeType::Sphere:
      add(sphereInterval(o, a, Vec3::Zero(), s.radius, s0, s1));
      break;
    case ShapeType::Cylinder:
      add(finiteCylinderInterval(o, a, s.radius, s.half_height, s0, s1));
      break;
    case ShapeType::Capsule:
      add(finiteCylinderInterval(o, a, s.radius, s.half_height, s0, s1));
      add(sphereInterval(o, a, Vec3(0, 0, s.half_height), s.radius, s0, s1));
      add(sphereInterval(o, a, Vec3(0, 0, -s.half_height), s.radius, s0, s1));
      break;
    default:
      return false;
  }
  if (lo > hi) return false;
  // B faces +n: its surface toward A is where the ray leaves it; A is entered there.
  z = side == Side::B ? hi : lo;
  return true;
}

void rasteriseCurved(const Volume& volume, const Curved& prim, int32_t id, SurfaceRaster& raster) {
  const int r = volume.resolution;
  const float sign = raster.side == Side::B ? 1.0f : -1.0f;
  const int j0 = std::max(prim.j0, raster.wj0), j1 = std::min(prim.j1, raster.wj1);
  for (int j = j0; j <= j1; ++j) {
    const double y = volume.centreX(j);
    const int i0 = std::max(prim.i0, raster.win_lo[static_cast<size_t>(j)]);
    const int i1 = std::min(prim.i1, raster.win_hi[static_cast<size_t>(j)]);
    for (int i = i0; i <= i1; ++i) {
      const double x = volume.centreX(i);
      double z = 0.0;
      // Depth clip, then keep the fragment nearest the other body.
      if (!castCurved(prim, raster.side, x, y, z) || !(std::abs(z) <= volume.half_depth)) {
        continue;
      }
      raster.cover(j, i, i);
      const size_t idx = static_cast<size_t>(j * r + i);
      const float key = sign * static_cast<float>(z);
      if (key > raster.key[idx]) {
        raster.key[idx] = key;
        raster.primitive[idx] = -1 - id;
      }
    }
  }
}

}  // namespace asperity::patch
