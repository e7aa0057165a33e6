// The surfaces' heights for the friction models that read them (patch_heights.hpp).
#include "sampler/patch_heights.hpp"

#include <algorithm>

#include "asperity/geometry/shape_mesh.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "sampler/patch_shade.hpp"
#include "sampler/patch_texture.hpp"

namespace asperity::patch {

void HeightCache::add(const Surface& surface) {
  const NormalMap* key = surface.normal_map.get();
  if (key == nullptr || entries_.count(key) > 0) return;
  Entry entry{surface.normal_map, nullptr};
  const GeneratorSpec& spec = surface.source.generator;
  if (!spec.name.empty() && generatorHasHeights(spec.name))
    entry.heights =
        std::make_shared<const HeightMap>(generateHeightMap(spec, surface.texture_size));
  entries_.emplace(key, std::move(entry));
}

void HeightCache::prepare(std::span<const Body> bodies, const Contact& contact) {
  for (const Side side : {Side::A, Side::B}) {
    const ShapeRange range = shapesOf(bodies, contact, side);
    for (int k = range.first; k < range.last; ++k)
      add(range.body->shapes[static_cast<size_t>(k)].surface);
  }
}

const HeightMap* HeightCache::find(const NormalMap* map) const {
  const auto it = entries_.find(map);
  return it == entries_.end() ? nullptr : it->second.heights.get();
}

namespace {

// Bilinear height at (u, v) in repeats, bracketed as the normals are (HeightMap::sample's
// values without its libm calls, which cost more than the rest of the model).
float sampleHeight(const HeightMap& map, float u, float v) {
  const TexelBracket bu = bracketRepeat(u, map.width);
  const TexelBracket bv = bracketRepeat(v, map.height);
  const float* row0 = &map.values[static_cast<size_t>(bv.lo) * map.width];
  const float* row1 = &map.values[static_cast<size_t>(bv.hi) * map.width];
  const float bottom = (1.0f - bu.weight) * row0[bu.lo] + bu.weight * row0[bu.hi];
  const float top = (1.0f - bu.weight) * row1[bu.lo] + bu.weight * row1[bu.hi];
  return (1.0f - bv.weight) * bottom + bv.weight * top;
}

// The material of a raster's primitive (planar >= 0, curved < 0).
const Material& materialOf(const SurfaceRaster& raster, int32_t id) {
  return id >= 0 ? raster.planars[static_cast<size_t>(id)].material
                 : raster.curveds[static_cast<size_t>(-1 - id)].material;
}

}  // namespace

// Pixels come in runs of one primitive: the primitive's heights are looked up once per run,
// and a planar run's pixels are independent texture reads (a map lookup or a branch per pixel
// would cost more than the rest of the model).
void heightsOf(const Volume& volume, const SurfaceRaster& raster,
               std::span<const uint32_t> in_patch, const HeightCache& cache, float* out) {
  const int r = volume.resolution;
  const auto primitiveAt = [&](size_t k) {
    const uint32_t packed = in_patch[k];
    return raster.primitive[(packed >> 16) * static_cast<uint32_t>(r) + (packed & 0xffffu)];
  };
  for (size_t k = 0; k < in_patch.size();) {
    const int32_t id = primitiveAt(k);
    size_t end = k + 1;
    while (end < in_patch.size() && primitiveAt(end) == id) ++end;
    const HeightMap* h = cache.find(materialOf(raster, id).map);
    if (h == nullptr) {
      std::fill(out + k, out + end, 0.0f);
    } else if (id >= 0) {
      const Planar& p = raster.planars[static_cast<size_t>(id)];
      for (; k < end; ++k) {
        const auto xf = static_cast<float>(volume.centreX(static_cast<int>(in_patch[k] & 0xffffu)));
        const auto yf = static_cast<float>(volume.centreX(static_cast<int>(in_patch[k] >> 16)));
        out[k] = sampleHeight(*h, p.uf[0] + p.uf[1] * xf + p.uf[2] * yf,
                              p.vf[0] + p.vf[1] * xf + p.vf[2] * yf);
      }
    } else {
      // Curved: the hit point and its analytic uv, as the shading finds them (patch_shade.cpp).
      const Curved& c = raster.curveds[static_cast<size_t>(-1 - id)];
      for (; k < end; ++k) {
        const double x = volume.centreX(static_cast<int>(in_patch[k] & 0xffffu));
        const double y = volume.centreX(static_cast<int>(in_patch[k] >> 16));
        double z = 0.0;
        castCurved(c, raster.side, x, y, z);
        const SurfaceFrame sf =
            surfaceFrameAt(*c.shape, -1, c.origin_local + c.to_local * Vec3(x, y, z));
        out[k] = sampleHeight(*h, static_cast<float>(sf.uv.x()), static_cast<float>(sf.uv.y()));
      }
    }
    k = end;
  }
}

}  // namespace asperity::patch
