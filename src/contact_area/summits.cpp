// The composite surface of two height maps and its summits (Greenwood and Williamson).
#include <algorithm>
#include <cmath>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/error.hpp"

namespace asperity {

namespace {

int wrapIndex(int index, int size) {
  const int m = index % size;
  return m < 0 ? m + size : m;
}

// B's heights plus A's on B's grid (A resampled bilinearly when its size differs).
HeightMap composite(const HeightMap& b, const HeightMap* a) {
  HeightMap sum = b;
  if (a != nullptr && !a->empty()) {
    const bool same = a->width == b.width && a->height == b.height;
    for (int j = 0; j < b.height; ++j) {
      for (int i = 0; i < b.width; ++i) {
        const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(b.width);
        const float v = (static_cast<float>(j) + 0.5f) / static_cast<float>(b.height);
        sum.at(i, j) += same ? a->at(i, j) : a->sample(u, v);
      }
    }
  }
  return sum;
}

// Mean zero: the separation is measured from the mean composite height.
void removeMean(HeightMap& h) {
  double mean = 0.0;
  for (float v : h.values) mean += v;
  mean /= static_cast<double>(h.values.size());
  for (float& v : h.values) v = static_cast<float>(v - mean);
}

// A summit is higher than the neighbours before it in row order and not lower than those
// after it, so a plateau of equal texels gives one summit, not none or several.
bool isSummit(const HeightMap& h, int i, int j) {
  // Wrapped neighbour rows and columns without a division (the per-contact model scans every
  // pixel of every patch).
  const int im = i == 0 ? h.width - 1 : i - 1, ip = i + 1 == h.width ? 0 : i + 1;
  const int jm = j == 0 ? h.height - 1 : j - 1, jp = j + 1 == h.height ? 0 : j + 1;
  // All eight tests, without short-circuit branches: whether a texel is a summit is as
  // unpredictable as the heights, and the tests are cheaper than the mispredictions.
  const float centre = h.at(i, j);
  const float* below = &h.values[static_cast<size_t>(jm) * static_cast<size_t>(h.width)];
  const float* row = &h.values[static_cast<size_t>(j) * static_cast<size_t>(h.width)];
  const float* above = &h.values[static_cast<size_t>(jp) * static_cast<size_t>(h.width)];
  const int before =
      (below[im] < centre) & (below[i] < centre) & (below[ip] < centre) & (row[im] < centre);
  const int after =
      (row[ip] <= centre) & (above[im] <= centre) & (above[i] <= centre) & (above[ip] <= centre);
  return (before & after) != 0;
}

// Mean curvature -(h_uu + h_vv) / 2 by second differences (1 / m).
double summitCurvature(const HeightMap& h, int i, int j, double texel) {
  const double c = h.at(i, j);
  const double huu =
      h.at(wrapIndex(i + 1, h.width), j) + h.at(wrapIndex(i - 1, h.width), j) - 2 * c;
  const double hvv =
      h.at(i, wrapIndex(j + 1, h.height)) + h.at(i, wrapIndex(j - 1, h.height)) - 2 * c;
  return -0.5 * (huu + hvv) / (texel * texel);
}

// sigma (spread of summit heights) and beta (mean radius).
void summarise(SummitSet& set) {
  if (set.summits.empty()) return;
  const auto n = static_cast<double>(set.summits.size());
  double mean = 0.0, radius = 0.0;
  for (const Summit& s : set.summits) {
    mean += s.height;
    radius += s.radius;
  }
  mean /= n;
  double var = 0.0;
  for (const Summit& s : set.summits) var += (s.height - mean) * (s.height - mean);
  set.sigma = std::sqrt(var / n);
  set.beta = radius / n;
}

}  // namespace

SummitSet findSummits(const HeightMap& b, const HeightMap* a, double texture_size) {
  if (b.empty()) throw Error("contact area: empty height map");
  SummitSet set;
  findSummitsInto(composite(b, a), texture_size, set);
  return set;
}

void findSummitsInto(const HeightMap& heights, double texture_size, SummitSet& set) {
  if (heights.empty()) throw Error("contact area: empty height map");
  if (!(texture_size > 0.0) || !std::isfinite(texture_size))
    throw Error("contact area: texture size must be a positive number of metres");
  HeightMap& h = set.surface;
  h.width = heights.width;
  h.height = heights.height;
  h.values.assign(heights.values.begin(), heights.values.end());
  removeMean(h);
  set.summits.clear();
  set.width = h.width;
  set.height = h.height;
  set.texel = texture_size / h.width;
  set.apparent_area = texture_size * (texture_size * h.height / h.width);
  set.sigma = set.beta = 0.0;
  const auto [lo, hi] = std::minmax_element(h.values.begin(), h.values.end());
  set.flat = *hi - *lo == 0.0f;
  if (set.flat) return;
  for (int j = 0; j < h.height; ++j) {
    for (int i = 0; i < h.width; ++i) {
      if (!isSummit(h, i, j)) continue;
      // A summit on a plateau of equal texels has no curvature, which the sphere model cannot
      // hold; its radius is capped at 64 texels (a flat top a few texels wide).
      const double curvature =
          std::max(summitCurvature(h, i, j, set.texel), 1.0 / (64.0 * set.texel));
      set.summits.push_back({h.at(i, j), 1.0 / curvature, i, j});
    }
  }
  std::sort(set.summits.begin(), set.summits.end(),
            [](const Summit& x, const Summit& y) { return x.height > y.height; });
  summarise(set);
}

}  // namespace asperity
