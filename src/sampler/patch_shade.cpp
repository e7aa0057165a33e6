// Fragment shading of the CPU sampler (patch_shade.hpp).
#include "sampler/patch_shade.hpp"

#include "asperity/friction/fragment_model.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "sampler/patch_texture.hpp"

namespace asperity::patch {

namespace {

// Tangent-space normal and mask at uv (flat and 1 when absent).
Fragment sampleMaterial(const Material& material, float u, float v) {
  Fragment f;
  if (material.map != nullptr && !material.map->empty()) f.m = sampleNormal(*material.map, u, v);
  if (material.mask != nullptr) f.gain = sampleMask(*material.mask, u, v);
  return f;
}

Fragment shadePlanar(const Planar& p, double x, double y) {
  // uv and frame are affine over the primitive.
  Fragment f = sampleMaterial(p.material, static_cast<float>(p.u.at(x, y)),
                              static_cast<float>(p.v.at(x, y)));
  if (!p.smooth) {
    f.m = p.frame * f.m;
    return f;
  }
  Eigen::Matrix3f frame;
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      frame(row, col) = static_cast<float>(p.tbn[static_cast<size_t>(3 * col + row)].at(x, y));
    }
  }
  f.m = frame * f.m;
  return f;
}

Fragment shadeCurved(const Curved& c, Side side, double x, double y) {
  // The hit point in the shape frame, then the analytic mapping there.
  double z = 0.0;
  castCurved(c, side, x, y, z);
  const Vec3 local = c.origin_local + c.to_local * Vec3(x, y, z);
  const SurfaceFrame sf = surfaceFrameAt(*c.shape, -1, local);
  Fragment f =
      sampleMaterial(c.material, static_cast<float>(sf.uv.x()), static_cast<float>(sf.uv.y()));
  const Mat3 to_contact = c.to_local.transpose();
  const Vec3 m =
      to_contact * (sf.t * static_cast<double>(f.m.x()) + sf.b * static_cast<double>(f.m.y()) +
                    sf.n * static_cast<double>(f.m.z()));
  f.m = m.cast<float>();
  return f;
}

}  // namespace

Fragment shadeFragment(const Volume& volume, const SurfaceRaster& raster, int pixel) {
  const int r = volume.resolution;
  const double x = volume.centreX(pixel % r), y = volume.centreX(pixel / r);
  const int32_t id = raster.primitive[static_cast<size_t>(pixel)];
  if (id >= 0) return shadePlanar(raster.planars[static_cast<size_t>(id)], x, y);
  return shadeCurved(raster.curveds[static_cast<size_t>(-1 - id)], raster.side, x, y);
}

void shadePloughing(const Volume& volume, const SurfaceRaster& raster,
                    std::span<const int32_t> pixels, float mu_max, float* gx, float* gy) {
  // Eqs. 3 to 6 through the friction module, scaled by the mask (max(0, s g.d) = s max(0, g.d)).
  for (size_t k = 0; k < pixels.size(); ++k) {
    const Fragment f = shadeFragment(volume, raster, pixels[k]);
    const Vec2f g = ploughingVector(f.m, raster.side, mu_max);
    gx[k] = f.gain * g.x();
    gy[k] = f.gain * g.y();
  }
}

}  // namespace asperity::patch
