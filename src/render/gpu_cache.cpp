// Uploads of shape meshes (interleaved vertex attributes) and normal maps.
#include "render/gpu_cache.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace asperity::render {
namespace {

// Interleaved layout: position, normal, tangent, bitangent (3 floats each), uv (2 floats).
constexpr int kFloatsPerVertex = 14;

void uploadMesh(const ShapeMesh& mesh, GpuMesh& gpu) {
  std::vector<float> data;
  data.reserve(mesh.positions.size() * kFloatsPerVertex);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    for (const Vec3f* v :
         {&mesh.positions[i], &mesh.normals[i], &mesh.tangents[i], &mesh.bitangents[i]})
      data.insert(data.end(), {v->x(), v->y(), v->z()});
    const Vec2f uv = i < mesh.uvs.size() ? mesh.uvs[i] : Vec2f::Zero();
    data.insert(data.end(), {uv.x(), uv.y()});
  }
  std::vector<uint32_t> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    for (int v : t) indices.push_back(static_cast<uint32_t>(v));

  glBindVertexArray(gpu.vao);
  glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)),
               indices.data(), GL_STATIC_DRAW);
  // Attribute locations match shaders::kMeshVertex.
  const GLsizei stride = kFloatsPerVertex * sizeof(float);
  const GLint sizes[5] = {3, 3, 3, 3, 2};
  size_t offset = 0;
  for (GLuint a = 0; a < 5; ++a) {
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    offset += static_cast<size_t>(sizes[a]);
  }
  glBindVertexArray(0);
  gpu.index_count = static_cast<GLsizei>(indices.size());
}

// Anisotropic filtering keeps grazing views of rough ground sharp, except on Mesa's llvmpipe:
// there (Mesa 22.3) a normal-mapped face seen almost exactly edge-on with MSAA took minutes to
// draw (renderer_test.cpp, EdgeOnNormalMappedFaceDrawsPromptly).
bool anisotropicFiltering() {
  if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))
    return false;
  const GLubyte* renderer = glGetString(GL_RENDERER);
  return renderer == nullptr ||
         std::strstr(reinterpret_cast<const char*>(renderer), "llvmpipe") == nullptr;
}

// Mipmaps, repeat, trilinear and (where available) anisotropic filtering for the bound texture.
void setSampling() {
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  if (anisotropicFiltering()) glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4.0f);
}

}  // namespace

const GpuMesh& MeshCache::get(const std::shared_ptr<const ShapeMesh>& mesh) {
  auto it = entries_.find(mesh.get());
  // A dead weak pointer means the address was reused by a new mesh: upload again.
  if (it != entries_.end() && it->second.source.lock() == mesh) return it->second.gpu;
  if (it != entries_.end()) entries_.erase(it);
  Entry& entry = entries_[mesh.get()];
  entry.source = mesh;
  uploadMesh(*mesh, entry.gpu);
  return entry.gpu;
}

void MeshCache::prune() {
  std::erase_if(entries_, [](const auto& e) { return e.second.source.expired(); });
}

std::pair<TextureCache::Entry*, bool> TextureCache::slot(
    const std::shared_ptr<const void>& source) {
  auto it = entries_.find(source.get());
  if (it != entries_.end() && it->second.source.lock() == source) return {&it->second, false};
  if (it != entries_.end()) entries_.erase(it);
  Entry& entry = entries_[source.get()];
  entry.source = source;
  return {&entry, true};
}

GLuint TextureCache::get(const std::shared_ptr<const NormalMap>& map) {
  auto [entry, upload] = slot(map);
  if (!upload) return entry->texture;
  // Unit vectors packed as 0.5 m + 0.5 in RGBA8 (what 8-bit PNG maps hold; the fastest format
  // to filter on software rasterisers); mipmaps average them, the shader renormalises.
  std::vector<uint8_t> packed;
  packed.reserve(map->texels().size() * 4);
  for (const Vec3f& m : map->texels()) {
    for (int c = 0; c < 3; ++c)
      packed.push_back(
          static_cast<uint8_t>(std::lround(std::clamp(127.5f * (m[c] + 1.0f), 0.0f, 255.0f))));
    packed.push_back(255);
  }
  glBindTexture(GL_TEXTURE_2D, entry->texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, map->width(), map->height(), 0, GL_RGBA,
               GL_UNSIGNED_BYTE, packed.data());
  setSampling();
  glBindTexture(GL_TEXTURE_2D, 0);
  return entry->texture;
}

GLuint TextureCache::get(const std::shared_ptr<const ColorImage>& image) {
  auto [entry, upload] = slot(image);
  if (!upload) return entry->texture;
  glBindTexture(GL_TEXTURE_2D, entry->texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image->width, image->height, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, image->rgba.data());
  setSampling();
  glBindTexture(GL_TEXTURE_2D, 0);
  return entry->texture;
}

void TextureCache::prune() {
  std::erase_if(entries_, [](const auto& e) { return e.second.source.expired(); });
}

}  // namespace asperity::render
