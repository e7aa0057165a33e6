// The heights of the surfaces a patch sampler reads for a friction model that asks for them
// (the contact-area model, sampler/models/): generated once per normal map, and looked up at
// the pixels of P.
#pragma once

#include <map>
#include <memory>
#include <span>

#include "asperity/texture/height_map.hpp"
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

// The heights (m) of one raster's kept fragments at P's pixels (Volume::pack), out of the
// surface toward the other body, from the heights of each primitive's normal map at the
// fragment's uv (0: flat), into out[k] for in_patch[k].
void heightsOf(const Volume& volume, const SurfaceRaster& raster,
               std::span<const uint32_t> in_patch, const HeightCache& cache, float* out);

}  // namespace asperity::patch
