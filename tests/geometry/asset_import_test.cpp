// Asset import: glTF (external and data-URI images), OBJ + MTL, 3DS from glmark2-data, the node
// key, and one test per kind of broken asset (the message names the file and the part).
#include "asperity/geometry/asset_import.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "asperity/error.hpp"
#include "asperity/geometry/mesh_io.hpp"
#include "asperity/geometry/shape_mesh.hpp"
#include "collision/signed_distance_field.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"

namespace asperity {
namespace {

std::string fixture(const std::string& name) {
  return test::sourcePath("tests/fixtures/assets/" + name);
}

// The error message of importAsset(path, options), or "" when it succeeds.
std::string importError(const std::string& path, const AssetImportOptions& options = {}) {
  try {
    importAsset(path, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The texel of tilt_normal.png, (200, 128, 220) decoded and normalised (SPEC 6).
Vec3f tiltTexel(float scale) {
  const Vec3f m(2.0f * 200 / 255 - 1, 2.0f * 128 / 255 - 1, 2.0f * 220 / 255 - 1);
  return Vec3f(scale * m.x(), scale * m.y(), m.z()).normalized();
}

TEST(AssetImport, GltfPlateBringsItsNormalMapAndBaseColour) {
  const ImportedAsset a = importAsset(fixture("plate.gltf"));
  ASSERT_EQ(a.mesh->triangles.size(), 2u);
  ASSERT_EQ(a.mesh->uvs.size(), a.mesh->vertices.size());
  ASSERT_TRUE(a.material.normal_map);
  EXPECT_EQ(a.material.normal_map->width(), 8);
  EXPECT_TRUE(a.material.normal_map->at(3, 3).isApprox(tiltTexel(1.0f), 1e-5f));
  EXPECT_EQ(a.material.normal_stats.invalid, 0u);
  EXPECT_TRUE(a.material.has_base_color);
  EXPECT_NEAR(a.material.base_color.x(), 0.8, 1e-6);
  // glTF's v runs down the image; the mesh keeps OpenGL's v up: file (0, 1) at (-0.1, -0.1).
  for (size_t v = 0; v < a.mesh->vertices.size(); ++v) {
    if (a.mesh->vertices[v].isApprox(Vec3(-0.1, -0.1, 0), 1e-6)) {
      EXPECT_TRUE(a.mesh->uvs[v].isApprox(Vec2(0, 0), 1e-6)) << a.mesh->uvs[v].transpose();
    }
  }
}

TEST(AssetImport, GltfTextureTransformIsAppliedToTheUvs) {
  // KHR_texture_transform on normalTexture: offset (0.25, 0.5), rotation 0.3, scale (2, 3).
  // The extension's rule in glTF's own uvs (v down): uv' = T(offset) R(rotation) S(scale) uv.
  const double c = std::cos(0.3), s = std::sin(0.3);
  auto expected = [&](double u, double vg) {
    const double u2 = c * 2 * u + s * 3 * vg + 0.25, vg2 = -s * 2 * u + c * 3 * vg + 0.5;
    return Vec2(u2, 1 - vg2);  // the mesh keeps v up
  };
  const ImportedAsset a = importAsset(fixture("plate_texture_transform.gltf"));
  ASSERT_EQ(a.mesh->uvs.size(), 4u);
  // The plate's corners and their uvs in the file.
  const std::pair<Vec3, Vec2> corners[] = {{Vec3(-0.1, -0.1, 0), Vec2(0, 1)},
                                           {Vec3(0.1, -0.1, 0), Vec2(1, 1)},
                                           {Vec3(0.1, 0.1, 0), Vec2(1, 0)},
                                           {Vec3(-0.1, 0.1, 0), Vec2(0, 0)}};
  int matched = 0;
  for (size_t v = 0; v < a.mesh->vertices.size(); ++v)
    for (const auto& corner : corners)
      if (a.mesh->vertices[v].isApprox(corner.first, 1e-6)) {
        const Vec2 want = expected(corner.second.x(), corner.second.y());
        EXPECT_TRUE(a.mesh->uvs[v].isApprox(want, 1e-5))
            << a.mesh->uvs[v].transpose() << " want " << want.transpose();
        ++matched;
      }
  EXPECT_EQ(matched, 4);
  // Without the extension the uvs are the file's.
  EXPECT_TRUE(importAsset(fixture("plate.gltf")).material.uv_transform.isIdentity());
}

TEST(AssetImport, TheFilesTangentsGiveTheTextureFrame) {
  // plate_tangents.gltf: the plate with NORMAL (+z) and TANGENT (0, 1, 0, w = -1), a frame
  // turned 90 degrees from its UV gradients (t = +x) and mirrored: b = w n x t = +x.
  const ImportedAsset a = importAsset(fixture("plate_tangents.gltf"));
  ASSERT_EQ(a.mesh->tangents.size(), a.mesh->vertices.size());
  for (const Vec4& t : a.mesh->tangents) EXPECT_TRUE(t.isApprox(Vec4(0, 1, 0, -1), 1e-6)) << t;
  ASSERT_EQ(a.mesh->normals.size(), a.mesh->vertices.size());
  for (const Vec3& n : a.mesh->normals) EXPECT_TRUE(n.isApprox(Vec3::UnitZ(), 1e-6)) << n;
  Shape plate;
  plate.type = ShapeType::TriangleMesh;
  plate.mesh = a.mesh;
  // At a contact on the plate and at every vertex of the mesh that the samplers rasterise.
  const SurfaceFrame f = surfaceFrameAt(plate, 0, Vec3(0.02, -0.03, 0));
  EXPECT_TRUE(f.t.isApprox(Vec3::UnitY(), 1e-9)) << f.t.transpose();
  EXPECT_TRUE(f.b.isApprox(Vec3::UnitX(), 1e-9)) << f.b.transpose();
  const ShapeMesh shown = buildShapeMesh(plate);
  for (size_t v = 0; v < shown.positions.size(); ++v) {
    EXPECT_TRUE(shown.tangents[v].isApprox(Vec3f::UnitY(), 1e-6f));
    EXPECT_TRUE(shown.bitangents[v].isApprox(Vec3f::UnitX(), 1e-6f));
  }
  // Without TANGENT the UV gradients decide: t = +x, b = +y.
  const ImportedAsset plain = importAsset(fixture("plate.gltf"));
  EXPECT_TRUE(plain.mesh->tangents.empty());
  EXPECT_TRUE(plain.mesh->normals.empty());
  plate.mesh = plain.mesh;
  EXPECT_TRUE(surfaceFrameAt(plate, 0, Vec3(0.02, -0.03, 0)).t.isApprox(Vec3::UnitX(), 1e-9));
}

TEST(AssetImport, DataUriImageMatchesTheExternalFile) {
  const ImportedAsset file = importAsset(fixture("plate.gltf"));
  const ImportedAsset uri = importAsset(fixture("plate_data_uri.gltf"));
  ASSERT_TRUE(uri.material.normal_map);
  EXPECT_EQ(uri.material.normal_map->texels(), file.material.normal_map->texels());
}

TEST(AssetImport, FromMemoryMatchesFromFile) {
  std::ifstream in(fixture("plate_data_uri.gltf"), std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                   std::istreambuf_iterator<char>()};
  const ImportedAsset mem = importAssetFromMemory(bytes, "plate", "gltf");
  const ImportedAsset file = importAsset(fixture("plate_data_uri.gltf"));
  EXPECT_EQ(mem.mesh->vertices, file.mesh->vertices);
  EXPECT_EQ(mem.material.normal_map->texels(), file.material.normal_map->texels());
}

TEST(AssetImport, ObjMtlBumpMapWithMultiplier) {
  const ImportedAsset a = importAsset(fixture("slab.obj"));
  ASSERT_TRUE(a.material.normal_map);
  EXPECT_DOUBLE_EQ(a.material.normal_scale, 0.5);
  EXPECT_TRUE(a.material.normal_map->at(0, 0).isApprox(tiltTexel(0.5f), 1e-5f));
  EXPECT_NEAR(a.material.base_color.y(), 0.3, 1e-6);
  // Geometry exactly as the plain OBJ reader gives it.
  EXPECT_EQ(a.mesh->vertices, loadObjMesh(fixture("slab.obj"))->vertices);
}

TEST(AssetImport, NodeKeyPicksByNameAndRejectsUnknownNames) {
  AssetImportOptions options;
  options.node = "plate";
  EXPECT_EQ(importAsset(fixture("plate.gltf"), options).mesh->triangles.size(), 2u);
  options.node = "plate_mesh";
  EXPECT_EQ(importAsset(fixture("plate.gltf"), options).mesh->triangles.size(), 2u);
  options.node = "lid";
  EXPECT_NE(importError(fixture("plate.gltf"), options).find("no node or mesh is named 'lid'"),
            std::string::npos);
}

TEST(AssetImport, NodeKeyPicksAnObjObjectWithItsMaterial) {
  AssetImportOptions options;
  options.node = "lid";
  const ImportedAsset lid = importAsset(fixture("two_objects.obj"), options);
  ASSERT_EQ(lid.mesh->triangles.size(), 2u);
  for (const Vec3& v : lid.mesh->vertices) EXPECT_EQ(v.z(), 1.0);
  EXPECT_TRUE(lid.material.normal_map);
  options.node = "base";
  const ImportedAsset base = importAsset(fixture("two_objects.obj"), options);
  for (const Vec3& v : base.mesh->vertices) EXPECT_EQ(v.z(), 0.0);
  EXPECT_FALSE(base.material.has_normal_texture);
  EXPECT_NEAR(base.material.base_color.z(), 0.9, 1e-6);
  // Both by default; an unknown name is an error naming the file.
  EXPECT_EQ(importAsset(fixture("two_objects.obj")).mesh->triangles.size(), 4u);
  options.node = "handle";
  const std::string error = importError(fixture("two_objects.obj"), options);
  EXPECT_NE(error.find("two_objects.obj: no object or group is named 'handle'"), std::string::npos)
      << error;
}

TEST(AssetImport, ScaleMultipliesPositions) {
  AssetImportOptions options;
  options.scale = 10.0;
  const ImportedAsset a = importAsset(fixture("plate.gltf"), options);
  double extent = 0.0;
  for (const Vec3& v : a.mesh->vertices) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  EXPECT_NEAR(extent, 1.0, 1e-6);
}

// Assets no one here wrote: glmark2-data's asteroid (3DS) and bunny (OBJ).
TEST(AssetImport, Glmark2AsteroidThreeDs) {
  const std::string path = "/usr/share/glmark2/models/asteroid-low.3ds";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "glmark2-data is not installed";
  const ImportedAsset a = importAsset(path);
  EXPECT_GT(a.mesh->triangles.size(), 100u);
  EXPECT_EQ(a.mesh->uvs.size(), a.mesh->vertices.size());
  // Split at its UV seams, it is still closed once welded by position.
  EXPECT_TRUE(isClosedMesh(*a.mesh));
}

TEST(AssetImport, Glmark2BunnyObjIsUnchanged) {
  const std::string path = "/usr/share/glmark2/models/bunny.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "glmark2-data is not installed";
  const ImportedAsset a = importAsset(path);
  const auto plain = loadObjMesh(path);
  EXPECT_EQ(a.mesh->vertices, plain->vertices);
  EXPECT_EQ(a.mesh->triangles, plain->triangles);
  EXPECT_FALSE(a.material.normal_map);
}

// Broken assets: one message naming the file and the part at fault.
TEST(AssetImport, BrokenGltfsNameTheFileAndThePart) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"missing_image.gltf", "image 'no_such_image.png' cannot be read"},
      {"broken_buffer.gltf", "no_such_buffer.bin"},
      {"points.gltf", "mesh 'plate_mesh' has non-triangle primitives"},
      {"huge_texture.gltf", "20000 x 20000"},
      {"no_uvs.gltf", "mesh 'plate_mesh' has no texture coordinates"},
  };
  for (const auto& [file, part] : cases) {
    const std::string message = importError(fixture(file));
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(AssetImport, BadPathsAndOptions) {
  EXPECT_NE(importError(fixture("nothing.glb")).find("cannot open"), std::string::npos);
  EXPECT_NE(importError(fixture("tilt_normal.png")).find("unknown mesh format"), std::string::npos);
  AssetImportOptions options;
  options.scale = 0.0;
  EXPECT_NE(importError(fixture("plate.gltf"), options).find("scale"), std::string::npos);
  EXPECT_THROW(importAssetFromMemory({}, "empty", "glb"), Error);
  EXPECT_THROW(importAssetFromMemory({1, 2, 3}, "junk", "glb"), Error);
  // OBJ goes through tinyobjloader from files only; from memory it is refused, not handed to
  // assimp's OBJ parser (which a fuzzed OBJ crashed).
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_EQ(test::errorOf([&] {
              importAssetFromMemory(std::vector<uint8_t>(obj.begin(), obj.end()), "tri.obj", "obj");
            }),
            "tri.obj: OBJ cannot be read from memory (an OBJ and its MTL are read from files)");
}

// A GLB whose header's lengths do not fit the file is refused before assimp allocates them (a
// fuzzed 1 kB file claimed a 4 GB chunk: assimp took 4 GB and half a minute).
TEST(AssetImport, GlbLengthsMustFitTheFile) {
  auto glb = [](uint32_t total, uint32_t chunk) {
    std::vector<uint8_t> bytes(40, ' ');
    const uint32_t words[] = {0x46546C67u, 2, total, chunk, 0x4E4F534Au};  // "glTF", "JSON"
    for (size_t w = 0; w < 5; ++w)
      for (size_t k = 0; k < 4; ++k) bytes[4 * w + k] = static_cast<uint8_t>(words[w] >> (8 * k));
    return bytes;
  };
  EXPECT_EQ(test::errorOf([&] { importAssetFromMemory(glb(1000, 20), "big", "glb"); }),
            "big: the GLB header gives a length of 1000 bytes, but the file has 40");
  EXPECT_EQ(test::errorOf([&] { importAssetFromMemory(glb(40, 0x04040404u), "chunk", "glb"); }),
            "chunk: the GLB's first chunk claims 67372036 bytes, more than the file's 40 hold");
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "huge_chunk.glb";
  const std::vector<uint8_t> bytes = glb(40, 0xFFFFFFF0u);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), 40);
  EXPECT_EQ(importError(path.string()),
            path.string() + ": the GLB's first chunk claims 4294967280 bytes, more than the " +
                "file's 40 hold");
}

// A file is read only as the format its extension names: assimp would otherwise guess another
// format from the content (an STL here; tests/fuzz found a reader that then allocated gigabytes).
TEST(AssetImport, ContentOfAnotherFormatIsNotGuessed) {
  const std::string stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid t\n";
  const std::vector<uint8_t> bytes(stl.begin(), stl.end());
  for (const char* format : {"glb", "gltf", "fbx", "dae", "3ds"}) {
    const std::string message = test::errorOf([&] { importAssetFromMemory(bytes, "tri", format); });
    EXPECT_EQ(message.rfind("tri: cannot import (", 0), 0u) << format << ": " << message;
  }
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "stl_inside.gltf";
  std::ofstream(path) << stl;
  EXPECT_EQ(importError(path.string()).rfind(path.string() + ": cannot import (", 0), 0u);
}

}  // namespace
}  // namespace asperity

