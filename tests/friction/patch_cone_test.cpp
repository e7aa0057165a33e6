// The flat-patch cone (Fig. 8) against the Gaussian-slope closed form (SPEC 2) and the frame
// conventions of both surfaces.
#include "asperity/friction/patch_cone.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// Normals normalize(-s_x, -s_y, 1) with slopes s ~ N(0, diag(sx^2, sy^2)), fixed seed.
NormalMap gaussianSlopes(int size, double sx, double sy, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> nx(0.0, sx), ny(0.0, sy);
  NormalMap map(size, size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double s_x = nx(rng), s_y = ny(rng);
      map.at(i, j) = Vec3(-s_x, -s_y, 1.0).normalized().cast<float>();
    }
  }
  return map;
}

// Every texel tilted by theta toward texture azimuth phi (x along u, y along v).
NormalMap uniformFacet(int size, double theta, double phi) {
  NormalMap map(size, size);
  const Vec3f m(static_cast<float>(std::sin(theta) * std::cos(phi)),
                static_cast<float>(std::sin(theta) * std::sin(phi)),
                static_cast<float>(std::cos(theta)));
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) map.at(i, j) = m;
  }
  return map;
}

// The same map mirrored in u (x -> -x).
NormalMap mirrorU(const NormalMap& in) {
  NormalMap out(in.width(), in.height());
  for (int j = 0; j < in.height(); ++j) {
    for (int i = 0; i < in.width(); ++i) {
      const Vec3f m = in.at(i, j);
      out.at(in.width() - 1 - i, j) = Vec3f(-m.x(), m.y(), m.z());
    }
  }
  return out;
}

// SPEC 2: mu_d = (2/pi) sigma_d / sqrt(2 pi), sigma_d = sqrt(sx^2 dx^2 + sy^2 dy^2).
// The clamp at mu_max = 4 only touches |s| > 2 pi, a 1e-8 event at sigma = 1: ignored.
// 65536 texels give a relative sampling error of about 0.6%; the tolerance is 3%.
double gaussianMu(double sx, double sy, const Vec2& d) {
  const double sigma = std::sqrt(sx * sx * d.x() * d.x() + sy * sy * d.y() * d.y());
  return (2.0 / kPi) * sigma / std::sqrt(2.0 * kPi);
}

TEST(FlatPatchCone, IsotropicGaussianOnB) {
  const NormalMap b = gaussianSlopes(256, 1.0, 1.0, 42);
  const DirectionalMu mu = flatPatchCone(nullptr, b, PatchConeOptions{});
  ASSERT_EQ(mu.count, 16);
  const auto dirs = sampleDirections(16);
  for (int k = 0; k < 16; ++k) {
    EXPECT_TRUE(near(mu.mu[k], gaussianMu(1.0, 1.0, dirs[k]), 0.03)) << k;
    EXPECT_TRUE(near(mu.mu[k], 0.254, 0.03)) << k;
  }
}

TEST(FlatPatchCone, AnisotropicGaussianOnBothSides) {
  const NormalMap map = gaussianSlopes(256, 0.1, 1.0, 7);
  const auto dirs = sampleDirections(16);
  // On B alone, then on A alone (the distribution is symmetric, so the same cone).
  for (bool on_a : {false, true}) {
    const NormalMap flat(8, 8);
    const DirectionalMu mu = on_a ? flatPatchCone(&map, flat, PatchConeOptions{})
                                  : flatPatchCone(nullptr, map, PatchConeOptions{});
    for (int k = 0; k < 16; ++k) {
      EXPECT_TRUE(near(mu.mu[k], gaussianMu(0.1, 1.0, dirs[k]), 0.03)) << on_a << " " << k;
    }
    EXPECT_TRUE(near(mu.mu[0], 0.0254, 0.03));
    EXPECT_TRUE(near(mu.mu[4], 0.254, 0.03));
  }
}

// Eq. 7 with gains: both surfaces add, scaled by k_A and k_B, on top of mu0.
TEST(FlatPatchCone, GainsAndBothSurfaces) {
  const NormalMap a = gaussianSlopes(128, 1.0, 1.0, 1);
  const NormalMap b = gaussianSlopes(64, 0.5, 0.5, 2);
  PatchConeOptions opt;
  const DirectionalMu mu_a = flatPatchCone(&a, NormalMap(4, 4), opt);
  const DirectionalMu mu_b = flatPatchCone(nullptr, b, opt);
  opt.gains = PatchGains{0.2, 2.0, 3.0};
  const DirectionalMu both = flatPatchCone(&a, b, opt);
  for (int k = 0; k < 16; ++k) {
    EXPECT_TRUE(near(both.mu[k], 0.2 + 2.0 * mu_a.mu[k] + 3.0 * mu_b.mu[k], 1e-5)) << k;
  }
}

