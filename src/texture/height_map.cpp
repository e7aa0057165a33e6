// Height maps at physical scale: PNG in and out, normals at the physical texel size, and the
// roughness statistics `asperity texture inspect` reports (SPEC 13).
#include "asperity/texture/height_map.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/texture/png_io.hpp"
#include "texture/exr_height.hpp"
#include "texture/height_field.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

namespace {

using texgen::bilinearWrapped;

// The scale a height PNG stores, or 0 when it stores none (or a bad one).
double storedScale(const std::vector<uint8_t>& bytes) {
  for (const png::TextEntry& entry : png::readText(bytes)) {
    if (entry.key != kHeightScaleKey) continue;
    double value = 0.0;
    const char* first = entry.text.data();
    const auto [end, ec] = std::from_chars(first, first + entry.text.size(), value);
    if (ec == std::errc() && std::isfinite(value) && value > 0.0) return value;
  }
  return 0.0;
}

// Wrapped central differences in metres per metre at texel (i, j).
void gradient(const HeightMap& map, int i, int j, double du, double dv, double& gu, double& gv) {
  gu = (map.at(wrapTexel(i + 1, map.width), j) - map.at(wrapTexel(i - 1, map.width), j)) /
       (2.0 * du);
  gv = (map.at(i, wrapTexel(j + 1, map.height)) - map.at(i, wrapTexel(j - 1, map.height))) /
       (2.0 * dv);
}

// Normalised autocorrelation at lag `lag` texels, mean of the u and v directions.
double autocorrelation(const HeightMap& map, double mean, double variance, int lag) {
  double sum = 0.0;
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      const double h = map.at(i, j) - mean;
      sum += h * (map.at(wrapTexel(i + lag, map.width), j) - mean);
      sum += h * (map.at(i, wrapTexel(j + lag, map.height)) - mean);
    }
  }
  return sum / (2.0 * static_cast<double>(map.values.size()) * variance);
}

// Lag (texels, interpolated) where the autocorrelation first falls to 1/e; half the map when
// it never does.
double correlationLagTexels(const HeightMap& map, double mean, double variance) {
  const double target = std::exp(-1.0);
  const int last = std::max(1, std::max(map.width, map.height) / 2);
  double previous = 1.0;
  for (int lag = 1; lag <= last; ++lag) {
    const double r = autocorrelation(map, mean, variance, lag);
    if (r <= target) return lag - 1 + (previous - target) / (previous - r);
    previous = r;
  }
  return last;
}

}  // namespace

float HeightMap::sample(float u, float v) const {
  if (empty()) return 0.0f;
  // Texel coordinates with centres at integers.
  const float x = u * static_cast<float>(width) - 0.5f;
  const float y = v * static_cast<float>(height) - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return values[0];
  return bilinearWrapped(x, y, width, height, [this](int i, int j) { return at(i, j); });
}

HeightMap loadHeightMapPng(const std::string& path, double height_scale, HeightMapInfo* info) {
  // Header checks first: a height map is one grey channel (alpha, if any, is ignored).
  const std::vector<uint8_t> bytes = png::readFile(path);
  const png::Header header = png::inspect(bytes, path, kMaxTextureSize);
  if (header.colour_type != png::kGrey && header.colour_type != png::kGreyAlpha)
    throw Error("PNG file '" + path + "': height maps need a greyscale image, got " +
                (header.colour_type == png::kPalette ? "a palette image" : "a colour image"));
  const double stored = storedScale(bytes);
  const double scale = height_scale > 0.0 ? height_scale : stored;
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw Error("PNG file '" + path + "': no height_scale given and none stored in the file");
  // Samples arrive in [0, 1] as floats, which hold all 16 bits exactly.
  const png::Image image = png::decode(bytes, path, kMaxTextureSize, 1);
  HeightMap map(header.width, header.height);
  for (int r = 0; r < map.height; ++r)
    for (int i = 0; i < map.width; ++i)
      map.at(i, map.height - 1 - r) =
          static_cast<float>(scale * image.samples[static_cast<size_t>(r) * map.width + i]);
  if (info) *info = {header.bit_depth == 16 ? 16 : 8, scale, !(height_scale > 0.0)};
  return map;
}

HeightMap loadHeightMap(const std::string& path, double height_scale, HeightMapInfo* info) {
  std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".exr") return loadHeightMapPng(path, height_scale, info);
  const double scale = height_scale > 0.0 ? height_scale : 1.0;
  HeightMap map = exr::load(path, scale);
  if (info) *info = {32, scale, false};
  return map;
}

double saveHeightMapPng(const HeightMap& map, const std::string& path) {
  if (map.empty()) throw Error("PNG file '" + path + "': cannot save an empty height map");
  const auto [lo, hi] = std::minmax_element(map.values.begin(), map.values.end());
  const double range = static_cast<double>(*hi) - static_cast<double>(*lo);
  // Grey g = round((h - min) / range * 65535), top PNG row = map row H - 1.
  std::vector<uint16_t> samples(map.values.size());
  for (int r = 0; r < map.height; ++r) {
    for (int i = 0; i < map.width; ++i) {
      const double h = map.at(i, map.height - 1 - r) - static_cast<double>(*lo);
      const double unit = range > 0.0 ? std::clamp(h / range, 0.0, 1.0) : 0.0;
      samples[static_cast<size_t>(r) * map.width + i] =
          static_cast<uint16_t>(std::lround(unit * 65535.0));
    }
  }
  // Shortest text that reads back as the same double.
  std::ostringstream text;
  text.precision(17);
  text << range;
  std::vector<png::TextEntry> entries;
  if (range > 0.0) entries.push_back({kHeightScaleKey, text.str()});
  png::write(path, map.width, map.height, 1, 16, samples, entries);
  return range;
}

NormalMap normalsFromHeightMap(const HeightMap& map, double texture_size) {
  if (!(texture_size > 0.0)) throw Error("height map: texture_size must be positive");
  const double du = texture_size / map.width;
  const double dv = texture_size / map.height;
  NormalMap normals(map.width, map.height);
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      double gu = 0.0, gv = 0.0;
      gradient(map, i, j, du, dv, gu, gv);
      const double inv = 1.0 / std::sqrt(gu * gu + gv * gv + 1.0);
      normals.at(i, j) = Vec3f(static_cast<float>(-gu * inv), static_cast<float>(-gv * inv),
                               static_cast<float>(inv));
    }
  }
  return normals;
}

HeightStats heightStats(const HeightMap& map, double texture_size) {
  HeightStats s;
  if (map.empty()) return s;
  const auto n = static_cast<double>(map.values.size());
  double mean = 0.0;
  for (float h : map.values) mean += h;
  mean /= n;
  double abs_sum = 0.0, sq_sum = 0.0, slope_sum = 0.0;
  const double du = texture_size / map.width;
  const double dv = texture_size / map.height;
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      const double h = map.at(i, j) - mean;
      abs_sum += std::abs(h);
      sq_sum += h * h;
      double gu = 0.0, gv = 0.0;
      gradient(map, i, j, du, dv, gu, gv);
      slope_sum += gu * gu + gv * gv;
    }
  }
  s.ra = abs_sum / n;
  s.rq = std::sqrt(sq_sum / n);
  s.rms_slope = std::sqrt(slope_sum / n);
  // Correlation length along u and v together, in metres (square texels assumed for the lag).
  if (sq_sum > 0.0) s.correlation_length = correlationLagTexels(map, mean, sq_sum / n) * du;
  return s;
}

}  // namespace asperity