namespace asperity {
namespace {

// An OBJ quad with UVs whose MTL names `line` (a grey height PNG, h.png, rising 1 grey level in
// 255 per texel along u), in a fresh folder; returns the OBJ's path.
std::string quadWithMaterial(const std::string& line) {
  const std::string dir = test::tempDir("mtl_heights");
  std::vector<uint16_t> grey(16 * 16);
  for (size_t k = 0; k < grey.size(); ++k) grey[k] = static_cast<uint16_t>(10 * (k % 16));
  png::write(dir + "/h.png", 16, 16, 1, 8, grey);
  std::ofstream(dir + "/quad.mtl") << "newmtl m\nKd 0.5 0.5 0.5\n" << line << "\n";
  std::ofstream(dir + "/quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nusemtl m\n"
                                      "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
  return dir + "/quad.obj";
}

TEST(AssetImport, GreyObjBumpAndDispMapsAreHeightMaps) {
  // Heights grey * bm texels: 10 levels of 255 per texel times bm 51 is a slope of 2 along u
  // (the normals tilt toward -u, SPEC 6), for `bump` and for `disp` alike.
  for (const std::string key : {"bump -bm 51 h.png", "disp -bm 51 h.png"}) {
    const ImportedAsset a = importAsset(quadWithMaterial(key));
    ASSERT_TRUE(a.material.normal_map) << key;
    const Vec3f m = a.material.normal_map->at(7, 5);
    EXPECT_NEAR(m.x() / m.z(), -2.0, 1e-4) << key;
    EXPECT_NEAR(m.y() / m.z(), 0.0, 1e-6) << key;
    EXPECT_DOUBLE_EQ(a.material.normal_scale, 51.0) << key;
  }
  // A colour bump image is still a normal map (obj2gltf and most exporters write those).
  EXPECT_TRUE(importAsset(fixture("slab.obj")).material.normal_map);
}

}  // namespace
}  // namespace asperity
