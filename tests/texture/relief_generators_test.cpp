// Height map files and the embossed teapot: slopes from central differences, row orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/test_support.hpp"
#include "texture/png_codec.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

using test::generate;
using test::near;

// A grayscale PNG whose value grows by `step` per texel along u (bits 8 or 16).
std::string rampFile(int w, int h, int step, int bits, bool along_rows) {
  const std::string path = test::tempDir("relief") + "/ramp.png";
  std::vector<uint16_t> grey(static_cast<size_t>(w * h));
  for (int r = 0; r < h; ++r) {
    for (int i = 0; i < w; ++i)
      grey[static_cast<size_t>(r * w + i)] = static_cast<uint16_t>(step * (along_rows ? r : i));
  }
  png::write(path, w, h, 1, bits, grey);
  return path;
}

TEST(HeightmapGenerator, RampGivesTheExpectedSlope) {
  // 8 bit: value 10 i, white = 255 -> height 10 i / 255 * height_scale texels.
  const std::string file = rampFile(16, 8, 10, 8, false);
  const NormalMap map = generate("heightmap", {{"file", file}, {"height_scale", "25.5"}});
  EXPECT_EQ(map.width(), 16);
  EXPECT_EQ(map.height(), 8);
  const double slope = 10.0 / 255.0 * 25.5;  // = 1: 45 degrees facing -u
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 16; ++i) {
      EXPECT_TRUE(near(map.at(i, j).x(), -slope / std::sqrt(1 + slope * slope), 0.0, 1e-5));
      EXPECT_TRUE(near(map.at(i, j).y(), 0.0, 0.0, 1e-6));
    }
  }
}

TEST(HeightmapGenerator, SixteenBitAndTopRowOrientation) {
  // Values grow downward in the PNG (row r), so heights fall toward +v: normals tilt toward +v.
  const std::string file = rampFile(4, 10, 1000, 16, true);
  const NormalMap map = generate("heightmap", {{"file", file}, {"height_scale", "65.535"}});
  const double slope = 1.0;  // 1000 / 65535 * 65.535
  for (int j = 0; j < 10; ++j) {
    EXPECT_TRUE(near(map.at(1, j).y(), slope / std::sqrt(2.0), 0.0, 1e-5)) << j;
  }
}

TEST(HeightmapGenerator, ColourFilesAreReadAsGrey) {
  const std::string path = test::tempDir("relief") + "/rgb.png";
  png::write(path, 2, 2, 3, 8, std::vector<uint16_t>(12, 200));
  const NormalMap map = generate("heightmap", {{"file", path}});
  for (const Vec3f& m : map.texels()) EXPECT_EQ(m, Vec3f(0, 0, 1));
}

TEST(EmbossGenerator, PlateauAndBackgroundAreFlatEdgesTiltByHeightOverWidth) {
  const NormalMap map = generate("emboss", {{"height", "6"}, {"edge_width", "12"}}, 512);
  // The body's centre (logo (0, -0.1)) and a corner are flat.
  EXPECT_EQ(map.at(256, 236), Vec3f(0, 0, 1));
  EXPECT_EQ(map.at(2, 2), Vec3f(0, 0, 1));
  // Inside the linear edge, tan = height / edge_width = 0.5: the median sloped texel.
  std::vector<double> tans;
  for (const Vec3f& m : map.texels()) {
    if (m.z() < 1.0f) tans.push_back(test::tanTilt(m));
  }
  std::nth_element(tans.begin(), tans.begin() + tans.size() / 2, tans.end());
  EXPECT_TRUE(near(tans[tans.size() / 2], 0.5, 0.05));
  const auto sloped = static_cast<int>(tans.size());
  EXPECT_GT(sloped, 1000);
  EXPECT_LT(sloped, 512 * 512 / 4);
}

TEST(EmbossGenerator, EdgesFaceOutward) {
  // Along the row through the body's centre: the left edge faces -u, the right edge +u (the
  // spout side is further right, so look near the body).
  const NormalMap map = generate("emboss", {}, 256);
  const int j = 118;
  double left = 0.0, right = 0.0;
  for (int i = 0; i < 128; ++i) left += map.at(i, j).x();
  for (int i = 128; i < 256; ++i) right += map.at(i, j).x();
  EXPECT_LT(left, 0.0);
  EXPECT_GT(right, 0.0);
}

}  // namespace
}  // namespace asperity
