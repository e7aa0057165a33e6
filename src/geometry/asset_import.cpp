// Assets through the Open Asset Import Library (see asset_import.hpp): chosen nodes' meshes
// gathered into one triangle mesh, the first normal-mapped material decoded.
#include "asperity/geometry/asset_import.hpp"

#include <assimp/BaseImporter.h>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <span>

#include "asperity/error.hpp"
#include "geometry/asset_import_internal.hpp"
#include "geometry/child_probe.hpp"

namespace asperity {

namespace {

// Reading as assimp does it: polygons split into triangles, equal corners shared, structure
// validated (so a broken file fails here, not later).
constexpr unsigned kImportFlags =
    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;

// An assimp importer that reads only the format the extension names. Left alone, assimp guesses
// another format from the content when the named one cannot read it, and some of those readers
// take a few hostile bytes for gigabytes to allocate (tests/fuzz found one behind a ".glb").
class FormatImporter {
 public:
  explicit FormatImporter(const std::string& extension) {
    for (size_t i = importer_.GetImporterCount(); i-- > 0;) {
      Assimp::BaseImporter* reader = importer_.GetImporter(i);
      std::set<std::string> extensions;
      reader->GetExtensionList(extensions);
      if (extensions.count(extension) != 0) continue;
      importer_.UnregisterLoader(reader);
      unregistered_.emplace_back(reader);
    }
  }
  Assimp::Importer& get() { return importer_; }

 private:
  Assimp::Importer importer_;
  // assimp deletes only the readers still registered; these are ours to delete.
  std::vector<std::unique_ptr<Assimp::BaseImporter>> unregistered_;
};

// A mesh chosen for import with the transform of the node that holds it.
struct Placed {
  const aiMesh* mesh = nullptr;
  aiMatrix4x4 transform;
};

// Meshes under `node` (with accumulated transforms); all of them when `take` is set, else only
// those of nodes or meshes named `name` (and everything below such a node).
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
             const std::string& name, bool take, std::vector<Placed>& out) {
  const aiMatrix4x4 world = parent * node.mTransformation;
  const bool take_node = take || node.mName.C_Str() == name;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh* mesh = scene.mMeshes[node.mMeshes[k]];
    if (take_node || mesh->mName.C_Str() == name) out.push_back({mesh, world});
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    collect(scene, *node.mChildren[c], world, name, take_node, out);
}

// The first material of the chosen meshes with a normal texture (or the first material).
const aiMaterial* pickMaterial(const aiScene& scene, const std::vector<Placed>& placed) {
  const aiMaterial* first = nullptr;
  for (const Placed& p : placed) {
    if (p.mesh->mMaterialIndex >= scene.mNumMaterials) continue;
    const aiMaterial* m = scene.mMaterials[p.mesh->mMaterialIndex];
    if (!first) first = m;
    if (m->GetTextureCount(aiTextureType_NORMALS) > 0) return m;
  }
  return first;
}

// A texture's bytes: embedded ("*N", .glb, data URI) or a file beside the asset; `name` is the
// part named in errors.
std::vector<uint8_t> textureBytes(const aiScene& scene, const std::string& ref,
                                  const std::string& asset_dir, const std::string& asset,
                                  const std::string& name) {
  if (const aiTexture* t = scene.GetEmbeddedTexture(ref.c_str())) {
    // mHeight == 0: compressed bytes (PNG, JPEG) of mWidth bytes.
    if (t->mHeight != 0)
      throw Error(asset + ": " + name + " is stored uncompressed; only PNG or JPEG is read");
    const auto* p = reinterpret_cast<const uint8_t*>(t->pcData);
    return std::vector<uint8_t>(p, p + t->mWidth);
  }
  if (asset_dir.empty() && !std::filesystem::path(ref).is_absolute())
    throw Error(asset + ": " + name + " is a separate file, which cannot be read from memory");
  return detail::readAssetFile(detail::resolveBeside(asset_dir, ref), asset, name);
}

// glTF's base colour factor, else the diffuse colour; the base colour texture, decoded when
// textures are loaded.
void readBaseColor(const aiScene& scene, const aiMaterial& m, const detail::Source& src,
                   const AssetImportOptions& options, AssetMaterial& out) {
  aiColor4D c;
  if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS ||
      m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
    out.has_base_color = true;
    out.base_color = Vec3(std::clamp<double>(c.r, 0, 1), std::clamp<double>(c.g, 0, 1),
                          std::clamp<double>(c.b, 0, 1));
  }
  aiString tex;
  if (m.GetTexture(AI_MATKEY_BASE_COLOR_TEXTURE, &tex) == AI_SUCCESS ||
      m.GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS)
    out.base_color_texture = tex.C_Str();
  if (out.base_color_texture.empty() || !options.load_textures) return;
  const std::string part = "base colour image '" + out.base_color_texture + "'";
  out.base_color_image = detail::decodeAssetColorImage(
      textureBytes(scene, out.base_color_texture, src.dir, src.name, part), src.name, part);
}

