// GPU copies of shape meshes and normal maps, uploaded once and kept while the CPU object
// lives (keyed by address, checked through a weak pointer so a reused address re-uploads).
#pragma once

#include <memory>
#include <unordered_map>

#include "asperity/geometry/shape_mesh.hpp"
#include "asperity/texture/color_image.hpp"
#include "asperity/texture/normal_map.hpp"
#include "gl/objects.hpp"

namespace asperity::render {

struct GpuMesh {
  gl::VertexArray vao;
  gl::Buffer vertices;
  gl::Buffer indices;
  GLsizei index_count = 0;
};

class MeshCache {
 public:
  const GpuMesh& get(const std::shared_ptr<const ShapeMesh>& mesh);
  // Drops entries whose mesh no longer exists.
  void prune();

 private:
  struct Entry {
    std::weak_ptr<const ShapeMesh> source;
    GpuMesh gpu;
  };
  std::unordered_map<const ShapeMesh*, Entry> entries_;
};

class TextureCache {
 public:
  // A mipmapped, repeating RGBA8 texture of 0.5 m + 0.5 (rows bottom-up as stored).
  GLuint get(const std::shared_ptr<const NormalMap>& map);
  // A mipmapped, repeating sRGB texture (sampling returns linear colour).
  GLuint get(const std::shared_ptr<const ColorImage>& image);
  void prune();

 private:
  struct Entry {
    std::weak_ptr<const void> source;
    gl::Texture texture;
  };
  // The entry for `source`, and whether it still has to be uploaded.
  std::pair<Entry*, bool> slot(const std::shared_ptr<const void>& source);
  std::unordered_map<const void*, Entry> entries_;
};

}  // namespace asperity::render
