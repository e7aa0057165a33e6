// The real-contact-area friction model at one contact (SPEC 13, docs/contact-area.md), on the
// CPU sampler's rasters: both surfaces' heights at the pixels of P, with the macro gap between
// the two rasterised surfaces, make the composite roughness of the patch; the load is the
// contact's previous normal impulse over the step; its Greenwood and Williamson summits give
// the real area A_r (contact_area/contact_area.hpp); mu_d = tau A_r / W plus Eq. 7's ploughing
// averaged over the pixels in contact only.
#pragma once

#include <map>
#include <memory>
#include <span>
#include <vector>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "sampler/patch_common.hpp"

namespace asperity::patch {

// The heights of the surfaces the contacts touch, generated once per normal map on the calling
// thread (prepare) and only read by the sampling threads. A surface whose normal map comes
// from a generator with a height field (the height_map generator included) has those
// heights; any other surface is flat for the area model.
class HeightCache {
 public:
  void prepare(std::span<const Body> bodies, const Contact& contact);
  // Null: flat.
  const HeightMap* find(const NormalMap* map) const;

 private:
  struct Entry {
    std::shared_ptr<const NormalMap> keep;  // so that the key's address is not reused
    std::shared_ptr<const HeightMap> heights;
  };
  void add(const Surface& surface);
  std::map<const NormalMap*, Entry> entries_;
};

// One thread's scratch for the model (no allocation once warm).
struct AreaScratch {
  HeightMap composite;  // over P's bounding box, its pixel (0, 0) at patch pixel (i0, j0)
  int i0 = 0, j0 = 0;
  SummitSet summits;
  std::vector<unsigned char> mask;
  std::vector<float> heights;      // A's then B's heights at P's pixels
  std::vector<uint32_t> touching;  // the pixels of P in contact (Volume::pack)
  std::vector<float> gx, gy;       // ploughing vectors of the pixels in contact, A then B

  // Every buffer at least as large as other's (CpuPatchSampler::State::reserveLike).
  void reserveLike(const AreaScratch& other) {
    composite.values.reserve(other.composite.values.capacity());
    summits.summits.reserve(other.summits.summits.capacity());
    summits.surface.values.reserve(other.summits.surface.values.capacity());
    mask.reserve(other.mask.capacity());
    heights.reserve(other.heights.capacity());
    touching.reserve(other.touching.capacity());
    gx.reserve(other.gx.capacity());
    gy.reserve(other.gy.capacity());
  }
};

// What the model needs besides the rasters.
struct AreaInputs {
  const ContactAreaOptions* options = nullptr;
  const HeightCache* heights = nullptr;
  std::span<const Vec2> directions;
  PatchGains gains;     // k_A, k_B (mu0 is replaced by the adhesion term)
  double mu_max = 4.0;  // cap of the adhesion term, as of the ploughing one
  SimdCopy simd = SimdCopy::Auto;
};

// The pair's mechanical values for this contact: those of each side's first shape in
// options.mechanical (pointers into it). Throws asperity::Error naming the body and shape
// without any.
std::array<const Mechanical*, 2> mechanicalOf(const ContactAreaOptions& options,
                                              const Contact& contact,
                                              const ShapeRange (&ranges)[2]);

// Fills contact.mu from the rasters and P (`in_patch`, Volume::pack), shading (Eqs. 3 to 6)
// only the pixels in contact, the only ones the ploughing means take. Returns their count.
int finishAreaContact(const Volume& volume, const std::array<SurfaceRaster, 2>& rasters,
                      std::span<const uint32_t> in_patch,
                      const std::array<const Mechanical*, 2>& pair, const AreaInputs& in,
                      Contact& contact, AreaScratch& scratch);

}  // namespace asperity::patch
