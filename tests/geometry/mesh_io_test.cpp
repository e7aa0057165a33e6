// OBJ loading (counts, UV splitting, scale, errors per kind of bad file) and simplification.
#include "asperity/geometry/mesh_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "asperity/error.hpp"
#include "collision/signed_distance_field.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

const char* kBunny = "/usr/share/glmark2/models/bunny.obj";

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = test::tempDir("mesh_io") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

using test::errorOf;

// A unit square in two triangles whose second triangle uses other UVs on the shared edge.
const char* kSeamSquare =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
    "f 1/1 2/2 3/3\nf 1/5 3/5 4/4\n";

TEST(MeshIo, SplitsVerticesWhereUvsDiffer) {
  const auto mesh = loadObjMesh(writeFile("seam.obj", kSeamSquare), 2.0);
  // Corners 1 and 3 carry two UVs each: 4 positions become 6 vertices.
  ASSERT_EQ(mesh->triangles.size(), 2u);
  ASSERT_EQ(mesh->vertices.size(), 6u);
  ASSERT_EQ(mesh->uvs.size(), 6u);
  for (size_t t = 0; t < 2; ++t) {
    for (int i : mesh->triangles[t]) {
      const Vec3& v = mesh->vertices[static_cast<size_t>(i)];
      EXPECT_TRUE(v.z() == 0 && (v.x() == 0 || v.x() == 2) && (v.y() == 0 || v.y() == 2));
    }
  }
  // The second triangle's first corner is position 1 with uv (0.5, 0.5).
  const int corner = mesh->triangles[1][0];
  EXPECT_EQ(mesh->vertices[static_cast<size_t>(corner)], Vec3::Zero());
  EXPECT_EQ(mesh->uvs[static_cast<size_t>(corner)], Vec2(0.5, 0.5));
  EXPECT_NE(mesh->source_file.find("seam.obj"), std::string::npos);
}

TEST(MeshIo, QuadsAreTriangulatedAndSharedWithoutUvs) {
  const auto mesh =
      loadObjMesh(writeFile("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  EXPECT_EQ(mesh->triangles.size(), 2u);
  EXPECT_EQ(mesh->vertices.size(), 4u);
  EXPECT_TRUE(mesh->uvs.empty());
}

TEST(MeshIo, BadFilesNameTheFile) {
  const std::string missing = test::tempDir("mesh_io") + "/missing.obj";
  EXPECT_NE(errorOf([&] { loadObjMesh(missing); }).find("missing.obj"), std::string::npos);
  const std::string out_of_range = writeFile("range.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n");
  EXPECT_NE(errorOf([&] { loadObjMesh(out_of_range); }).find("range.obj"), std::string::npos);
  const std::string no_faces = writeFile("points.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_NE(errorOf([&] { loadObjMesh(no_faces); }).find("no faces"), std::string::npos);
  const std::string empty = writeFile("empty.obj", "");
  EXPECT_NE(errorOf([&] { loadObjMesh(empty); }).find("empty.obj"), std::string::npos);
  EXPECT_NE(errorOf([&] { loadObjMesh(writeFile("scale.obj", kSeamSquare), 0.0); }).find("scale"),
            std::string::npos);
}

TEST(MeshIo, BunnyLoadsAndSimplifiesForCollision) {
  if (!std::filesystem::exists(kBunny)) GTEST_SKIP() << "glmark2-data is not installed";
  const auto bunny = loadObjMesh(kBunny);
  EXPECT_EQ(bunny->triangles.size(), 69666u);
  EXPECT_EQ(bunny->vertices.size(), 34835u);
  EXPECT_TRUE(bunny->uvs.empty());
  const auto simple = simplifyMesh(*bunny, 2000);
  EXPECT_LE(simple->triangles.size(), 2000u);
  EXPECT_GE(simple->triangles.size(), 1900u);
  EXPECT_LT(simple->vertices.size(), 1500u);
  // The bunny is closed, and stays closed for the signed-distance collision path.
  EXPECT_TRUE(isClosedMesh(*bunny));
  EXPECT_TRUE(isClosedMesh(*simple));
  // The simplified bunny keeps its extent (within a few per cent of its size).
  auto box = [](const TriangleMeshData& m) {
    Eigen::AlignedBox3d b;
    for (const Vec3& v : m.vertices) b.extend(v);
    return b;
  };
  const Eigen::AlignedBox3d full = box(*bunny), reduced = box(*simple);
  EXPECT_LT((full.min() - reduced.min()).norm(), 0.05 * full.diagonal().norm());
  EXPECT_LT((full.max() - reduced.max()).norm(), 0.05 * full.diagonal().norm());
  for (const auto& tri : simple->triangles) {
    for (int i : tri) EXPECT_LT(static_cast<size_t>(i), simple->vertices.size());
  }
}

TEST(MeshIo, SimplifyKeepsUvsAndSmallMeshes) {
  const auto square = loadObjMesh(writeFile("seam2.obj", kSeamSquare));
  const auto same = simplifyMesh(*square, 10);
  EXPECT_EQ(same->triangles.size(), 2u);
  EXPECT_EQ(same->uvs.size(), same->vertices.size());
  EXPECT_THROW(simplifyMesh(*square, 0), Error);
}

}  // namespace
}  // namespace asperity
