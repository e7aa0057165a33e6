// Pictures of the contact: which texels touch at each load, over the composite heights.
#include <algorithm>

#include "asperity/contact_area/contact_area.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

void saveContactMapPng(const SummitSet& set, const std::vector<ContactArea>& results,
                       const std::string& path) {
  constexpr int kGap = 4;
  const int panels = std::max<int>(1, static_cast<int>(results.size()));
  const int width = panels * set.width + (panels - 1) * kGap;
  std::vector<uint16_t> grey(static_cast<size_t>(width) * set.height, 0);
  // Heights mapped to greys 40..140, so that white contact stands out.
  const auto [lo, hi] = std::minmax_element(set.surface.values.begin(), set.surface.values.end());
  const float range = *hi - *lo;
  for (size_t p = 0; p < results.size(); ++p) {
    const std::vector<unsigned char> mask = contactMask(set, results[p]);
    const int x0 = static_cast<int>(p) * (set.width + kGap);
    for (int r = 0; r < set.height; ++r) {
      const int j = set.height - 1 - r;  // PNG rows top first
      for (int i = 0; i < set.width; ++i) {
        const float h = set.surface.at(i, j);
        const float unit = range > 0.0f ? (h - *lo) / range : 0.5f;
        const size_t k = static_cast<size_t>(j) * set.width + i;
        grey[static_cast<size_t>(r) * width + x0 + i] =
            mask[k] ? uint16_t{255} : static_cast<uint16_t>(40.0f + 100.0f * unit);
      }
    }
  }
  png::write(path, width, set.height, 1, 8, grey);
}

}  // namespace asperity
