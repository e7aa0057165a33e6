// Surfaces from their sources: normal maps read or generated, gain masks read.
#include "asperity/geometry/surface.hpp"

#include <iostream>

#include "asperity/texture/map_inspect.hpp"
#include "texture/png_codec.hpp"

namespace asperity {

namespace {

// Warns when the map, read with the surface's `directx` setting, has slopes that clearly fit
// the other green convention (map_inspect: the curl of the implied slope field).
void warnGreenContradiction(const std::string& path, GreenConvention green, const NormalMap& map) {
  if (judgeGreenConvention(map).verdict != GreenVerdict::DirectX) return;
  const bool directx = green == GreenConvention::DirectX;
  std::cerr << "asperity: warning: " << path
            << ": the surface says \"directx\": " << (directx ? "true" : "false")
            << " but the map's slopes fit the " << (directx ? "OpenGL" : "DirectX")
            << " convention (asperity texture inspect)\n";
}

}  // namespace

std::shared_ptr<const NormalMap> loadNormalMap(const SurfaceSource& source) {
  if (!source.normal_map_file.empty()) {
    auto map =
        std::make_shared<const NormalMap>(loadNormalMapPng(source.normal_map_file, source.green));
    warnGreenContradiction(source.normal_map_file, source.green, *map);
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

void resolveSurface(Surface& surface) {
  if (!surface.normal_map) surface.normal_map = loadNormalMap(surface.source);
  if (!surface.mask && !surface.source.mask_file.empty())
    surface.mask = std::make_shared<const GainMask>(loadGainMask(surface.source.mask_file));
}

}  // namespace asperity
