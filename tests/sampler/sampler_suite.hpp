// The one test suite that every patch sampler passes (CPU here, OpenGL in tests/sampler/gl/):
// a typed GoogleTest suite over a traits class with
//   static std::unique_ptr<FrictionProvider> make();
//   static double tolerance();      // per-coefficient agreement with the analytic oracles
//   static double tessellationTolerance();  // one surface as two meshes (interpolated uvs)
//   static bool multipleOf4Only();  // the sampler needs N % 4 == 0
//   static double curvedCoverageTolerance();  // relative; tessellated spheres see a bit less
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/friction/patch_cone.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/texture/generators.hpp"

namespace asperity::sampler_test {

// A static textured plane z = 0 (body 0, surface B) and a body A above it.
struct Scene {
  std::vector<Body> bodies;
  Contact contact;
};

inline std::shared_ptr<NormalMap> uniformMap(const Vec3f& m, int size = 4) {
  auto map = std::make_shared<NormalMap>(size, size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) map->at(i, j) = m.normalized();
  }
  return map;
}

// Deterministic rough map: each texel tilted by a pseudo-random slope.
inline std::shared_ptr<NormalMap> roughMap(int size, uint32_t seed) {
  auto map = std::make_shared<NormalMap>(size, size);
  uint32_t state = seed;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24) * 2.0f - 1.0f;
  };
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) map->at(i, j) = Vec3f(next(), next(), 1.0f).normalized();
  }
  return map;
}

inline Body planeBody(std::shared_ptr<const NormalMap> map, double texture_size, double gain) {
  Body b;
  b.name = "ground";
  b.type = BodyType::Static;
  Shape s;
  s.type = ShapeType::Plane;
  s.surface.normal_map = std::move(map);
  s.surface.texture_size = texture_size;
  s.surface.gain = gain;
  b.shapes.push_back(s);
  return b;
}

// A box of half extents h whose bottom face (z = 0 at rest) has this map.
inline Body boxBody(const Vec3& h, const Transform& pose, std::shared_ptr<const NormalMap> map,
                    double texture_size, double gain) {
  Body b;
  b.name = "box";
  b.pose = pose;
  Shape s;
  s.type = ShapeType::Box;
  s.half_extents = h;
  s.surface.normal_map = std::move(map);
  s.surface.texture_size = texture_size;
  s.surface.gain = gain;
  b.shapes.push_back(s);
  return b;
}

inline Contact contactAt(const Vec3& point, double phi, double angle = 0.0) {
  Contact c;
  c.body_a = 1;
  c.body_b = 0;
  c.shape_a = 0;
  c.shape_b = 0;
  c.point = point;
  c.witness_a = point - Vec3(0, 0, 0.5 * phi);
  c.witness_b = point + Vec3(0, 0, 0.5 * phi);
  c.normal = Vec3::UnitZ();
  c.phi = phi;
  c.t = Vec3(std::cos(angle), std::sin(angle), 0.0);
  c.b = c.normal.cross(c.t);
  return c;
}

inline FrictionSettings settings(int n = 4, int r = 16, double w = 0.02, double mu0 = 0.2) {
  FrictionSettings s;
  s.directions = n;
  s.patch_resolution = r;
  s.patch_width = w;
  s.mu0 = mu0;
  // One provider samples unrelated scenes whose contacts share an identity: every call
  // samples anew instead of keeping the last scene's sample.
  s.reuse_pixels = 0.0;
  return s;
}

template <class Traits>
class SamplerSuite : public ::testing::Test {
 protected:
  // Runs the sampler on one contact and returns it.
  Contact run(Scene& scene, const FrictionSettings& s) {
    if (!provider_) provider_ = Traits::make();
    std::vector<Contact> contacts{scene.contact};
    provider_->computeCoefficients(scene.bodies, contacts, s);
    return contacts.front();
  }
  std::unique_ptr<FrictionProvider> provider_;
};

TYPED_TEST_SUITE_P(SamplerSuite);