// glTF's KHR_texture_transform as an affine map of uvs in the mesh's v-up convention. assimp
// (5.2) stores the extension's offset converted for its v flip and its rotation about the
// image centre; this undoes that conversion to get the extension's own offset o, rotation r
// and scale s, then expresses uv' = T(o) R(r) S(s) uv (glTF, v down) with v' = 1 - v.
Eigen::Matrix<double, 2, 3> gltfUvTransform(const aiUVTransform& t) {
  const double sx = t.mScaling.x, sy = t.mScaling.y, r = -static_cast<double>(t.mRotation);
  const double c = std::cos(r), s = std::sin(r);
  const double ox = t.mTranslation.x - 0.5 * sx * (1 - c + s);
  const double oy = 1 - sy - t.mTranslation.y + 0.5 * sy * (s + c - 1);
  // glTF: u' = c sx u + s sy vg + ox, vg' = -s sx u + c sy vg + oy, with vg = 1 - v.
  Eigen::Matrix<double, 2, 3> m;
  m << c * sx, -s * sy, s * sy + ox,  //
      s * sx, c * sy, 1 - c * sy - oy;
  return m;
}

// The normal texture of `m` (SPEC 10): uv set, glTF scale and texture transform, decoded with
// hygiene.
void readNormalTexture(const aiScene& scene, const aiMaterial& m, const detail::Source& src,
                       const AssetImportOptions& options, AssetMaterial& out) {
  aiString ref;
  if (m.GetTexture(aiTextureType_NORMALS, 0, &ref) != AI_SUCCESS) return;
  int uv_set = 0;
  if (m.Get(AI_MATKEY_UVWSRC(aiTextureType_NORMALS, 0), uv_set) == AI_SUCCESS)
    out.uv_set = std::max(uv_set, 0);
  ai_real scale = 1;
  if (m.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), scale) == AI_SUCCESS)
    out.normal_scale = static_cast<double>(scale);
  aiUVTransform transform;
  if (src.gltf && m.Get(AI_MATKEY_UVTRANSFORM(aiTextureType_NORMALS, 0), transform) == AI_SUCCESS)
    out.uv_transform = gltfUvTransform(transform);
  out.has_normal_texture = true;
  if (!options.load_textures) return;
  // glTF fixes the convention; other formats take the caller's.
  const GreenConvention green = src.gltf ? GreenConvention::OpenGL : options.green;
  const std::string name =
      (scene.GetEmbeddedTexture(ref.C_Str()) ? "embedded texture '" : "image '") +
      std::string(ref.C_Str()) + "'";
  const std::vector<uint8_t> bytes = textureBytes(scene, ref.C_Str(), src.dir, src.name, name);
  out.normal_map_name = name;
  out.normal_map = std::make_shared<const NormalMap>(detail::decodeAssetNormalMap(
      bytes, src.name, name, green, out.normal_scale, out.normal_stats));
}

