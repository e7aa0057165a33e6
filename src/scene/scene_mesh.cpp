// OBJ meshes of scene files: loaded and scaled, then simplified to the scene's target triangle
// count (geometry/mesh_io.hpp).
#include "asperity/geometry/mesh_io.hpp"
#include "scene/scene_resources.hpp"

namespace asperity::scene {

std::shared_ptr<const TriangleMeshData> loadSceneMesh(const std::string& path,
                                                      const SceneMesh& source) {
  std::shared_ptr<TriangleMeshData> mesh = loadObjMesh(path, source.scale);
  // simplify = 0 keeps every triangle.
  if (source.simplify > 0) mesh = simplifyMesh(*mesh, static_cast<size_t>(source.simplify));
  return mesh;
}

}  // namespace asperity::scene
