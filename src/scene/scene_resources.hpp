// The files and generated data a scene refers to, loaded once each while a World is built:
// equal surfaces share one NormalMap, equal asset references one mesh and material.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "asperity/geometry/asset_import.hpp"
#include "asperity/geometry/shape.hpp"
#include "asperity/geometry/surface.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity::scene {

class ResourceCache {
 public:
  explicit ResourceCache(std::string base_dir) : base_dir_(std::move(base_dir)) {}

  // The surface's PNG or generated map; null for a flat surface. Warnings of a map's first
  // load go to `diagnostics`. Throws asperity::Error.
  std::shared_ptr<const NormalMap> normalMap(const Surface& surface, Diagnostics& diagnostics);
  // The grey PNG mask; null for an empty name.
  std::shared_ptr<const GainMask> mask(const std::string& file);
  // The asset (mesh and material), scaled and simplified as the scene says; a normal map in
  // a format that does not fix its green convention is read with `green`. Its normal map's
  // invalid texels are reported to `diagnostics` on first load.
  std::shared_ptr<const ImportedAsset> asset(const SceneMesh& source, GreenConvention green,
                                             Diagnostics& diagnostics);

 private:
  std::string base_dir_;
  std::map<std::string, std::shared_ptr<const NormalMap>> normal_maps_;
  std::map<std::string, std::shared_ptr<const GainMask>> masks_;
  std::map<std::string, std::shared_ptr<const ImportedAsset>> assets_;
};

// The friend of SceneResources through which instantiate() reaches its caches (the public
// header shows no internals).
struct ResourcesAccess {
  static SceneResources::Impl& impl(SceneResources& resources) { return *resources.impl_; }
};

// Loads `path` (the resolved asset file of `source`, asset_import), scales it, picks its node
// and simplifies its mesh (mesh_io).
std::shared_ptr<const ImportedAsset> loadSceneMesh(const std::string& path, const SceneMesh& source,
                                                   GreenConvention green);

}  // namespace asperity::scene