// Whether a mesh has texture coordinates of set `uv_set`.
bool hasUvs(const aiMesh& m, int uv_set) {
  return uv_set < AI_MAX_NUMBER_OF_TEXTURECOORDS &&
         m.HasTextureCoords(static_cast<unsigned>(uv_set));
}

// Normals transform by the inverse transpose of the node's linear part.
aiMatrix3x3 normalMatrix(const aiMatrix4x4& transform) {
  aiMatrix3x3 m(transform);
  return m.Inverse().Transpose();
}

// The file's unit normal of vertex `v` through the node transform.
Vec3 fileNormal(const aiMesh& m, unsigned v, const aiMatrix4x4& transform) {
  const aiVector3D n = normalMatrix(transform) * m.mNormals[v];
  const Vec3 out(n.x, n.y, n.z);
  return out.squaredNorm() > 0.0 ? out.normalized() : Vec3::UnitZ();
}

// The file's tangent of vertex `v` through the node transform, with its bitangent sign
// (glTF TANGENT: assimp stores b = w n x t, so w is the sign of (n x t) . b after transforming).
Vec4 fileTangent(const aiMesh& m, unsigned v, const aiMatrix4x4& transform) {
  const aiMatrix3x3 linear(transform);
  const aiVector3D t = linear * m.mTangents[v], b = linear * m.mBitangents[v];
  const aiVector3D n = m.HasNormals() ? normalMatrix(transform) * m.mNormals[v] : t ^ b;
  // A zero tangent (a broken file) stays zero: the frame then falls back to the normal's axes.
  const Vec3 raw(t.x, t.y, t.z);
  const Vec3 tt = raw.squaredNorm() > 0.0 ? raw.normalized() : Vec3::Zero();
  const double w = (Vec3(n.x, n.y, n.z).cross(tt)).dot(Vec3(b.x, b.y, b.z)) < 0.0 ? -1.0 : 1.0;
  return Vec4(tt.x(), tt.y(), tt.z(), w);
}

// Which per-vertex attributes every chosen mesh has, so that all of them are kept.
struct Kept {
  bool uvs = false;
  bool normals = false;
  bool tangents = false;
};

// Appends one placed mesh's triangles (positions transformed and scaled, the material's uvs,
// transformed, the file's normals and tangents, as `kept` says); a normal-mapped asset must
// have uvs.
void appendMesh(const Placed& p, double scale, const AssetMaterial& material, const Kept& kept,
                const std::string& asset, TriangleMeshData& out) {
  const int uv_set = material.uv_set;
  const bool need_uvs = material.has_normal_texture;
  const aiMesh& m = *p.mesh;
  const std::string which = "mesh '" + std::string(m.mName.C_Str()) + "'";
  // Points and lines cannot touch anything.
  if (m.mPrimitiveTypes & (aiPrimitiveType_POINT | aiPrimitiveType_LINE))
    throw Error(asset + ": " + which + " has non-triangle primitives (points or lines)");
  if (need_uvs && !hasUvs(m, uv_set))
    throw Error(asset + ": " + which + " has no texture coordinates (UV set " +
                std::to_string(uv_set) + ") for its normal map");
  const size_t base = out.vertices.size();
  for (unsigned v = 0; v < m.mNumVertices; ++v) {
    const aiVector3D q = p.transform * m.mVertices[v];
    out.vertices.emplace_back(scale * q.x, scale * q.y, scale * q.z);
    if (kept.uvs) {
      const aiVector3D& t = m.mTextureCoords[uv_set][v];
      out.uvs.push_back(material.uv_transform * Vec3(t.x, t.y, 1.0));
    }
    if (kept.normals) out.normals.push_back(fileNormal(m, v, p.transform));
    if (kept.tangents) out.tangents.push_back(fileTangent(m, v, p.transform));
  }
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3)
      throw Error(asset + ": " + which + " has a face with " + std::to_string(face.mNumIndices) +
                  " corners");
    out.triangles.push_back({static_cast<int>(base + face.mIndices[0]),
                             static_cast<int>(base + face.mIndices[1]),
                             static_cast<int>(base + face.mIndices[2])});
  }
}