// A uniform facet tilted by theta toward +t on B: mu_{+t} = (2/pi) tan(theta) (Eq. 5), 0 in the
// other directions; on A (the box's bottom face, T = t) the same facet resists -t instead.
TYPED_TEST_P(SamplerSuite, UniformFacetMatchesEquationFive) {
  const double theta = 0.3;
  const auto facet = uniformMap(
      Vec3f(static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta))));
  const double expected = 2.0 / kPi * std::tan(theta);
  const double tol = TypeParam::tolerance();
  Scene scene{{planeBody(facet, 0.1, 2.0),
               boxBody(Vec3(0.2, 0.2, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0)},
              contactAt(Vec3(0.01, 0.02, 0), 1e-4)};
  Contact c = this->run(scene, settings());
  EXPECT_FALSE(c.fallback);
  EXPECT_EQ(c.covered_pixels, 256);
  EXPECT_NEAR(c.mu.mu[0], 0.2 + 2.0 * expected, 2.0 * tol);
  EXPECT_NEAR(c.mu.mu[1], 0.2, 2.0 * tol);
  EXPECT_NEAR(c.mu.mu[2], 0.2, 2.0 * tol);
  EXPECT_NEAR(c.mu.mu[3], 0.2, 2.0 * tol);
  // The facet on A's bottom face (T = +x = t) resists the opposite direction.
  Scene flipped{{planeBody(nullptr, 0.1, 2.0),
                 boxBody(Vec3(0.2, 0.2, 0.1), {Vec3(0, 0, 0.1)}, facet, 0.1, 3.0)},
                contactAt(Vec3(0.01, 0.02, 0), 1e-4)};
  c = this->run(flipped, settings());
  EXPECT_NEAR(c.mu.mu[0], 0.2, 3.0 * tol);
  EXPECT_NEAR(c.mu.mu[2], 0.2 + 3.0 * expected, 3.0 * tol);
}

// The fragment model's fixtures (gentle, steep beyond mu_max, facing away, flat, off-axis): a
// uniform map on B gives exactly fragmentMu of the friction module in every direction, so the
// samplers' shading (and the GLSL copy of the formula) is pinned to the C++ one.
TYPED_TEST_P(SamplerSuite, FragmentFixturesMatchFragmentMu) {
  const std::vector<Vec3f> fixtures = {Vec3f(0.1f, 0.05f, 1.0f), Vec3f(0.9f, -0.2f, 0.1f),
                                       Vec3f(0.3f, 0.4f, -0.5f), Vec3f(0.0f, 0.0f, 1.0f),
                                       Vec3f(-0.5f, 0.7f, 0.6f)};
  const std::vector<Vec2> dirs = sampleDirections(8);
  for (const Vec3f& m : fixtures) {
    Scene scene{{planeBody(uniformMap(m), 0.1, 1.0),
                 boxBody(Vec3(0.2, 0.2, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0)},
                contactAt(Vec3(0.004, -0.003, 0), 1e-4)};
    const Contact c = this->run(scene, settings(8, 4, 0.02, 0.0));
    for (int k = 0; k < 8; ++k) {
      const float expected =
          fragmentMu(m.normalized(), Side::B, dirs[static_cast<size_t>(k)].cast<float>());
      EXPECT_NEAR(c.mu.mu[k], expected, TypeParam::tolerance()) << m.transpose() << " k " << k;
    }
  }
}

// A flat patch covering whole texels (w = texture size, one pixel per texel, centres on texel
// centres) averages every texel: the friction module's flatPatchCone (B = plane with u along t,
// A = box bottom face with u along t and v along -b).
TYPED_TEST_P(SamplerSuite, FlatPatchMatchesFlatPatchCone) {
  const double size = 0.02;
  const auto map_b = roughMap(8, 3), map_a = roughMap(8, 11);
  for (int n : {4, 8, 16}) {
    const Vec3 h(0.5, 0.5, 0.1);
    // The box's local (size/2, -size/2, -h) sits on the contact point (u = v = 1/2 there).
    const Vec3 point(0.5 * size, 0.5 * size, 0.0);
    const Transform pose{point - Vec3(0.5 * size, -0.5 * size, -h.z())};
    Scene scene{{planeBody(map_b, size, 1.0), boxBody(h, pose, map_a, size, 1.0)},
                contactAt(point, 0.0)};
    const Contact c = this->run(scene, settings(n, 8, size, 0.1));
    PatchConeOptions opt;
    opt.directions = n;
    opt.gains = {0.1, 1.0, 1.0};
    const DirectionalMu cone = flatPatchCone(map_a.get(), *map_b, opt);
    ASSERT_EQ(c.mu.count, n);
    EXPECT_EQ(c.covered_pixels, 64);
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(c.mu.mu[k], cone.mu[k], 2.0 * TypeParam::tolerance()) << "N " << n << " k " << k;
    }
  }
}

