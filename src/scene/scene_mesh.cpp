// Meshes of scene files: assets (OBJ, glTF, FBX, COLLADA, 3DS) loaded with their material,
// scaled, reduced to one node when the scene names one, then simplified to the scene's target
// triangle count (geometry/asset_import.hpp, geometry/mesh_io.hpp).
#include "asperity/geometry/mesh_io.hpp"
#include "scene/scene_resources.hpp"

namespace asperity::scene {

std::shared_ptr<const ImportedAsset> loadSceneMesh(const std::string& path, const SceneMesh& source,
                                                   GreenConvention green) {
  AssetImportOptions options;
  options.scale = source.scale;
  options.node = source.node;
  options.green = green;
  auto asset = std::make_shared<ImportedAsset>(importAsset(path, options));
  // simplify = 0 keeps every triangle.
  if (source.simplify > 0)
    asset->mesh = simplifyMesh(*asset->mesh, static_cast<size_t>(source.simplify));
  return asset;
}

}  // namespace asperity::scene