// From assimp's scene to our mesh and material.
ImportedAsset convert(const aiScene& scene, const detail::Source& src,
                      const AssetImportOptions& options) {
  if (!scene.mRootNode) throw Error(src.name + ": the file holds no nodes");
  std::vector<Placed> placed;
  collect(scene, *scene.mRootNode, aiMatrix4x4(), options.node, options.node.empty(), placed);
  if (placed.empty())
    throw Error(src.name + (options.node.empty()
                                ? std::string(": the file holds no meshes")
                                : ": no node or mesh is named '" + options.node + "'"));
  // Material first: its normal map decides which UV set the mesh keeps.
  ImportedAsset asset;
  if (const aiMaterial* m = pickMaterial(scene, placed)) {
    readBaseColor(scene, *m, src, options, asset.material);
    readNormalTexture(scene, *m, src, options, asset.material);
  }
  // UVs are kept when every chosen mesh has them (a scene's own normal_map follows them too).
  const int uv_set = asset.material.uv_set;
  auto all = [&](auto has) { return std::all_of(placed.begin(), placed.end(), has); };
  Kept kept;
  kept.uvs = asset.material.has_normal_texture ||
             all([&](const Placed& p) { return hasUvs(*p.mesh, uv_set); });
  // Normals and tangents as the file stores them (without aiProcess_GenNormals and
  // aiProcess_CalcTangentSpace assimp invents none). The tangents describe the file's uvs: a
  // texture transform that turns or mirrors the uvs leaves them to the UV gradients instead.
  kept.normals = all([](const Placed& p) { return p.mesh->HasNormals(); });
  kept.tangents = kept.uvs && asset.material.uv_transform.leftCols<2>().isDiagonal() &&
                  (asset.material.uv_transform.leftCols<2>().diagonal().array() > 0).all() &&
                  all([](const Placed& p) { return p.mesh->HasTangentsAndBitangents(); });
  asset.mesh = std::make_shared<TriangleMeshData>();
  asset.mesh->source_file = src.name;
  for (const Placed& p : placed)
    appendMesh(p, options.scale, asset.material, kept, src.name, *asset.mesh);
  if (asset.mesh->triangles.empty()) throw Error(src.name + ": the chosen meshes have no faces");
  asset.display_mesh = asset.mesh;
  return asset;
}

// Lower-case extension without the dot.
std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// assimp's one-line reason, without a trailing newline.
std::string importerError(const Assimp::Importer& importer) {
  std::string why = importer.GetErrorString();
  while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
  std::replace(why.begin(), why.end(), '\n', ' ');
  return why.empty() ? "unreadable" : why;
}

// Reads little-endian uint32 at `at`.
uint32_t littleEndian32(const uint8_t* at) {
  return uint32_t{at[0]} | uint32_t{at[1]} << 8 | uint32_t{at[2]} << 16 | uint32_t{at[3]} << 24;
}

// A GLB's header (glTF 2.0, "Binary glTF Layout"): magic "glTF", version, total length, then the
// first chunk's length. assimp allocates and fills both lengths before reading (a 1 kB file
// claiming a 4 GB chunk takes 4 GB and half a minute), so they must fit the file. `head` holds
// the file's first bytes (up to 20).
void checkGlbLengths(std::span<const uint8_t> head, uint64_t file_size, const std::string& name) {
  if (head.size() < 16 || std::memcmp(head.data(), "glTF", 4) != 0) return;  // assimp's to judge
  const uint32_t total = littleEndian32(&head[8]), chunk = littleEndian32(&head[12]);
  if (total > file_size)
    throw Error(name + ": the GLB header gives a length of " + std::to_string(total) +
                " bytes, but the file has " + std::to_string(file_size));
  if (uint64_t{chunk} + 20 > total)
    throw Error(name + ": the GLB's first chunk claims " + std::to_string(chunk) +
                " bytes, more than the file's " + std::to_string(total) + " hold");
}