// Sawtooth ridges along t (SPEC 7): sliding against the steep faces and along the ramps differ,
// so mu_{+t} != mu_{-t}; across the ridges (+-b) the two agree.
TYPED_TEST_P(SamplerSuite, SawtoothIsAsymmetric) {
  GeneratorSpec spec;
  spec.name = "sawtooth";
  spec.size = 64;
  const auto saw = std::make_shared<NormalMap>(generateNormalMap(spec));
  Scene scene{{planeBody(saw, 0.05, 4.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0)},
              contactAt(Vec3(0.003, 0.004, 0), 1e-4)};
  const Contact c = this->run(scene, settings());
  EXPECT_GT(std::abs(c.mu.mu[0] - c.mu.mu[2]), 0.1);
  EXPECT_NEAR(c.mu.mu[1], c.mu.mu[3], 2.0 * TypeParam::tolerance());
}

// Rotating the texture, the box and the contact frame together about the contact point leaves
// the cone unchanged (the rasterised patch is the same).
TYPED_TEST_P(SamplerSuite, RotatingTextureWithFrameKeepsCone) {
  GeneratorSpec spec;
  spec.name = "sawtooth";
  spec.size = 64;
  const auto saw = std::make_shared<NormalMap>(generateNormalMap(spec));
  const auto rough = roughMap(16, 5);
  auto cone = [&](double angle) {
    Body plane = planeBody(saw, 0.05, 4.0);
    plane.shapes[0].surface.texture_rotation = angle;
    const Transform pose{Vec3(0, 0, 0.1), Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ()))};
    Scene scene{{plane, boxBody(Vec3(0.1, 0.1, 0.1), pose, rough, 0.07, 1.0)},
                contactAt(Vec3::Zero(), 1e-4, angle)};
    return this->run(scene, settings(8));
  };
  const Contact ref = cone(0.0);
  for (double angle : {0.4, 1.3, -2.0}) {
    const Contact c = cone(angle);
    for (int k = 0; k < 8; ++k) {
      EXPECT_NEAR(c.mu.mu[k], ref.mu.mu[k], 2.0 * TypeParam::tolerance()) << angle << " " << k;
    }
  }
}

// Only one surface inside the volume (the box hovers 1 cm up): P is empty, mu = mu0.
TYPED_TEST_P(SamplerSuite, OneSurfaceFallsBackToMu0) {
  Scene scene{{planeBody(roughMap(8, 1), 0.1, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.11)}, roughMap(8, 2), 0.1, 1.0)},
              contactAt(Vec3::Zero(), 0.0)};
  const Contact c = this->run(scene, settings(4, 16, 0.02, 0.3));
  EXPECT_TRUE(c.fallback);
  EXPECT_EQ(c.covered_pixels, 0);
  for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(c.mu.mu[k], 0.3f);
}

// phi = 0 (surfaces exactly touching) still sees both (depth 0.01 w); a box corner on the
// contact covers a quarter of the patch.
TYPED_TEST_P(SamplerSuite, ZeroPenetrationAndCornerCoverage) {
  Scene scene{{planeBody(roughMap(8, 1), 0.1, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(8, 2), 0.1, 1.0)},
              contactAt(Vec3::Zero(), 0.0)};
  EXPECT_EQ(this->run(scene, settings()).covered_pixels, 256);
  scene.contact = contactAt(Vec3(0.1, 0.1, 0.0), 0.0);
  const Contact corner = this->run(scene, settings());
  EXPECT_EQ(corner.covered_pixels, 64);
  EXPECT_FALSE(corner.fallback);
}

