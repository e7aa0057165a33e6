// The OpenGL sampler's fragments read back whole, for a friction model that reads more of P
// than its sums (the contact-area model): one contact's two tiles of the fragment atlas become
// the PatchFragments the CPU sampler would hand the model, and the model runs here.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "sampler/models/friction_models.hpp"

namespace asperity::glpatch {

class FragmentReduction {
 public:
  FragmentReduction();
  // `pixels`: rows of the fragment atlas (`atlas_size` pixels of 4 floats: g_t, g_b, height,
  // depth key; the key FragmentAtlas::kNoFragment where nothing was drawn), the contact's A in
  // tile `tile_a` and B in the next, R x R pixels each. `in` carries all but the model.
  void reduce(std::span<const float> pixels, int atlas_size, int resolution, int tile_a,
              const models::FrictionModelVariant& model, const models::ModelInputs& in,
              double patch_width, Contact& contact);

 private:
  struct Side {
    std::vector<float> gx, gy, height, depth;
  };
  std::vector<uint32_t> p_;  // P, packed as the CPU sampler packs it
  std::array<Side, 2> sides_;
  std::array<std::unique_ptr<models::ModelScratch>, std::size(models::kFrictionModelVariants)>
      scratch_;
};

}  // namespace asperity::glpatch