// A facet on B facing +u raises only mu_{+t}-side directions; on A it raises the -t side.
TEST(FlatPatchCone, DirectionConventions) {
  const NormalMap facet = uniformFacet(4, 0.5, 0.0);
  const double p = (2.0 / kPi) * std::tan(0.5);
  const NormalMap flat(4, 4);
  const DirectionalMu on_b = flatPatchCone(nullptr, facet, PatchConeOptions{4});
  EXPECT_TRUE(near(on_b.mu[0], p, 1e-5));
  EXPECT_NEAR(on_b.mu[1], 0.0, 1e-7);
  EXPECT_EQ(on_b.mu[2], 0.0f);
  EXPECT_NEAR(on_b.mu[3], 0.0, 1e-7);
  const DirectionalMu on_a = flatPatchCone(&facet, flat, PatchConeOptions{4});
  EXPECT_EQ(on_a.mu[0], 0.0f);
  EXPECT_TRUE(near(on_a.mu[2], p, 1e-5));
  // v maps to +b on B and to -b on A; A's facet facing -b in the world raises mu_{+b}.
  const NormalMap facet_v = uniformFacet(4, 0.5, 0.5 * kPi);
  EXPECT_TRUE(near(flatPatchCone(nullptr, facet_v, PatchConeOptions{4}).mu[1], p, 1e-5));
  EXPECT_TRUE(near(flatPatchCone(&facet_v, flat, PatchConeOptions{4}).mu[1], p, 1e-5));
}

// Relabelling the bodies (the textured one as A, with n, b flipped) maps mu_k to mu_{N/2-k}:
// both labellings describe the same physical contact.
TEST(FlatPatchCone, RelabellingTheBodies) {
  const NormalMap tex = gaussianSlopes(64, 0.3, 1.0, 3);
  const NormalMap skew = uniformFacet(8, 0.6, 0.4);
  const NormalMap flat(4, 4);
  for (const NormalMap* t : {&tex, &skew}) {
    const DirectionalMu as_b = flatPatchCone(nullptr, *t, PatchConeOptions{16});
    const DirectionalMu as_a = flatPatchCone(t, flat, PatchConeOptions{16});
    for (int k = 0; k < 16; ++k) {
      EXPECT_TRUE(near(as_a.mu[k], as_b.mu[(16 + 8 - k) % 16], 1e-6, 1e-7)) << k;
    }
  }
}

// Swapping A and B with a mirror in u gives the same cone (g_A(x, y, z) = g_B(-x, y, z)).
TEST(FlatPatchCone, SwapWithMirror) {
  const NormalMap t1 = gaussianSlopes(32, 0.3, 1.0, 4);
  const NormalMap t2 = uniformFacet(16, 0.3, 1.0);
  const DirectionalMu direct = flatPatchCone(&t1, t2, PatchConeOptions{16});
  const NormalMap m2 = mirrorU(t2);
  const DirectionalMu swapped = flatPatchCone(&m2, mirrorU(t1), PatchConeOptions{16});
  for (int k = 0; k < 16; ++k) EXPECT_TRUE(near(direct.mu[k], swapped.mu[k], 1e-6)) << k;
}

// Facing away and steeper than the clamp count as mu_max; facets parallel to n give 0.
TEST(FlatPatchCone, ClampAndFlat) {
  const NormalMap flat(8, 8);
  const DirectionalMu zero = flatPatchCone(&flat, flat, PatchConeOptions{8});
  for (int k = 0; k < 8; ++k) EXPECT_EQ(zero.mu[k], 0.0f);
  const NormalMap steep = uniformFacet(4, 1.5, 0.0);
  EXPECT_TRUE(near(flatPatchCone(nullptr, steep, PatchConeOptions{4}).mu[0], 4.0, 1e-6));
  const NormalMap away = uniformFacet(4, 2.0, 0.0);
  PatchConeOptions opt{4};
  opt.mu_max = 2.5f;
  EXPECT_TRUE(near(flatPatchCone(nullptr, away, opt).mu[0], 2.5, 1e-6));
}

// Bad options and inputs throw asperity::Error.
TEST(FlatPatchCone, RejectsBadValues) {
  const NormalMap b(4, 4);
  EXPECT_THROW(flatPatchCone(nullptr, b, PatchConeOptions{3}), Error);
  EXPECT_THROW(flatPatchCone(nullptr, b, PatchConeOptions{65}), Error);
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), -1.0f, 0.0f,
                    std::numeric_limits<float>::infinity()}) {
    PatchConeOptions opt;
    opt.mu_max = bad;
    EXPECT_THROW(flatPatchCone(nullptr, b, opt), Error) << bad;
  }
  const NormalMap empty;
  EXPECT_THROW(flatPatchCone(nullptr, empty, PatchConeOptions{}), Error);
  EXPECT_THROW(flatPatchCone(&empty, b, PatchConeOptions{}), Error);
}

}  // namespace
}  // namespace asperity