// A sphere on the plane: only the cap within the thin volume is seen, |P| < R^2, close to the
// disc of radius sqrt(2 r (depth - gap)) in pixels.
TYPED_TEST_P(SamplerSuite, SphereGivesPartialCoverage) {
  Body sphere;
  sphere.pose.position = Vec3(0, 0, 0.1 - 1e-4);
  Shape s;
  s.type = ShapeType::Sphere;
  s.radius = 0.1;
  s.surface.normal_map = roughMap(8, 4);
  sphere.shapes.push_back(s);
  Scene scene{{planeBody(roughMap(8, 1), 0.1, 1.0), sphere}, contactAt(Vec3(0, 0, -0.5e-4), 1e-4)};
  const Contact c = this->run(scene, settings(4, 32));
  // Sphere bottom at -phi/2 from the contact point, clip at +(phi + 0.01 w)/2 = 1.5e-4.
  const double rho = std::sqrt(2.0 * 0.1 * (1.5e-4 + 0.5e-4));
  const double expected = kPi * rho * rho / std::pow(0.02 / 32, 2);
  EXPECT_GT(c.covered_pixels, 0);
  EXPECT_LT(c.covered_pixels, 32 * 32);
  EXPECT_NEAR(c.covered_pixels, expected, TypeParam::curvedCoverageTolerance() * expected);
}

// A triangle-mesh floor (two triangles whose diagonal crosses the patch) gives exactly the
// analytic plane's numbers: no pixel lost or counted twice on the shared edge.
TYPED_TEST_P(SamplerSuite, MeshEdgeMatchesPlane) {
  auto quad = std::make_shared<TriangleMeshData>();
  quad->vertices = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  quad->triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto map = roughMap(16, 9);
  Scene plane{{planeBody(map, 0.03, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(8, 2), 0.1, 1.0)},
              contactAt(Vec3(0.0013, -0.0007, 0), 1e-4)};
  Scene mesh = plane;
  mesh.bodies[0].shapes[0].type = ShapeType::TriangleMesh;
  mesh.bodies[0].shapes[0].mesh = quad;
  const Contact a = this->run(plane, settings(8));
  const Contact b = this->run(mesh, settings(8));
  EXPECT_EQ(b.covered_pixels, 256);
  const double tol = TypeParam::tessellationTolerance();
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(a.mu.mu[k], b.mu.mu[k], tol) << k;
  // The same floor with its own UVs (the plane's mapping) and interpolated frames.
  auto uv_quad = std::make_shared<TriangleMeshData>(*quad);
  for (const Vec3& v : uv_quad->vertices) uv_quad->uvs.emplace_back(v.x() / 0.03, v.y() / 0.03);
  mesh.bodies[0].shapes[0].mesh = uv_quad;
  const Contact c = this->run(mesh, settings(8));
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(a.mu.mu[k], c.mu.mu[k], 2.0 * tol) << k;
}

// A gain mask of 0.5 everywhere halves the surface's contribution (Eq. 7 with k per texel).
TYPED_TEST_P(SamplerSuite, GainMaskScalesContribution) {
  const double theta = 0.4;
  const auto facet = uniformMap(
      Vec3f(static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta))));
  Body plane = planeBody(facet, 0.1, 2.0);
  auto mask = std::make_shared<GainMask>();
  mask->width = mask->height = 2;
  mask->values.assign(4, 0.5f);
  plane.shapes[0].surface.mask = mask;
  Scene scene{{plane, boxBody(Vec3(0.2, 0.2, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0)},
              contactAt(Vec3::Zero(), 1e-4)};
  const Contact c = this->run(scene, settings(4, 16, 0.02, 0.1));
  EXPECT_NEAR(c.mu.mu[0], 0.1 + 2.0 * 0.5 * 2.0 / kPi * std::tan(theta),
              2.0 * TypeParam::tolerance());
}

