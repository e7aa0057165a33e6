// OBJ loading with tinyobjloader and simplification with meshoptimizer (see mesh_io.hpp).
#include "asperity/geometry/mesh_io.hpp"

#include <meshoptimizer.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "asperity/error.hpp"

namespace asperity {

namespace {

// One line: the reader's first error or warning line.
std::string firstLine(const std::string& text) {
  const size_t end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

// Appends the vertex for an OBJ (position, uv) pair, sharing it when seen before.
int vertexFor(const tinyobj::index_t& idx, const tinyobj::attrib_t& attrib, double scale,
              bool with_uvs, std::map<std::pair<int, int>, int>& seen, TriangleMeshData& mesh,
              const std::string& path) {
  const int vertex_count = static_cast<int>(attrib.vertices.size() / 3);
  const int uv_count = static_cast<int>(attrib.texcoords.size() / 2);
  if (idx.vertex_index < 0 || idx.vertex_index >= vertex_count || idx.texcoord_index >= uv_count) {
    throw Error(path + ": face index out of range");
  }
  const auto key = std::make_pair(idx.vertex_index, with_uvs ? idx.texcoord_index : -1);
  const auto found = seen.find(key);
  if (found != seen.end()) return found->second;
  const auto v = static_cast<size_t>(idx.vertex_index);
  mesh.vertices.emplace_back(scale * attrib.vertices[3 * v], scale * attrib.vertices[3 * v + 1],
                             scale * attrib.vertices[3 * v + 2]);
  if (with_uvs) {
    // A corner without texture coordinates in a textured file gets (0, 0).
    const auto t = static_cast<size_t>(idx.texcoord_index);
    mesh.uvs.push_back(idx.texcoord_index < 0
                           ? Vec2::Zero()
                           : Vec2(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]));
  }
  const int id = static_cast<int>(mesh.vertices.size()) - 1;
  seen.emplace(key, id);
  return id;
}

// Edge collapses can fold two triangles onto the same three vertices (a fin of no volume, its
// edges used four times): dropping each such pair, and degenerate triangles, keeps a closed
// mesh closed for the signed-distance collision path.
void dropFins(TriangleMeshData& mesh) {
  std::map<std::array<int, 3>, int> count;
  auto key = [](std::array<int, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  for (const auto& t : mesh.triangles) ++count[key(t)];
  std::vector<std::array<int, 3>> kept;
  for (const auto& t : mesh.triangles) {
    const auto k = key(t);
    const bool degenerate = k[0] == k[1] || k[1] == k[2];
    if (!degenerate && count[k] % 2 == 1) kept.push_back(t), count[k] = 0;
  }
  mesh.triangles = std::move(kept);
}

}  // namespace

std::shared_ptr<TriangleMeshData> loadObjMesh(const std::string& path, double scale,
                                              const std::string& object) {
  if (!(scale > 0)) throw Error(path + ": mesh scale must be positive");
  // Parse, triangulating polygons; no materials are needed.
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    const std::string why = firstLine(reader.Error());
    throw Error(path + ": cannot read OBJ mesh" + (why.empty() ? "" : " (" + why + ")"));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const bool with_uvs = !attrib.texcoords.empty();
  // Triangles of every object in the file, vertices split where their UVs differ.
  auto mesh = std::make_shared<TriangleMeshData>();
  mesh->source_file = path;
  std::map<std::pair<int, int>, int> seen;
  bool named = false;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    if (!object.empty() && shape.name != object) continue;
    named = true;
    const auto& indices = shape.mesh.indices;
    size_t offset = 0;
    for (const unsigned char corners : shape.mesh.num_face_vertices) {
      if (corners != 3) throw Error(path + ": face with " + std::to_string(corners) + " corners");
      std::array<int, 3> tri{};
      for (size_t c = 0; c < 3; ++c) {
        tri[c] = vertexFor(indices[offset + c], attrib, scale, with_uvs, seen, *mesh, path);
      }
      mesh->triangles.push_back(tri);
      offset += 3;
    }
  }
  if (!object.empty() && !named)
    throw Error(path + ": no object or group is named '" + object + "'");
  if (mesh->triangles.empty()) throw Error(path + ": OBJ mesh has no faces");
  return mesh;
}

std::shared_ptr<TriangleMeshData> simplifyMesh(const TriangleMeshData& mesh,
                                               size_t target_triangles) {
  if (target_triangles == 0) throw Error("simplifyMesh: target_triangles must be at least 1");
  auto out = std::make_shared<TriangleMeshData>(mesh);
  if (mesh.triangles.size() <= target_triangles) return out;
  // Flat arrays for meshoptimizer.
  std::vector<float> positions;
  positions.reserve(mesh.vertices.size() * 3);
  for (const Vec3& v : mesh.vertices) {
    positions.insert(positions.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()),
                                       static_cast<float>(v.z())});
  }
  std::vector<unsigned int> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const auto& tri : mesh.triangles) {
    for (int i : tri) indices.push_back(static_cast<unsigned int>(i));
  }
  // Edge collapses with no error bound first; the sloppy simplifier when they get stuck.
  const size_t target = target_triangles * 3;
  std::vector<unsigned int> result(indices.size());
  size_t count =
      meshopt_simplify(result.data(), indices.data(), indices.size(), positions.data(),
                       mesh.vertices.size(), 3 * sizeof(float), target, 1.0f, 0, nullptr);
  if (count > target) {
    count = meshopt_simplifySloppy(result.data(), indices.data(), indices.size(), positions.data(),
                                   mesh.vertices.size(), 3 * sizeof(float), target, 1.0f, nullptr);
  }
  result.resize(count);
  // Triangles in the original numbering, fins dropped.
  TriangleMeshData reduced;
  for (size_t t = 0; t + 2 < result.size(); t += 3) {
    reduced.triangles.push_back({static_cast<int>(result[t]), static_cast<int>(result[t + 1]),
                                 static_cast<int>(result[t + 2])});
  }
  dropFins(reduced);
  // Keep only the vertices still in use, in their original order.
  std::vector<int> remap(mesh.vertices.size(), -1);
  out->vertices.clear();
  out->uvs.clear();
  out->normals.clear();
  out->tangents.clear();
  out->triangles.clear();
  for (auto tri : reduced.triangles) {
    for (int& i : tri) {
      const auto v = static_cast<size_t>(i);
      if (remap[v] < 0) {
        remap[v] = static_cast<int>(out->vertices.size());
        out->vertices.push_back(mesh.vertices[v]);
        if (!mesh.uvs.empty()) out->uvs.push_back(mesh.uvs[v]);
        if (!mesh.normals.empty()) out->normals.push_back(mesh.normals[v]);
        if (!mesh.tangents.empty()) out->tangents.push_back(mesh.tangents[v]);
      }
      i = remap[v];
    }
    out->triangles.push_back(tri);
  }
  return out;
}

}  // namespace asperity
