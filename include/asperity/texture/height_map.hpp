// Height (displacement) maps at physical scale (SPEC 13): heights in metres over a texture that
// covers `texture_size` metres per repeat, their normals normalize(-h_u, -h_v, 1) at the physical
// texel size (the convention of SPEC 6's normal maps), and their roughness statistics.
#pragma once

#include <string>
#include <vector>

#include "asperity/texture/normal_map.hpp"

namespace asperity {

// Heights in metres; texel (i, j) as in NormalMap (i along +u, rows bottom-up).
struct HeightMap {
  int width = 0;
  int height = 0;
  std::vector<float> values;

  HeightMap() = default;
  HeightMap(int w, int h) : width(w), height(h), values(static_cast<size_t>(w) * h, 0.0f) {}
  bool empty() const { return values.empty(); }
  float& at(int i, int j) { return values[static_cast<size_t>(j) * width + i]; }
  float at(int i, int j) const { return values[static_cast<size_t>(j) * width + i]; }
  // Bilinear height at texture coordinates (u, v), tiling with period 1 (texel centres at
  // ((i + .5) / W, (j + .5) / H), as NormalMap::sample).
  float sample(float u, float v) const;
};

// The tEXt keyword under which a height PNG stores its height_scale (metres per full range).
inline constexpr const char* kHeightScaleKey = "height_scale";

// What a height map file held besides its heights.
struct HeightMapInfo {
  int bits = 0;              // 8 or 16 (PNG); 32 for float files
  double height_scale = 0;   // metres per full range used for the heights
  bool scale_from_file = false;  // the scale came from the file's text chunk
};

// A greyscale PNG (8 or 16 bits; 16 bits keep all 16) as heights grey * height_scale metres.
// height_scale <= 0 takes the scale the file stores under kHeightScaleKey. Throws
// asperity::Error naming the file for a missing or corrupt file, a colour or palette image,
// or no usable scale.
HeightMap loadHeightMapPng(const std::string& path, double height_scale = 0.0,
                           HeightMapInfo* info = nullptr);

// A height map by its file name: `.exr` (any case) is a 32-bit float OpenEXR file whose values
// are multiplied by height_scale (<= 0: 1, the values are metres; the channel named height, Z,
// Y or R, or the only one; at most 8192 texels a side, checked from the header, and every
// scaled height finite), anything else a PNG as loadHeightMapPng. Builds without Debian's
// libopenexr-dev refuse EXR files with an error saying so.
HeightMap loadHeightMap(const std::string& path, double height_scale = 0.0,
                        HeightMapInfo* info = nullptr);

// Writes a 16-bit greyscale PNG whose full range spans the map's heights (min at 0), storing
// that range (metres) under kHeightScaleKey; returns it (0 for a flat map, written all black).
double saveHeightMapPng(const HeightMap& map, const std::string& path);

// Normals m = normalize(-dh/du, -dh/dv, 1) by central differences over texels of
// texture_size / width by texture_size / height metres, wrapping (textures tile).
NormalMap normalsFromHeightMap(const HeightMap& map, double texture_size);

// Roughness of a height map at physical scale (SPEC 13), all in metres or 1.
struct HeightStats {
  double ra = 0.0;                  // mean |h - mean h|
  double rq = 0.0;                  // rms(h - mean h)
  double rms_slope = 0.0;           // h'_rms: rms of |grad h| by central differences
  double correlation_length = 0.0;  // lag where the autocorrelation (mean of u and v) falls to 1/e
};
HeightStats heightStats(const HeightMap& map, double texture_size);

}  // namespace asperity
