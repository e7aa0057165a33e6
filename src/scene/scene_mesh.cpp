// OBJ meshes of scene files: triangles with their UVs (tinyobjloader), a uniform scale, and an
// optional simplification to a target triangle count (meshoptimizer).
#include <tiny_obj_loader.h>

#include <meshoptimizer.h>
#include <map>

#include "asperity/error.hpp"
#include "scene/scene_resources.hpp"

namespace asperity::scene {

namespace {

// One vertex per distinct (position, uv) pair of the OBJ's faces.
TriangleMeshData readObj(const std::string& path, double scale) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw Error(path + ": cannot read OBJ mesh: " + (why.empty() ? "unknown error" : why));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  TriangleMeshData mesh;
  mesh.source_file = path;
  std::map<std::pair<int, int>, int> index_of;
  bool all_uvs = true;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (size_t f = 0; f + 2 < indices.size(); f += 3) {
      std::array<int, 3> tri{};
      for (size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t& id = indices[f + k];
        const auto [it, inserted] = index_of.try_emplace({id.vertex_index, id.texcoord_index},
                                                         static_cast<int>(mesh.vertices.size()));
        if (inserted) {
          const size_t v = static_cast<size_t>(id.vertex_index) * 3;
          mesh.vertices.push_back(
              scale * Vec3(attrib.vertices[v], attrib.vertices[v + 1], attrib.vertices[v + 2]));
          all_uvs = all_uvs && id.texcoord_index >= 0;
          const size_t t = static_cast<size_t>(std::max(id.texcoord_index, 0)) * 2;
          mesh.uvs.push_back(id.texcoord_index >= 0
                                 ? Vec2(attrib.texcoords[t], attrib.texcoords[t + 1])
                                 : Vec2::Zero());
        }
        tri[k] = it->second;
      }
      mesh.triangles.push_back(tri);
    }
  }
  if (!all_uvs) mesh.uvs.clear();  // UVs for all vertices or none (shape.hpp)
  if (mesh.triangles.empty()) throw Error(path + ": OBJ mesh has no triangles");
  return mesh;
}

// meshoptimizer's edge-collapse simplification toward `target` triangles (UVs are kept).
void simplify(TriangleMeshData& mesh, int target) {
  if (target <= 0 || static_cast<size_t>(target) >= mesh.triangles.size()) return;
  std::vector<unsigned int> indices;
  for (const auto& t : mesh.triangles)
    for (int i : t) indices.push_back(static_cast<unsigned int>(i));
  std::vector<float> positions;
  for (const Vec3& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(v[k]));
  std::vector<unsigned int> out(indices.size());
  const size_t count = meshopt_simplify(out.data(), indices.data(), indices.size(),
                                        positions.data(), mesh.vertices.size(), 3 * sizeof(float),
                                        static_cast<size_t>(target) * 3, 1.0f, 0, nullptr);
  // Keep only the vertices the remaining triangles use (hulls are built from vertices).
  std::vector<int> remap(mesh.vertices.size(), -1);
  TriangleMeshData kept;
  kept.source_file = mesh.source_file;
  for (size_t i = 0; i + 2 < count; i += 3) {
    std::array<int, 3> tri{};
    for (size_t k = 0; k < 3; ++k) {
      int& r = remap[out[i + k]];
      if (r < 0) {
        r = static_cast<int>(kept.vertices.size());
        kept.vertices.push_back(mesh.vertices[out[i + k]]);
        if (!mesh.uvs.empty()) kept.uvs.push_back(mesh.uvs[out[i + k]]);
      }
      tri[k] = r;
    }
    kept.triangles.push_back(tri);
  }
  mesh = std::move(kept);
}

}  // namespace

std::shared_ptr<const TriangleMeshData> loadSceneMesh(const std::string& path,
                                                      const SceneMesh& source) {
  TriangleMeshData mesh = readObj(path, source.scale);
  simplify(mesh, source.simplify);
  return std::make_shared<const TriangleMeshData>(std::move(mesh));
}

}  // namespace asperity::scene
