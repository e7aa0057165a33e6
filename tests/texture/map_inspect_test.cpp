// Green-convention verdict (curl of the implied slope field) and mean slope on maps with known
// answers: the normals of a height field, the same with green flipped, a flat map.
#include "asperity/texture/map_inspect.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace asperity {
namespace {

// Normals of h = a sin(2 pi i / W) sin(4 pi j / H) (texel units), green as `green` says.
NormalMap heightFieldNormals(int w, int h, double a, GreenConvention green) {
  NormalMap map(w, h);
  const double ku = 2 * M_PI / w, kv = 4 * M_PI / h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double du = a * ku * std::cos(ku * i) * std::sin(kv * j);
      const double dv = a * kv * std::sin(ku * i) * std::cos(kv * j);
      const double y = green == GreenConvention::DirectX ? dv : -dv;
      map.at(i, j) = Vec3(-du, y, 1.0).normalized().cast<float>();
    }
  return map;
}

TEST(MapInspect, HeightFieldNormalsFitOpenGl) {
  const GreenFit fit =
      judgeGreenConvention(heightFieldNormals(64, 64, 4.0, GreenConvention::OpenGL));
  EXPECT_EQ(fit.verdict, GreenVerdict::OpenGL);
  EXPECT_LT(fit.curl_opengl, 0.1 * fit.curl_directx);
}

TEST(MapInspect, FlippedGreenFitsDirectX) {
  const GreenFit fit =
      judgeGreenConvention(heightFieldNormals(64, 48, 4.0, GreenConvention::DirectX));
  EXPECT_EQ(fit.verdict, GreenVerdict::DirectX);
}

TEST(MapInspect, FlatAndTinyMapsAreUnknown) {
  EXPECT_EQ(judgeGreenConvention(NormalMap(32, 32)).verdict, GreenVerdict::Unknown);
  EXPECT_EQ(judgeGreenConvention(NormalMap(2, 2)).verdict, GreenVerdict::Unknown);
  EXPECT_STREQ(verdictName(GreenVerdict::Unknown), "unknown");
}

TEST(MapInspect, MeanSlopeIsTanOfTheTilt) {
  NormalMap map(4, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) map.at(i, j) = Vec3f(0.6f, 0.0f, 0.8f);
  EXPECT_NEAR(meanSlope(map), 0.75, 1e-6);
  EXPECT_DOUBLE_EQ(meanSlope(NormalMap(4, 4)), 0.0);
  EXPECT_DOUBLE_EQ(meanSlope(NormalMap()), 0.0);
}

}  // namespace
}  // namespace asperity