// A cylinder lying on the plane with its texture seam (longitude +-pi) along the contact line:
// the patch crosses the seam and still gives finite coefficients within the model's range.
TYPED_TEST_P(SamplerSuite, TextureSeamStaysSane) {
  Body cylinder;
  cylinder.pose.position = Vec3(0, 0, 0.05 - 1e-4);
  cylinder.pose.rotation = Quat::FromTwoVectors(-Vec3::UnitX(), -Vec3::UnitZ());
  Shape s;
  s.type = ShapeType::Cylinder;
  s.radius = 0.05;
  s.half_height = 0.1;
  s.surface.normal_map = roughMap(16, 7);
  s.surface.texture_size = 0.07;
  cylinder.shapes.push_back(s);
  Scene scene{{planeBody(roughMap(8, 1), 0.1, 1.0), cylinder},
              contactAt(Vec3(0.001, 0.002, -0.5e-4), 1e-4)};
  const Contact c = this->run(scene, settings(8));
  EXPECT_FALSE(c.fallback);
  EXPECT_GT(c.covered_pixels, 16);
  EXPECT_LT(c.covered_pixels, 256);
  for (int k = 0; k < 8; ++k) {
    EXPECT_TRUE(std::isfinite(c.mu.mu[k]));
    EXPECT_GE(c.mu.mu[k], 0.2f - 1e-6f);
    EXPECT_LE(c.mu.mu[k], 0.2f + 2.0f * kDefaultMuMax);
  }
}

// Bad settings: each kind is an asperity::Error naming the parameter.
TYPED_TEST_P(SamplerSuite, BadSettingsThrow) {
  Scene scene{{planeBody(nullptr, 0.1, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0)},
              contactAt(Vec3::Zero(), 0.0)};
  auto expectError = [&](const FrictionSettings& s, const char* word) {
    try {
      this->run(scene, s);
      ADD_FAILURE() << "no error for " << word;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  for (double w : {0.0, -1.0, 1e-9, 1e3, std::nan("")}) {
    expectError(settings(4, 16, w), "patch_width");
  }
  for (int r : {0, 257}) expectError(settings(4, r), "patch_resolution");
  for (int n : {3, 65}) expectError(settings(n), "directions");
  if (TypeParam::multipleOf4Only()) expectError(settings(6), "multiple of 4");
  FrictionSettings s = settings();
  s.mu_max = 0.0f;
  expectError(s, "mu_max");
  // A contact naming a shape the body does not have.
  scene.contact.shape_a = 3;
  expectError(settings(), "shape");
}

// Tiny and huge widths inside the documented range still give sane numbers.
TYPED_TEST_P(SamplerSuite, ExtremeWidthsStaySane) {
  const double theta = 0.2;
  const auto facet = uniformMap(
      Vec3f(static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta))));
  for (double w : {1e-5, 50.0}) {
    Scene scene{{planeBody(facet, 0.1, 1.0),
                 boxBody(Vec3(100, 100, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0)},
                contactAt(Vec3::Zero(), 0.0)};
    const Contact c = this->run(scene, settings(4, 16, w, 0.0));
    EXPECT_EQ(c.covered_pixels, 256) << w;
    EXPECT_NEAR(c.mu.mu[0], 2.0 / kPi * std::tan(theta), 2.0 * TypeParam::tolerance()) << w;
  }
}

REGISTER_TYPED_TEST_SUITE_P(SamplerSuite, UniformFacetMatchesEquationFive,
                            FragmentFixturesMatchFragmentMu, FlatPatchMatchesFlatPatchCone,
                            SawtoothIsAsymmetric, RotatingTextureWithFrameKeepsCone,
                            OneSurfaceFallsBackToMu0, ZeroPenetrationAndCornerCoverage,
                            SphereGivesPartialCoverage, MeshEdgeMatchesPlane,
                            GainMaskScalesContribution, TextureSeamStaysSane, BadSettingsThrow,
                            ExtremeWidthsStaySane);

}  // namespace asperity::sampler_test
