// Meshes with their materials from asset files (SPEC 10): glTF 2.0 (.gltf, .glb), FBX, COLLADA
// and 3DS through the Open Asset Import Library, Wavefront OBJ + MTL through tinyobjloader.
// The entry points are plain functions from a path or bytes to a mesh and a material, so a
// fuzzer can drive them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "asperity/geometry/shape.hpp"
#include "asperity/texture/color_image.hpp"
#include "asperity/texture/normal_map.hpp"
#include "asperity/texture/png_io.hpp"

namespace asperity {

struct AssetImportOptions {
  double scale = 1.0;  // uniform scale of the file's coordinates (1)
  // One node or mesh by name; empty: every mesh of the file, with its node transforms.
  std::string node;
  // Green convention of the normal map for formats that do not define one (OBJ, FBX, COLLADA,
  // 3DS). glTF is always OpenGL (green = +bitangent).
  GreenConvention green = GreenConvention::OpenGL;
  bool load_textures = true;  // false: geometry and material fields only, no image decoding
};

// The first material (in file order of the chosen meshes) that has a normal texture.
struct AssetMaterial {
  bool has_normal_texture = false;              // the material names a normal texture
  std::shared_ptr<const NormalMap> normal_map;  // null without one (or load_textures false)
  std::string normal_map_name;                  // file name, or "embedded texture N"
  // Invalid texels found while decoding (SPEC 10); importing prints nothing, the caller reports
  // them (warnInvalidTexels, as the scene layer does).
  NormalMapStats normal_stats;
  double normal_scale = 1.0;  // glTF normalTexture.scale, MTL -bm
  int uv_set = 0;             // texture coordinate set the map uses
  // glTF KHR_texture_transform of the normal texture, already applied to the mesh's uvs
  // (v up): uv' = uv_transform * (u, v, 1). Identity when the file has none.
  Eigen::Matrix<double, 2, 3> uv_transform = Eigen::Matrix<double, 2, 3>::Identity();
  bool has_base_color = false;
  Vec3 base_color = Vec3(0.7, 0.7, 0.7);  // linear RGB factor (glTF baseColorFactor, MTL Kd)
  std::string base_color_texture;         // its file name; empty when none
  // The base colour texture decoded (display only); null without one or with load_textures off.
  std::shared_ptr<const ColorImage> base_color_image;
};

struct ImportedAsset {
  std::shared_ptr<TriangleMeshData> mesh;  // triangles of all chosen meshes, uvs of `uv_set`
  // The mesh as imported, for display: the same as `mesh` until a caller replaces `mesh` with a
  // simplified copy for collision.
  std::shared_ptr<const TriangleMeshData> display_mesh;
  AssetMaterial material;
};

// Reads an asset file. The format follows the extension (.obj uses tinyobjloader and its MTL,
// everything else assimp). Throws asperity::Error `PATH: what` naming the part at fault (a
// missing image, a broken buffer, a mesh of points or lines, an oversized texture, a mesh
// without UVs under a normal map, an unknown node).
ImportedAsset importAsset(const std::string& path, const AssetImportOptions& options = {});

// The same from bytes in memory; `extension` ("glb", "gltf", "fbx", "dae", "3ds") picks the
// reader and `name` appears in messages ("obj" is refused: OBJ and its MTL are read from
// files). Files the asset refers to cannot be read from memory: only embedded and data-URI
// images load.
ImportedAsset importAssetFromMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                                    const std::string& extension,
                                    const AssetImportOptions& options = {});

// True for the extensions importAsset reads through assimp (lower case, without the dot).
bool isAssimpExtension(const std::string& extension);

}  // namespace asperity
