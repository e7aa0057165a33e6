// Pieces shared by the assimp and OBJ readers of asset_import (private to the geometry stage).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asperity/geometry/asset_import.hpp"

namespace asperity::detail {

// Where an asset came from: its name for messages, its folder (empty when read from memory),
// whether it is glTF (OpenGL green by definition).
struct Source {
  std::string name;
  std::string dir;
  bool gltf = false;
};

// `ref` relative to `dir` unless absolute.
std::string resolveBeside(const std::string& dir, const std::string& ref);

// The bytes of a file the asset refers to; throws `asset: part cannot be read (path)`.
std::vector<uint8_t> readAssetFile(const std::string& path, const std::string& asset,
                                   const std::string& part);

// Decodes a normal texture (SPEC 10 hygiene), errors naming asset and part; invalid texels
// are counted in `stats` (AssetMaterial::normal_stats), which the caller reports.
NormalMap decodeAssetNormalMap(const std::vector<uint8_t>& bytes, const std::string& asset,
                               const std::string& part, GreenConvention green, double scale,
                               NormalMapStats& stats);

// Decodes a base colour texture for display, errors naming asset and part.
std::shared_ptr<const ColorImage> decodeAssetColorImage(const std::vector<uint8_t>& bytes,
                                                        const std::string& asset,
                                                        const std::string& part);

// OBJ + MTL through tinyobjloader: geometry exactly as loadObjMesh, material from the MTL's
// `norm` (else `map_Bump` / `bump`, with -bm) and Kd / map_Kd.
ImportedAsset importObj(const std::string& path, const AssetImportOptions& options);

}  // namespace asperity::detail
