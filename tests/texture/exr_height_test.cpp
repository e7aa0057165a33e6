// Float OpenEXR height maps: read back exactly, scaled, found by extension, and refused by name
// when broken. Skipped in builds without libopenexr-dev, except where ASPERITY_REQUIRE_OPENEXR is
// set (`make test`), which then fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "asperity/texture/height_map.hpp"
#include "support/test_support.hpp"
#include "texture/exr_height.hpp"
#include "texture_test_util.hpp"

namespace asperity {
namespace {

bool haveOpenExr() {
  if (exr::available()) return true;
  if (std::getenv("ASPERITY_REQUIRE_OPENEXR") != nullptr)
    ADD_FAILURE() << "ASPERITY_REQUIRE_OPENEXR is set but this build has no OpenEXR";
  return false;
}

HeightMap ramp(int w, int h) {
  HeightMap map(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) map.at(i, j) = 1e-6f * static_cast<float>(3 * i - 7 * j) + 1e-9f;
  return map;
}

TEST(ExrHeight, FloatsReadBackExactlyWithRowsBottomUp) {
  if (!haveOpenExr()) GTEST_SKIP() << "built without OpenEXR";
  const std::string path = test::tempDir("exr") + "/ramp.exr";
  const HeightMap written = ramp(37, 21);
  exr::save(written, path);
  HeightMapInfo info;
  const HeightMap read = loadHeightMap(path, 0.0, &info);
  ASSERT_EQ(read.width, 37);
  ASSERT_EQ(read.height, 21);
  EXPECT_EQ(read.values, written.values);  // 32-bit floats, no quantisation
  EXPECT_EQ(info.bits, 32);
  // A scale multiplies; the extension is found in any case.
  const std::string upper = test::tempDir("exr") + "/RAMP.EXR";
  exr::save(written, upper);
  EXPECT_FLOAT_EQ(loadHeightMap(upper, 1e3).at(5, 3), 1e3f * written.at(5, 3));
  // Normals by the same rule as PNG heights: slope 3e-6 m per 1e-6 m texel along u.
  const NormalMap n = normalsFromHeightMap(read, 37e-6);
  EXPECT_NEAR(n.at(10, 10).x() / n.at(10, 10).z(), -3.0, 1e-3);
  // Along v the 21 rows span the same 37 um: texels 37 / 21 um tall.
  EXPECT_NEAR(n.at(10, 10).y() / n.at(10, 10).z(), 7.0 * 21.0 / 37.0, 1e-3);
}

TEST(ExrHeight, BrokenFilesAreRefusedByName) {
  const std::string dir = test::tempDir("exr");
  std::ofstream(dir + "/junk.exr") << "not an exr file";
  test::expectErrorContaining([&] { loadHeightMap(dir + "/junk.exr"); }, {"junk.exr"});
  test::expectErrorContaining([&] { loadHeightMap(dir + "/none.exr"); }, {"none.exr"});
}

// The cap of PNG maps, checked from the header before the pixels are allocated.
TEST(ExrHeight, AMapWiderThan8192TexelsIsRefusedFromItsHeader) {
  if (!haveOpenExr()) GTEST_SKIP() << "built without OpenEXR";
  const std::string path = test::tempDir("exr") + "/wide.exr";
  exr::save(HeightMap(8193, 1), path);
  test::expectErrorContaining([&] { loadHeightMap(path); },
                              {"wide.exr", "data window 8193 x 1", "1 to 8192 texels a side"});
}

TEST(ExrHeight, ANonFiniteTexelIsRefusedNamingIt) {
  if (!haveOpenExr()) GTEST_SKIP() << "built without OpenEXR";
  const std::string dir = test::tempDir("exr");
  for (const float bad : {std::nanf(""), std::numeric_limits<float>::infinity()}) {
    HeightMap map = ramp(4, 5);
    map.at(1, 4 - 2) = bad;  // row 2 from the top
    exr::save(map, dir + "/bad.exr");
    test::expectErrorContaining([&] { loadHeightMap(dir + "/bad.exr"); },
                                {"bad.exr", "column 1, row 2", "heights must be finite"});
  }
  // Finite heights that a scale takes past a float are refused too.
  HeightMap big = ramp(4, 4);
  big.at(0, 0) = 1e30f;
  exr::save(big, dir + "/big.exr");
  test::expectErrorContaining([&] { loadHeightMap(dir + "/big.exr", 1e20); }, {"must be finite"});
}

}  // namespace
}  // namespace asperity
