// Shading of kept fragments (SPEC 2, 3): the meso normal of the fragment at a pixel (the normal
// map's texel under the pixel, or a bilinear blend: Volume::reading; repeat; through the
// fragment's tangent frame, in the contact frame),
// its gain-mask factor, and its ploughing vector g (friction/fragment_model.hpp).
#pragma once

#include <cstdint>
#include <span>

#include "sampler/patch_raster.hpp"

namespace asperity::patch {

struct Fragment {
  Vec3f m = Vec3f::UnitZ();  // meso normal in the contact frame (not normalised)
  float gain = 1.0f;         // gain-mask value (1 without a mask)
};

// The fragment kept at `pixel` of `raster` (which must be covered).
Fragment shadeFragment(const Volume& volume, const SurfaceRaster& raster, int pixel);

// g = gain * ploughingVector(m) for each listed (covered) pixel (Volume::pack(i, j)), into
// gx[k], gy[k]. Flat-framed planar primitives with a power-of-two map and no mask (box faces,
// planes) are shaded in bulk with the same float operations; nothing is allocated.
void shadePloughing(const Volume& volume, const SurfaceRaster& raster,
                    std::span<const uint32_t> pixels, float mu_max, float* gx, float* gy);

}  // namespace asperity::patch
