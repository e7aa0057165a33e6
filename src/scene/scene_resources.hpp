// The files and generated data a scene refers to, loaded once each while a World is built:
// equal surfaces share one NormalMap, equal OBJ references one mesh.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "asperity/geometry/shape.hpp"
#include "asperity/geometry/surface.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity::scene {

class ResourceCache {
 public:
  explicit ResourceCache(std::string base_dir) : base_dir_(std::move(base_dir)) {}

  // The surface's PNG or generated map; null for a flat surface. Throws asperity::Error.
  std::shared_ptr<const NormalMap> normalMap(const Surface& surface);
  // The grey PNG mask; null for an empty name.
  std::shared_ptr<const GainMask> mask(const std::string& file);
  // The OBJ mesh, scaled and simplified as the scene says.
  std::shared_ptr<const TriangleMeshData> mesh(const SceneMesh& source);

 private:
  std::string base_dir_;
  std::map<std::string, std::shared_ptr<const NormalMap>> normal_maps_;
  std::map<std::string, std::shared_ptr<const GainMask>> masks_;
  std::map<std::string, std::shared_ptr<const TriangleMeshData>> meshes_;
};

// Loads `path` (the resolved OBJ file of `source`), scales and simplifies it (mesh_io).
std::shared_ptr<const TriangleMeshData> loadSceneMesh(const std::string& path,
                                                      const SceneMesh& source);

}  // namespace asperity::scene
