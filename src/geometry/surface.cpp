// Surfaces from their sources: normal maps read or generated, gain masks read; the resolver
// that code calls before World::createBody.
#include "asperity/geometry/surface.hpp"

#include "asperity/error.hpp"
#include "asperity/geometry/shape.hpp"
#include "asperity/texture/map_inspect.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

namespace {

// Warns when the map, read with the surface's `directx` setting, has slopes that clearly fit
// the other green convention (map_inspect: the curl of the implied slope field).
void warnGreenContradiction(const std::string& path, GreenConvention green, const NormalMap& map,
                            Diagnostics& diagnostics) {
  if (judgeGreenConvention(map).verdict != GreenVerdict::DirectX) return;
  const bool directx = green == GreenConvention::DirectX;
  diagnostics.warn(path + ": the surface says \"directx\": " + (directx ? "true" : "false") +
                   " but the map's slopes fit the " + (directx ? "OpenGL" : "DirectX") +
                   " convention (asperity texture inspect)");
}

}  // namespace

std::shared_ptr<const NormalMap> loadNormalMap(const SurfaceSource& source,
                                               Diagnostics& diagnostics) {
  // A file: decoded, then its invalid texels and green convention reported.
  if (!source.normal_map_file.empty()) {
    NormalMapStats stats;
    auto map = std::make_shared<const NormalMap>(
        loadNormalMapPng(source.normal_map_file, source.green, &stats));
    warnInvalidTexels(source.normal_map_file, stats, diagnostics);
    warnGreenContradiction(source.normal_map_file, source.green, *map, diagnostics);
    return map;
  }
  if (!source.generator.name.empty())
    return std::make_shared<const NormalMap>(generateNormalMap(source.generator));
  return nullptr;
}

GainMask loadGainMask(const std::string& path) {
  const std::vector<uint8_t> bytes = png::readFile(path);
  png::inspect(bytes, path, kMaxTextureSize);
  const png::Image image = png::decode(bytes, path, kMaxTextureSize, 1);
  GainMask mask;
  mask.width = image.header.width;
  mask.height = image.header.height;
  mask.values.resize(image.samples.size());
  // PNG rows run top-down; masks, like normal maps, bottom-up.
  const size_t w = static_cast<size_t>(mask.width);
  const size_t h = static_cast<size_t>(mask.height);
  for (size_t r = 0; r < h; ++r)
    for (size_t i = 0; i < w; ++i) mask.values[(h - 1 - r) * w + i] = image.samples[r * w + i];
  return mask;
}

void resolveSurface(Surface& surface, Diagnostics& diagnostics) {
  if (!surface.normal_map) surface.normal_map = loadNormalMap(surface.source, diagnostics);
  if (!surface.mask && !surface.source.mask_file.empty())
    surface.mask = std::make_shared<const GainMask>(loadGainMask(surface.source.mask_file));
}

std::string unresolvedPart(const Surface& surface) {
  const SurfaceSource& s = surface.source;
  // The normal map first: a file, else a generator; then the mask.
  if (!surface.normal_map && !s.normal_map_file.empty())
    return "normal map \"" + s.normal_map_file + "\"";
  if (!surface.normal_map && !s.generator.name.empty())
    return "normal map generator \"" + s.generator.name + "\"";
  if (!surface.mask && !s.mask_file.empty()) return "mask \"" + s.mask_file + "\"";
  return "";
}

void resolveSurfaces(std::span<Shape> shapes, Diagnostics& diagnostics) {
  // Errors name the shape, as World::createBody's do.
  for (size_t i = 0; i < shapes.size(); ++i) {
    try {
      resolveSurface(shapes[i].surface, diagnostics);
    } catch (const Error& e) {
      throw Error("shape " + std::to_string(i) + ": " + e.what());
    }
  }
}

}  // namespace asperity
