// OBJ + MTL assets and the texture helpers of asset_import (see asset_import_internal.hpp).
#include <tiny_obj_loader.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "asperity/error.hpp"
#include "asperity/geometry/mesh_io.hpp"
#include "asperity/texture/height_map.hpp"
#include "geometry/asset_import_internal.hpp"

namespace asperity::detail {

namespace {

// The first material the faces (of objects named `object`, when given) use that names a normal
// map (`norm`, else a bump map, which obj2gltf and most exporters fill with a tangent-space
// normal map), else the first used one.
const tinyobj::material_t* pickMaterial(const tinyobj::ObjReader& reader,
                                        const std::string& object) {
  const auto& materials = reader.GetMaterials();
  const tinyobj::material_t* first = nullptr;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    if (!object.empty() && shape.name != object) continue;
    for (const int id : shape.mesh.material_ids) {
      if (id < 0 || static_cast<size_t>(id) >= materials.size()) continue;
      const tinyobj::material_t& m = materials[static_cast<size_t>(id)];
      if (!first) first = &m;
      if (!m.normal_texname.empty() || !m.bump_texname.empty() ||
          !m.displacement_texname.empty())
        return &m;
    }
  }
  return first;
}

// True for PNG bytes whose colour type (IHDR, byte 25) is grey or grey + alpha.
bool isGreyPng(const std::vector<uint8_t>& bytes) {
  static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return bytes.size() > 25 && std::equal(signature, signature + 8, bytes.begin()) &&
         (bytes[25] == 0 || bytes[25] == 4);
}

// A grey `bump` or `disp` image is a height map (SPEC 13): grey * multiplier texels high, as the
// heightmap generator reads one, its normals by central differences wrapping like the sampler.
NormalMap heightsToNormals(const std::string& file, double multiplier, const std::string& asset) {
  try {
    const HeightMap heights = loadHeightMapPng(file, multiplier);
    // A texture one texel per unit wide: slopes in height texels per texel.
    return normalsFromHeightMap(heights, static_cast<double>(heights.width));
  } catch (const Error& e) {
    throw Error(asset + ": height map: " + e.what());
  }
}

// Material fields of one MTL entry; the normal map decoded when asked.
AssetMaterial readMaterial(const tinyobj::material_t& m, const std::string& path,
                           const AssetImportOptions& options) {
  AssetMaterial out;
  out.has_base_color = true;
  out.base_color = Vec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]).cwiseMax(0.0).cwiseMin(1.0);
  out.base_color_texture = m.diffuse_texname;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  if (options.load_textures && !m.diffuse_texname.empty()) {
    const std::string part = "base colour image '" + m.diffuse_texname + "'";
    out.base_color_image = decodeAssetColorImage(
        readAssetFile(resolveBeside(dir, m.diffuse_texname), path, part), path, part);
  }
  // `norm` first; `map_Bump` / `bump` with its -bm multiplier, then `disp`, otherwise.
  const bool norm = !m.normal_texname.empty();
  const bool bump = !norm && !m.bump_texname.empty();
  const std::string ref = norm ? m.normal_texname : bump ? m.bump_texname : m.displacement_texname;
  if (ref.empty()) return out;
  out.has_normal_texture = true;
  const tinyobj::texture_option_t& opt =
      norm ? m.normal_texopt : bump ? m.bump_texopt : m.displacement_texopt;
  out.normal_scale = static_cast<double>(opt.bump_multiplier);
  if (!options.load_textures) return out;
  const std::string part = "image '" + ref + "'";
  const std::string file = resolveBeside(dir, ref);
  const std::vector<uint8_t> bytes = readAssetFile(file, path, part);
  out.normal_map_name = part;
  // A grey bump or displacement image holds heights; a colour one, normals (what obj2gltf and
  // most exporters write under `bump`).
  if (!norm && isGreyPng(bytes)) {
    out.normal_map =
        std::make_shared<const NormalMap>(heightsToNormals(file, out.normal_scale, path));
    return out;
  }
  out.normal_map = std::make_shared<const NormalMap>(
      decodeAssetNormalMap(bytes, path, part, options.green, out.normal_scale, out.normal_stats));
  return out;
}

}  // namespace

std::string resolveBeside(const std::string& dir, const std::string& ref) {
  const std::filesystem::path p(ref);
  return p.is_absolute() || dir.empty() ? ref : (std::filesystem::path(dir) / p).string();
}

std::vector<uint8_t> readAssetFile(const std::string& path, const std::string& asset,
                                   const std::string& part) {
  std::optional<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) throw Error(asset + ": " + part + " cannot be read (" + path + ")");
  return std::move(*bytes);
}

NormalMap decodeAssetNormalMap(const std::vector<uint8_t>& bytes, const std::string& asset,
                               const std::string& part, GreenConvention green, double scale,
                               NormalMapStats& stats) {
  // Errors name the asset and the image; invalid texels are counted in `stats` for the caller.
  NormalMap map;
  try {
    // The image's own name inside the decoder's message (part is `image 'NAME'`).
    const size_t open = part.find('\''), close = part.rfind('\'');
    const std::string ref =
        open != std::string::npos && close > open ? part.substr(open + 1, close - open - 1) : part;
    map = decodeNormalMap(bytes, ref, green, scale, &stats);
  } catch (const Error& e) {
    throw Error(asset + ": normal map: " + e.what());
  }
  return map;
}

std::shared_ptr<const ColorImage> decodeAssetColorImage(const std::vector<uint8_t>& bytes,
                                                        const std::string& asset,
                                                        const std::string& part) {
  try {
    return std::make_shared<const ColorImage>(decodeColorImage(bytes, part));
  } catch (const Error& e) {
    throw Error(asset + ": " + e.what());
  }
}

ImportedAsset importObj(const std::string& path, const AssetImportOptions& options) {
  // Geometry exactly as loadObjMesh gives it; `node` names an object or group (`o` / `g`).
  ImportedAsset asset;
  asset.mesh = loadObjMesh(path, options.scale, options.node);
  // The MTL beside it; a missing MTL only means no material.
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.mtl_search_path = std::filesystem::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) return asset;
  if (const tinyobj::material_t* m = pickMaterial(reader, options.node))
    asset.material = readMaterial(*m, path, options);
  if (asset.material.has_normal_texture && asset.mesh->uvs.empty())
    throw Error(path + ": the mesh has no texture coordinates (vt) for its normal map");
  asset.display_mesh = asset.mesh;
  return asset;
}

}  // namespace asperity::detail
