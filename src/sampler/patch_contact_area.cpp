// The real-contact-area model on the CPU sampler's rasters (patch_contact_area.hpp).
#include "sampler/patch_contact_area.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "asperity/error.hpp"
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

const Mechanical* lookup(const ContactAreaOptions& options, int body, int shape) {
  auto it = options.mechanical.find({body, shape});
  if (it == options.mechanical.end()) it = options.mechanical.find({body, -1});
  return it == options.mechanical.end() ? nullptr : &it->second;
}

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

// The heights (m) of one raster's kept fragments at P's pixels, out of the surface toward the
// other body, from the heights of each primitive's normal map at the fragment's uv (0: flat),
// into out[k] for in_patch[k]. Pixels come in runs of one primitive: the primitive's heights
// are looked up once per run, and a planar run's pixels are independent texture reads (a map
// lookup or a branch per pixel would cost more than the rest of the model).
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

// The composite roughness over P's bounding box (origin i0, j0 in the patch): at each pixel of
// P, how far the two surfaces' heights reach past the macro gap between their rasterised faces
// (keys: z for B, -z for A, so key_A + key_B = z_B - z_A = -gap). Other pixels lie below P's
// lowest by P's span, so that they never touch. Returns false when P is flat (the model's full
// contact). Only the box is scanned for summits: a contact often covers a part of its patch.
bool compositeOverPatch(const Volume& volume, const std::array<SurfaceRaster, 2>& rasters,
                        std::span<const uint32_t> in_patch, const HeightCache& cache,
                        AreaScratch& s) {
  const int r = volume.resolution;
  int i0 = r, j0 = r, i1 = -1, j1 = -1;
  for (const uint32_t p : in_patch) {
    const int i = static_cast<int>(p & 0xffffu), j = static_cast<int>(p >> 16);
    i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  }
  HeightMap& out = s.composite;
  s.i0 = i0, s.j0 = j0;
  out.width = i1 - i0 + 1, out.height = j1 - j0 + 1;
  out.values.assign(static_cast<size_t>(out.width * out.height),
                    std::numeric_limits<float>::quiet_NaN());
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  s.heights.resize(2 * in_patch.size());
  float* const ha = s.heights.data();
  float* const hb = ha + in_patch.size();
  heightsOf(volume, rasters[0], in_patch, cache, ha);
  heightsOf(volume, rasters[1], in_patch, cache, hb);
  for (size_t k = 0; k < in_patch.size(); ++k) {
    const uint32_t p = in_patch[k];
    const int i = static_cast<int>(p & 0xffffu), j = static_cast<int>(p >> 16);
    const auto idx = static_cast<size_t>(j * r + i);
    const float c = ha[k] + hb[k] + rasters[0].key[idx] + rasters[1].key[idx];
    out.at(i - i0, j - j0) = c;
    lo = std::min(lo, c), hi = std::max(hi, c);
  }
  if (!(hi > lo)) return false;
  const float below = lo - (hi - lo);
  for (float& v : out.values)
    if (std::isnan(v)) v = below;
  return true;
}

// The pixels of P in contact (in P's order) into scratch, and their ploughing vectors, A's then
// B's: only those enter the means, so only those are shaded. Returns their count.
size_t shadeInContact(const Volume& volume, const std::array<SurfaceRaster, 2>& rasters,
                      std::span<const uint32_t> in_patch, float mu_max, AreaScratch& s) {
  s.touching.clear();
  for (const uint32_t p : in_patch) {
    const int i = static_cast<int>(p & 0xffffu) - s.i0, j = static_cast<int>(p >> 16) - s.j0;
    if (s.mask[static_cast<size_t>(j * s.composite.width + i)]) s.touching.push_back(p);
  }
  const size_t n = s.touching.size();
  s.gx.resize(2 * n);
  s.gy.resize(2 * n);
  for (size_t k = 0; k < 2 && n > 0; ++k)
    shadePloughing(volume, rasters[k], s.touching, mu_max, s.gx.data() + k * n,
                   s.gy.data() + k * n);
  return n;
}

}  // namespace

std::array<const Mechanical*, 2> mechanicalOf(const ContactAreaOptions& options,
                                              const Contact& contact,
                                              const ShapeRange (&ranges)[2]) {
  std::array<const Mechanical*, 2> pair{};
  const int bodies[2] = {static_cast<int>(contact.body_a), static_cast<int>(contact.body_b)};
  for (size_t s = 0; s < 2; ++s) {
    const Mechanical* m = lookup(options, bodies[s], ranges[s].first);
    if (m == nullptr)
      throw Error("friction model contact_area: body " + std::to_string(bodies[s]) + " shape " +
                  std::to_string(ranges[s].first) +
                  " has no mechanical values (E, nu, H, tau): give its surface a \"mechanical\" "
                  "preset or values");
    pair[s] = m;
  }
  return pair;
}

int finishAreaContact(const Volume& volume, const std::array<SurfaceRaster, 2>& rasters,
                      std::span<const uint32_t> in_patch,
                      const std::array<const Mechanical*, 2>& pair, const AreaInputs& in,
                      Contact& contact, AreaScratch& s) {
  const size_t count = in_patch.size();
  const double apparent = static_cast<double>(count) * volume.pixel * volume.pixel;
  const ContactMaterial material = contactPair(*pair[0], *pair[1]);
  // The load: last step's normal impulse over the step; a new contact (none yet) is taken at
  // a light load, 1e-4 of what would flatten the patch, where A_r is still proportional to W.
  const double stiff = material.hardness > 0.0 ? material.hardness : material.modulus;
  const double light = 1e-4 * stiff * apparent;
  const double load = std::max(contact.lambda_n / in.options->dt, light);
  double real_area = apparent;
  // Without relief every pixel of P is in contact.
  s.i0 = s.j0 = 0;
  s.composite.width = volume.resolution;
  s.mask.assign(static_cast<size_t>(volume.resolution * volume.resolution), 1);
  if (count > 0 && compositeOverPatch(volume, rasters, in_patch, *in.heights, s)) {
    findSummitsInto(s.composite, s.composite.width * volume.pixel, s.summits);
    s.summits.apparent_area = apparent;
    const ContactArea area = solveContact(s.summits, material, load);
    real_area = area.real_area;
    contactMaskInto(s.summits, area, s.mask);
  }
  const size_t touching =
      count > 0 ? shadeInContact(volume, rasters, in_patch, static_cast<float>(in.mu_max), s) : 0;
  // Adhesion, capped as the ploughing term is (a flat pair is in full contact at any load).
  PatchGains gains = in.gains;
  gains.mu0 = std::min(pairShear(*pair[0], *pair[1]) * real_area / load, in.mu_max);
  std::array<std::array<double, kMaxDirections>, 2> sums{};
  const size_t n = in.directions.size();
  for (size_t k = 0; k < 2 && touching > 0; ++k) {
    accumulateDirectionalSums(std::span<const float>(s.gx.data() + k * touching, touching),
                              std::span<const float>(s.gy.data() + k * touching, touching),
                              in.directions, std::span<double>(sums[k].data(), n), in.simd);
  }
  finishContact(contact, std::span<const double>(sums[0].data(), n),
                std::span<const double>(sums[1].data(), n), static_cast<int>(touching), gains);
  return static_cast<int>(touching);
}

}  // namespace asperity::patch
