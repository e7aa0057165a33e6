// The cone provider: whole-texture cones turned into the contact frame (Eq. 7 with the
// texture means), checked against the Gaussian-slope oracle of SPEC 2.
#include "asperity/sampler/cone_provider.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// Gaussian slopes (sx, sy): normals normalize(-s_x, -s_y, 1), fixed seed.
std::shared_ptr<const NormalMap> gaussian(double sx, double sy) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto map = std::make_shared<NormalMap>(256, 256);
  for (int j = 0; j < 256; ++j) {
    for (int i = 0; i < 256; ++i) {
      const Vec3 m(-sx * normal(rng), -sy * normal(rng), 1.0);
      map->at(i, j) = m.normalized().cast<float>();
    }
  }
  return map;
}

// Body 0: a textured static plane (B); body 1: a flat cube (A) resting on it.
std::vector<Body> scene(std::shared_ptr<const NormalMap> map, double rotation, double gain) {
  Body plane;
  plane.type = BodyType::Static;
  Shape p;
  p.type = ShapeType::Plane;
  p.surface.normal_map = std::move(map);
  p.surface.texture_rotation = rotation;
  p.surface.gain = gain;
  plane.shapes = {p};
  Body cube;
  Shape c;
  c.type = ShapeType::Box;
  cube.shapes = {c};
  cube.pose.position = Vec3(0, 0, 0.1);
  return {plane, cube};
}

Contact contactOnPlane() {
  Contact c;
  c.body_a = 1;
  c.body_b = 0;
  c.shape_a = c.shape_b = 0;
  c.point = c.witness_a = c.witness_b = Vec3(0.02, 0.03, 0.0);
  c.normal = Vec3::UnitZ();
  return c;
}

// SPEC 2: mu_d = (2/pi) sigma_d / sqrt(2 pi), sigma_d = sqrt(sx^2 dx^2 + sy^2 dy^2).
double oracle(double sx, double sy, double angle) {
  const double sigma = std::hypot(sx * std::cos(angle), sy * std::sin(angle));
  return 2.0 / kPi * sigma / std::sqrt(2.0 * kPi);
}

TEST(ConeProvider, AnisotropicTextureGivesTheGaussianOracleInTheContactFrame) {
  // sx = 0.1, sy = 1: about 0.0254 along u and 0.254 along v; mu0 = 0.2, gain 2.
  const auto map = gaussian(0.1, 1.0);
  ConeProvider provider;
  FrictionSettings s;
  s.directions = 8;
  s.mu0 = 0.2;
  const auto bodies = scene(map, 0.0, 2.0);
  std::vector<Contact> contacts{contactOnPlane()};
  provider.computeCoefficients(bodies, contacts, s);
  for (int k = 0; k < 8; ++k) {
    const double angle = 2 * kPi * k / 8;
    EXPECT_TRUE(
        near(contacts[0].mu.mu[static_cast<size_t>(k)], 0.2 + 2.0 * oracle(0.1, 1.0, angle), 0.05))
        << k;
  }
  EXPECT_FALSE(contacts[0].fallback);
}

TEST(ConeProvider, TurningTheTextureTurnsTheCone) {
  // Texture turned 90 degrees: u along world y, so t (= x) now sees the v roughness.
  const auto map = gaussian(0.1, 1.0);
  ConeProvider provider;
  FrictionSettings s;
  s.mu0 = 0.0;
  const auto bodies = scene(map, 0.5 * kPi, 1.0);
  std::vector<Contact> contacts{contactOnPlane()};
  provider.computeCoefficients(bodies, contacts, s);
  EXPECT_TRUE(near(contacts[0].mu.mu[0], oracle(0.1, 1.0, 0.5 * kPi), 0.05));
  EXPECT_TRUE(near(contacts[0].mu.mu[1], oracle(0.1, 1.0, 0.0), 0.1));
}

TEST(ConeProvider, FlatSurfacesGiveMu0AndConesAreCached) {
  ConeProvider provider;
  FrictionSettings s;
  s.mu0 = 0.3;
  auto bodies = scene(nullptr, 0.0, 1.0);
  std::vector<Contact> contacts{contactOnPlane()};
  provider.computeCoefficients(bodies, contacts, s);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(contacts[0].mu.mu[static_cast<size_t>(k)], 0.3f);
  const auto map = gaussian(1.0, 1.0);
  const DirectionalMu& first = provider.coneOf(map, Side::B, 4.0f);
  EXPECT_EQ(&first, &provider.coneOf(map, Side::B, 4.0f));
  EXPECT_EQ(first.count, ConeProvider::kConeDirections);
  // Isotropic sigma = 1: about 0.254 in every direction (SPEC 2).
  EXPECT_TRUE(near(first.along(1.0), 0.254, 0.05));
}

}  // namespace
}  // namespace asperity