// The child's limits for reading a file of `bytes`: what assimp needs grows with the file.
detail::ProbeLimits probeLimits(uint64_t bytes) {
  detail::ProbeLimits limits;
  limits.memory_bytes += static_cast<size_t>(std::min<uint64_t>(bytes, uint64_t{1} << 40) * 8);
  return limits;
}

// The scene that `read` (a ReadFile or ReadFileFromMemory on the importer it is given) makes of
// the asset `name` of `bytes` bytes and `extension`'s format, held by `importer`. assimp may
// crash, hang or run away with memory on a malformed file: a child reads it first
// (geometry/child_probe.hpp).
template <class Read>
const aiScene& readGuarded(FormatImporter& importer, const std::string& name,
                           const std::string& extension, uint64_t bytes, const Read& read) {
  detail::probeInChild(
      name, [&] { read(FormatImporter(extension).get()); }, probeLimits(bytes));
  const aiScene* scene = read(importer.get());
  if (!scene) throw Error(name + ": cannot import (" + importerError(importer.get()) + ")");
  return *scene;
}

}  // namespace

bool isAssimpExtension(const std::string& extension) {
  static const char* const kKnown[] = {"gltf", "glb", "fbx", "dae", "3ds", "obj"};
  return std::find(std::begin(kKnown), std::end(kKnown), extension) != std::end(kKnown);
}

ImportedAsset importAsset(const std::string& path, const AssetImportOptions& options) {
  if (!(options.scale > 0)) throw Error(path + ": mesh scale must be positive");
  const std::string ext = extensionOf(path);
  // OBJ keeps tinyobjloader (its MTL included), so OBJ scenes load exactly as before.
  if (ext == "obj") return detail::importObj(path, options);
  if (!isAssimpExtension(ext))
    throw Error(path + ": unknown mesh format '." + ext +
                "' (read: .obj, .gltf, .glb, .fbx, .dae, .3ds)");
  if (!std::filesystem::is_regular_file(path)) throw Error(path + ": cannot open file");
  const uint64_t size = std::filesystem::file_size(path);
  if (ext == "glb") {
    std::array<uint8_t, 20> head{};
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(head.data()), head.size());
    checkGlbLengths(std::span<const uint8_t>(head.data(), static_cast<size_t>(in.gcount())), size,
                    path);
  }
  FormatImporter importer(ext);
  const aiScene& scene = readGuarded(importer, path, ext, size, [&](Assimp::Importer& reader) {
    return reader.ReadFile(path, kImportFlags);
  });
  const detail::Source src{path, std::filesystem::path(path).parent_path().string(),
                           ext == "gltf" || ext == "glb"};
  return convert(scene, src, options);
}

ImportedAsset importAssetFromMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                                    const std::string& extension,
                                    const AssetImportOptions& options) {
  if (!(options.scale > 0)) throw Error(name + ": mesh scale must be positive");
  // OBJ is read from files only, by tinyobjloader with its MTL beside it, as importAsset does;
  // assimp's own OBJ parser crashes on malformed input (tests/fuzz, docs/reliability.md).
  if (extension == "obj")
    throw Error(name + ": OBJ cannot be read from memory (an OBJ and its MTL are read from files)");
  if (!isAssimpExtension(extension))
    throw Error(name + ": unknown mesh format '" + extension + "'");
  if (bytes.empty()) throw Error(name + ": empty file");
  if (extension == "glb") checkGlbLengths(bytes, bytes.size(), name);
  FormatImporter importer(extension);
  const aiScene& scene =
      readGuarded(importer, name, extension, bytes.size(), [&](Assimp::Importer& reader) {
        return reader.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags,
                                         extension.c_str());
      });
  const detail::Source src{name, "", extension == "gltf" || extension == "glb"};
  return convert(scene, src, options);
}

}  // namespace asperity
