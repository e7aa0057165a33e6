// The CPU reference sampler: the shared sampler suite, plus its own images and timings.
#include "asperity/sampler/cpu_patch_sampler.hpp"

#include "sampler/patch_texture.hpp"
#include "sampler/sampler_suite.hpp"

namespace asperity::sampler_test {
namespace {

struct CpuTraits {
  static std::unique_ptr<FrictionProvider> make() { return std::make_unique<CpuPatchSampler>(); }
  static double tolerance() { return 1e-5; }
  static double tessellationTolerance() { return 1e-5; }
  static bool multipleOf4Only() { return false; }
  static double curvedCoverageTolerance() { return 0.1; }
};

INSTANTIATE_TYPED_TEST_SUITE_P(Cpu, SamplerSuite, CpuTraits);

// The images of a box corner on a plane: each surface's coverage, P = their overlap, and the
// mean of the images' coefficients over P reproduces the contact's mu (Eq. 8). The images
// shade pixel by pixel, the coefficients in batches (texel offsets by masks for power-of-two
// maps, by wrapping for the others): both give the same numbers within rounding.
TEST(CpuPatchSampler, ImagesAgreeWithCoefficients) {
  // Turned half a turn, the box's texture runs the other way: u and v below the face's corner.
  for (const auto& [size, turn] : {std::pair{8, 0.0}, {10, 0.0}, {160, 0.0}, {160, kPi}}) {
    const Transform pose{Vec3(0, 0, 0.1), Quat(Eigen::AngleAxisd(turn, Vec3::UnitZ()))};
    Scene scene{{planeBody(roughMap(size, 1), 0.1, 1.5),
                 boxBody(Vec3(0.1, 0.1, 0.1), pose, roughMap(size, 2), 0.1, 0.5)},
                contactAt(Vec3(0.1, 0.1, 0.0), 1e-4)};
    CpuPatchSampler sampler;
    PatchImages images;
    sampler.sampleContact(scene.bodies, scene.contact, settings(8), &images);
    ASSERT_EQ(images.resolution, 16);
    int both = 0, plane = 0;
    std::vector<double> mean(8, 0.0);
    for (int p = 0; p < 256; ++p) {
      plane += images.covered[1][static_cast<size_t>(p)];
      if (!images.in_patch[static_cast<size_t>(p)]) continue;
      ++both;
      for (size_t k = 0; k < 8; ++k) {
        mean[k] += 0.5 * images.mu[0][static_cast<size_t>(p) * 8 + k] +
                   1.5 * images.mu[1][static_cast<size_t>(p) * 8 + k];
      }
      EXPECT_NEAR(images.normals[1][static_cast<size_t>(p)].norm(), 1.0f, 1e-5f);
    }
    EXPECT_EQ(plane, 256);
    EXPECT_EQ(both, 64);
    EXPECT_EQ(scene.contact.covered_pixels, 64);
    for (size_t k = 0; k < 8; ++k) {
      EXPECT_NEAR(scene.contact.mu.mu[k], 0.2 + mean[k] / both, 1e-5) << size << " texels, " << k;
    }
  }
}

// Texel wrapping without a division agrees with the modulo, for any size and both signs.
TEST(CpuPatchSampler, TexelWrapWithoutDivisionIsTheModulo) {
  for (const int size : {1, 2, 3, 8, 10, 160, 288, 1000, 4096}) {
    const float inv = 1.0f / static_cast<float>(size);
    for (int t = -20 * size - 3; t <= 20 * size + 3; ++t) {
      ASSERT_EQ(patch::wrapTexelBy(t, size, inv), wrapTexel(t, size)) << t << " " << size;
    }
  }
}

// The provider reports its time split and keeps mesh BVHs between calls.
TEST(CpuPatchSampler, ReportsTimes) {
  Scene scene{{planeBody(roughMap(8, 1), 0.1, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(8, 2), 0.1, 1.0)},
              contactAt(Vec3(0.1, 0.1, 0.0), 1e-4)};
  CpuPatchSampler sampler;
  std::vector<Contact> contacts(50, scene.contact);
  sampler.computeCoefficients(scene.bodies, contacts, settings());
  EXPECT_GT(sampler.lastStats().patch_ms, 0.0);
  EXPECT_GE(sampler.lastStats().averaging_ms, 0.0);
  EXPECT_EQ(sampler.name(), "cpu");
}

}  // namespace
}  // namespace asperity::sampler_test
