// One contact's fragments from the OpenGL sampler's read-back (gl_patch_fragments.hpp).
#include "sampler/gl/gl_patch_fragments.hpp"

#include "sampler/gl/gl_patch_resources.hpp"

namespace asperity::glpatch {

FragmentReduction::FragmentReduction() {
  for (size_t m = 0; m < std::size(models::kFrictionModelVariants); ++m)
    if (models::kFrictionModelVariants[m]->make_scratch)
      scratch_[m] = models::kFrictionModelVariants[m]->make_scratch();
}

void FragmentReduction::reduce(std::span<const float> pixels, int atlas_size, int resolution,
                               int tile_a, const models::FrictionModelVariant& model,
                               const models::ModelInputs& in, double patch_width,
                               Contact& contact) {
  // P: the pixels of the two tiles that both surfaces cover, in the CPU sampler's order (rows
  // from -b, each from -t), with both sides' fragments.
  const int r = resolution, per_row = atlas_size / r;
  const auto pixelAt = [&](int tile, int i, int j) {
    const int x = (tile % per_row) * r + i, y = (tile / per_row) * r + j;
    return &pixels[(static_cast<size_t>(y) * static_cast<size_t>(atlas_size) +
                    static_cast<size_t>(x)) *
                   4];
  };
  p_.clear();
  for (Side& side : sides_)
    side.gx.clear(), side.gy.clear(), side.height.clear(), side.depth.clear();
  for (int j = 0; j < r; ++j) {
    for (int i = 0; i < r; ++i) {
      const float* both[2] = {pixelAt(tile_a, i, j), pixelAt(tile_a + 1, i, j)};
      if (!(both[0][3] > FragmentAtlas::kNoFragment && both[1][3] > FragmentAtlas::kNoFragment))
        continue;
      p_.push_back(static_cast<uint32_t>(i) | static_cast<uint32_t>(j) << 16);
      for (size_t s = 0; s < 2; ++s) {
        sides_[s].gx.push_back(both[s][0]);
        sides_[s].gy.push_back(both[s][1]);
        sides_[s].height.push_back(both[s][2]);
        sides_[s].depth.push_back(both[s][3]);
      }
    }
  }
  models::PatchFragments f{r, patch_width / r, p_};
  for (size_t s = 0; s < 2; ++s) {
    f.gx[s] = sides_[s].gx.data();
    f.gy[s] = sides_[s].gy.data();
    f.height[s] = sides_[s].height.data();
    f.depth[s] = sides_[s].depth.data();
  }
  model.reduce(f, in, contact, scratch_[static_cast<size_t>(model.kind)].get());
}

}  // namespace asperity::glpatch
