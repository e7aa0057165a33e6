// The cpu sampler's planar path (sampler/patch_planar.hpp) against its reference, the raster
// path: an analytic oracle (a uniform-slope map, whose coefficient is the same everywhere), the
// tables' budget, and agreement over every contact of 100 steps of the experiments' scenes.
#include "sampler/patch_planar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/texture/generators.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// A map whose every texel is the normal of slopes (sx, sy): one ploughing vector everywhere.
std::shared_ptr<const NormalMap> uniformSlope(int size, float sx, float sy) {
  auto map = std::make_shared<NormalMap>(size, size);
  const Vec3f m = Vec3f(-sx, -sy, 1.0f).normalized();
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) map->at(i, j) = m;
  return map;
}

TEST(PlanarTables, UniformSlopeIntegratesToTheClosedForm) {
  // Over any polygon, rotated or not, the mean is max(0, g . e) of the one ploughing vector.
  const auto map = uniformSlope(16, 0.3f, -0.2f);
  const patch::TableLayout layout = patch::tableLayout(16, 16, 4);
  const patch::CoefficientTables tables(*map, nullptr, 4.0f, layout, nullptr);
  const Vec2f g = ploughingVector(map->at(0, 0), Side::B, 4.0f);
  const std::vector<Vec2> polygon = {{3.3, -7.1}, {41.9, 2.2}, {30.4, 29.7}, {-5.2, 12.5}};
  std::vector<int> which(static_cast<size_t>(tables.angles()));
  for (int a = 0; a < tables.angles(); ++a) which[static_cast<size_t>(a)] = a;
  std::vector<double> sums(which.size());
  const double area = tables.integrate(polygon, which, sums);
  for (int a = 0; a < tables.angles(); ++a) {
    const double t = 2.0 * kPi * a / tables.angles();
    const double expected = std::max(0.0, g.x() * std::cos(t) + g.y() * std::sin(t));
    EXPECT_NEAR(sums[static_cast<size_t>(a)] / area, expected, 1e-5) << "angle " << a;
  }
}

// A generated normal map (the scenes' generators, their default parameters unless given).
std::shared_ptr<const NormalMap> generated(const std::string& name, int size,
                                           std::map<std::string, std::string> params = {}) {
  GeneratorSpec spec;
  spec.name = name;
  spec.size = size;
  spec.params = std::move(params);
  return std::make_shared<NormalMap>(generateNormalMap(spec));
}

// Every angle's integral over `polygon` as a contact reads it (integrateGroups, which takes a
// coarser level for a tall footprint), angle by angle.
std::vector<double> readAsAContact(const patch::CoefficientTables& tables,
                                   std::span<const Vec2> polygon, double& area) {
  std::vector<double> sums(static_cast<size_t>(tables.angles()));
  std::vector<float> phase(static_cast<size_t>(tables.group()));
  for (int p = 0; p < tables.phases(); ++p) {
    area = tables.integrateGroups(polygon, p, 1, false, phase.data());
    for (int i = 0; i < tables.group(); ++i)
      sums[static_cast<size_t>(i * tables.phases() + p)] = phase[static_cast<size_t>(i)];
  }
  return sums;
}

// A square `side` cells wide about `centre`, turned by `turn` (rad), counter-clockwise.
std::vector<Vec2> turnedSquare(const Vec2& centre, double side, double turn) {
  const Vec2 along(std::cos(turn), std::sin(turn)), across(-along.y(), along.x());
  return {centre - 0.5 * side * (along + across), centre + 0.5 * side * (along - across),
          centre + 0.5 * side * (along + across), centre - 0.5 * side * (along - across)};
}

TEST(PlanarTables, CoarserLevelsReadTallFootprintsWithinTheirBound) {
  // Turned squares 20 to 120 cells tall read on the levels a contact takes against the finest
  // level's integrals: within kMaxLevelError of the mean at every angle. A uniform slope (the
  // same coefficient everywhere) coarsens exactly; stacking's acrylic keeps every level.
  const auto acrylic = generated("acrylic", 128);
  const auto slope = uniformSlope(64, 0.3f, -0.2f);
  for (const auto& map : {acrylic, slope}) {
    const patch::CoefficientTables tables(
        *map, nullptr, 4.0f, patch::tableLayout(map->width(), map->height(), 4), nullptr);
    ASSERT_EQ(tables.levels(), patch::CoefficientTables::kMaxLevels);
    std::vector<int> which(static_cast<size_t>(tables.angles()));
    for (int a = 0; a < tables.angles(); ++a) which[static_cast<size_t>(a)] = a;
    for (int k = 0; k < 12; ++k) {
      const std::vector<Vec2> square =
          turnedSquare(Vec2(11.3 * k, 5.7 * k), 14.0 + 7.0 * k, 0.37 * k);
      std::vector<double> finest(which.size());
      const double area = tables.integrate(square, which, finest);
      double read_area = 0.0;
      const std::vector<double> read = readAsAContact(tables, square, read_area);
      EXPECT_NEAR(read_area, area, 1e-9 * area);
      for (size_t a = 0; a < which.size(); ++a)
        EXPECT_NEAR(read[a] / area, finest[a] / area, patch::CoefficientTables::kMaxLevelError)
            << "square " << k << " angle " << a;
    }
  }
}

TEST(PlanarTables, TheGradientsLevelsReadFootprintsWithinTheirBound) {
  // The gradient enters times the tilt's tangent (at most tan(kMaxTilt)), so it is read on
  // levels where a footprint spans at most kMaxGradientRows rows: turned squares 4 to 48 cells
  // tall, read as a tilted face's contact reads them, against the finest gradient cells, within
  // kMaxLevelError in mu at the largest tilt, at every angle and in both components. Acrylic
  // keeps every level; the worm's sawtooth, whose coarse cells err alike along a side, does not
  // (read on all of them, these squares stray beyond the bound).
  const auto acrylic = generated("acrylic", 128);
  const auto sawtooth = generated("sawtooth", 64, {{"period", "16"}});
  for (const auto& map : {acrylic, sawtooth}) {
    const patch::CoefficientTables tables(
        *map, nullptr, 4.0f, patch::tableLayout(map->width(), map->height(), 4), nullptr);
    if (map == acrylic)
      EXPECT_EQ(tables.gradientLevels(), patch::CoefficientTables::kMaxLevels);
    else
      EXPECT_LT(tables.gradientLevels(), patch::CoefficientTables::kMaxLevels);
    const int group = tables.group(), phases = tables.phases();
    std::vector<int> which(static_cast<size_t>(tables.angles()));
    for (int a = 0; a < tables.angles(); ++a) which[static_cast<size_t>(a)] = a;
    const double tan_max = std::tan(patch::kMaxTilt);
    for (int k = 0; k < 12; ++k) {
      const std::vector<Vec2> square =
          turnedSquare(Vec2(9.1 * k, 13.4 * k), 4.0 + 4.0 * k, 0.61 * k);
      for (int channel = 1; channel <= 2; ++channel) {
        std::vector<double> finest(which.size());
        const double area = tables.integrate(square, which, finest, channel);
        std::vector<float> read(static_cast<size_t>(3 * group));
        for (int p = 0; p < phases; ++p) {
          EXPECT_NEAR(tables.integrateGroups(square, p, 1, true, read.data()), area, 1e-9 * area);
          for (int i = 0; i < group; ++i) {
            const auto a = static_cast<size_t>(i * phases + p);
            EXPECT_NEAR(tan_max * read[static_cast<size_t>(channel * group + i)] / area,
                        tan_max * finest[a] / area, patch::CoefficientTables::kMaxLevelError)
                << "square " << k << " channel " << channel << " angle " << a;
          }
        }
      }
    }
  }
}

TEST(PlanarTables, ASawtoothKeepsItsFinestCells) {
  // crawling_worm's skin: on cells of one texel a footprint's side along the teeth errs alike
  // at every tooth (up to 58 % of the raster path's coefficient); no coarser level passes.
  const auto sawtooth = generated("sawtooth", 64, {{"period", "16"}});
  const patch::CoefficientTables tables(*sawtooth, nullptr, 4.0f, patch::tableLayout(64, 64, 4),
                                        nullptr);
  EXPECT_EQ(tables.levels(), 1);
}

TEST(PlanarTables, AlignedRectanglesMatchTheirSplitCopies) {
  // A texture-aligned rectangle (one span per row of cells, over several repeats) and the same
  // rectangle with one vertex pushed out by 1e-9 cells (its rows split at the vertex, float
  // running sums): the same integrals.
  auto map = std::make_shared<NormalMap>(16, 12);
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 16; ++i) {
      const auto x = static_cast<float>(i), y = static_cast<float>(j);
      map->at(i, j) =
          Vec3f(0.4f * std::sin(1.3f * x + 0.7f * y), 0.3f * std::cos(0.9f * x * y), 1.0f)
              .normalized();
    }
  const patch::TableLayout layout = patch::tableLayout(16, 12, 4);
  const patch::CoefficientTables tables(*map, nullptr, 4.0f, layout, nullptr);
  std::vector<int> which(static_cast<size_t>(tables.angles()));
  for (int a = 0; a < tables.angles(); ++a) which[static_cast<size_t>(a)] = a;
  const double boxes[][4] = {{1.3, 2.7, 9.6, 7.2},
                             {-5.5, -3.25, 4.1, 20.9},
                             {25.2, 14.1, 57.9, 37.6},
                             {0.0, 0.0, 32.0, 24.0},
                             {-40.4, 30.5, -33.0, 31.0}};
  for (const auto& b : boxes) {
    const std::vector<Vec2> rect = {{b[0], b[1]}, {b[2], b[1]}, {b[2], b[3]}, {b[0], b[3]}};
    const std::vector<Vec2> pushed = {
        {b[0], b[1]}, {b[2], b[1]}, {b[2], b[3]}, {0.5 * (b[0] + b[2]), b[3] + 1e-9}, {b[0], b[3]}};
    std::vector<double> fast(which.size()), spans(which.size());
    const double area = tables.integrate(rect, which, fast);
    const double area_spans = tables.integrate(pushed, which, spans);
    EXPECT_NEAR(area, (b[2] - b[0]) * (b[3] - b[1]), 1e-9);
    EXPECT_NEAR(area, area_spans, 1e-6);
    for (size_t a = 0; a < which.size(); ++a)
      EXPECT_NEAR(fast[a] / area, spans[a] / area_spans, 1e-5) << "box " << b[0] << " angle " << a;
  }
}

TEST(PlanarTables, DiamondsMatchTheirSplitCopies) {
  // A square turned by 45 degrees against the texture and the same square with one vertex
  // pushed out by 1e-9 cells (its strips split there): close, at any repeat.
  auto map = std::make_shared<NormalMap>(16, 16);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const auto x = static_cast<float>(i), y = static_cast<float>(j);
      map->at(i, j) = Vec3f(0.2f * std::sin(0.4f * x + 0.3f * y), 0.15f * std::cos(0.5f * y), 1.0f)
                          .normalized();
    }
  const patch::TableLayout layout = patch::tableLayout(16, 16, 4);
  const patch::CoefficientTables tables(*map, nullptr, 4.0f, layout, nullptr);
  std::vector<int> which(static_cast<size_t>(tables.angles()));
  for (int a = 0; a < tables.angles(); ++a) which[static_cast<size_t>(a)] = a;
  const double centres[][3] = {{5.3, 7.1, 6.0}, {-20.2, 3.7, 11.3}, {40.9, -33.4, 4.4}};
  for (const auto& c : centres) {
    const double x = c[0], y = c[1], h = c[2];
    const std::vector<Vec2> diamond = {{x, y - h}, {x + h, y}, {x, y + h}, {x - h, y}};
    const std::vector<Vec2> pushed = {
        {x, y - h}, {x + h, y}, {x + 0.5 * h + 1e-9, y + 0.5 * h}, {x, y + h}, {x - h, y}};
    std::vector<double> fast(which.size()), spans(which.size());
    const double area = tables.integrate(diamond, which, fast);
    const double area_spans = tables.integrate(pushed, which, spans);
    ASSERT_GT(area, 0.0);
    for (size_t a = 0; a < which.size(); ++a) {
      const double mean = spans[a] / area_spans;
      EXPECT_NEAR(fast[a] / area, mean, 2e-3 + 0.01 * mean) << "centre " << x << " angle " << a;
    }
  }
}

TEST(PlanarTables, UniformSlopeGradientIntegratesToTheClosedForm) {
  // Where f = g . e > 0 the gradient in the tilt of a uniform slope p (unclamped) is
  // -(2 / pi) (e + (p . e) p), 0 elsewhere. Its cells are twice as large as f's where the
  // cells' rows and columns are even (kGradientCoarsening), as f's where they are odd (17 x 17
  // at one cell per texel); either way its integrals count f's cells (the area f's gives).
  for (const int size : {16, 17}) {
    const auto map = uniformSlope(size, 0.3f, -0.2f);
    const patch::TableLayout layout =
        size % 2 == 0 ? patch::tableLayout(size, size, 4) : patch::TableLayout{1, 16, 4};
    const patch::CoefficientTables tables(*map, nullptr, 4.0f, layout, nullptr);
    const Vec3f m = map->at(0, 0);
    const Vec2 p(m.x() / m.z(), m.y() / m.z());
    const Vec2f g = ploughingVector(m, Side::B, 4.0f);
    const std::vector<Vec2> polygon = {{3.3, -7.1}, {41.9, 2.2}, {30.4, 29.7}, {-5.2, 12.5}};
    std::vector<int> which(static_cast<size_t>(tables.angles()));
    for (int a = 0; a < tables.angles(); ++a) which[static_cast<size_t>(a)] = a;
    std::vector<double> f(which.size()), x(which.size()), y(which.size());
    const double area = tables.integrate(polygon, which, f, 0);
    EXPECT_NEAR(tables.integrate(polygon, which, x, 1), area, 1e-9 * area) << "size " << size;
    EXPECT_NEAR(tables.integrate(polygon, which, y, 2), area, 1e-9 * area) << "size " << size;
    for (int a = 0; a < tables.angles(); ++a) {
      const double t = 2.0 * kPi * a / tables.angles();
      const Vec2 e(std::cos(t), std::sin(t));
      const bool on = g.x() * e.x() + g.y() * e.y() > 0.0;
      const Vec2 expected = on ? Vec2(-2.0 / kPi * (e + p.dot(e) * p)) : Vec2(0.0, 0.0);
      EXPECT_NEAR(x[static_cast<size_t>(a)] / area, expected.x(), 1e-5)
          << "size " << size << " angle " << a;
      EXPECT_NEAR(y[static_cast<size_t>(a)] / area, expected.y(), 1e-5)
          << "size " << size << " angle " << a;
    }
  }
}

TEST(PlanarTables, BothSimdCopiesBuildTheSameBits) {
  // The build's loop over angles and the integrals' sums over strips have AVX2 copies
  // (math/simd.hpp); the tables (f and its tilt gradient, their coarser levels), the tilt error
  // and the integrals must not depend on which one ran.
  GeneratorSpec spec;
  spec.name = "concrete";
  spec.size = 64;
  const NormalMap map = generateNormalMap(spec);
  const patch::TableLayout layout = patch::tableLayout(64, 64, 4);
  const patch::CoefficientTables a(map, nullptr, 4.0f, layout, nullptr, SimdCopy::Auto);
  const patch::CoefficientTables b(map, nullptr, 4.0f, layout, nullptr, SimdCopy::Baseline);
  EXPECT_EQ(a.tiltError(), b.tiltError());
  EXPECT_GT(a.tiltError(), 0.0);
  const std::vector<Vec2> polygon = {{3.3, -7.1}, {41.9, 2.2}, {30.4, 29.7}, {-5.2, 12.5}};
  std::vector<int> which(static_cast<size_t>(a.angles()));
  for (int k = 0; k < a.angles(); ++k) which[static_cast<size_t>(k)] = k;
  for (int channel = 0; channel < 3; ++channel) {
    std::vector<double> x(which.size()), y(which.size());
    a.integrate(polygon, which, x, channel);
    b.integrate(polygon, which, y, channel);
    EXPECT_EQ(x, y) << "channel " << channel;
  }
  EXPECT_EQ(a.levels(), b.levels());
  EXPECT_EQ(a.gradientLevels(), b.gradientLevels());
  for (int phase = 0; phase < a.phases(); ++phase) {
    // Both phases side by side with the gradient: every width a contact reads.
    std::vector<float> x(static_cast<size_t>(6 * a.group())), y(x.size());
    EXPECT_EQ(a.integrateGroups(polygon, phase, 2, true, x.data()),
              b.integrateGroups(polygon, phase, 2, true, y.data()));
    EXPECT_EQ(x, y) << "phase " << phase;
  }
}

TEST(PlanarTables, BudgetHoldsAndOversizedTexturesAreRasterised) {
  // 512 x 512 at N = 16: within 64 MB; 8192 x 8192 fits no layout (the raster path samples it).
  const patch::TableLayout layout = patch::tableLayout(512, 512, 16);
  ASSERT_GT(layout.angles, 0);
  EXPECT_EQ(layout.angles % 16, 0);
  EXPECT_LE(layout.bytes(512, 512), patch::kTableBudgetBytes);
  EXPECT_EQ(patch::tableLayout(8192, 8192, 16).angles, 0);
}

TEST(PlanarTables, WorldsWithTheSameTexturesShareOneBuild) {
  // Two caches (two worlds) with maps loaded apart but equal texel for texel get the same
  // tables; another map, another mask or another mu_max get their own.
  const auto map = uniformSlope(32, 0.25f, 0.1f);
  const auto copy = uniformSlope(32, 0.25f, 0.1f);
  const auto other = uniformSlope(32, 0.25f, 0.11f);
  auto mask = std::make_shared<GainMask>();
  mask->width = mask->height = 2;
  mask->values = {1.0f, 0.5f, 0.5f, 1.0f};
  patch::TableCache first, second;
  const patch::CoefficientTables* built = first.get(map, nullptr, 4.0f, 16, nullptr);
  ASSERT_NE(built, nullptr);
  EXPECT_EQ(second.get(copy, nullptr, 4.0f, 16, nullptr), built);
  EXPECT_NE(second.get(other, nullptr, 4.0f, 16, nullptr), built);
  EXPECT_NE(second.get(copy, mask, 4.0f, 16, nullptr), built);
  EXPECT_NE(second.get(copy, nullptr, 3.0f, 16, nullptr), built);
  EXPECT_EQ(second.find(copy.get(), nullptr, 4.0f, 16), built);
  // A map whose tables would exceed the budget gets none (it is rasterised).
  ASSERT_EQ(patch::tableLayout(512, 512, 64).angles, 0);
  EXPECT_EQ(first.get(uniformSlope(512, 0.1f, 0.1f), nullptr, 4.0f, 64, nullptr), nullptr);
}

// One box resting on a plane (both with `map`), turned by `yaw` about n, its frame turned too.
std::unique_ptr<World> boxOnPlane(const std::shared_ptr<const NormalMap>& map, double yaw,
                                  const std::string& provider) {
  WorldSettings s;
  s.friction.reuse_pixels = 0.0;
  auto world = std::make_unique<World>(s);
  BodyDesc ground = groundPlaneDesc();
  ground.shapes[0].surface.normal_map = map;
  ground.shapes[0].surface.texture_size = 0.2;
  world->createBody(ground);
  BodyDesc box =
      boxDesc("box", Vec3::Constant(0.1),
              {Vec3(0.013, -0.021, 0.0999), Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ()))});
  box.shapes[0].surface.normal_map = map;
  box.shapes[0].surface.texture_size = 0.17;
  world->createBody(box);
  world->setFrictionProvider(FrictionProviders::builtIn().make(provider));
  return world;
}

TEST(PlanarPath, UniformSlopeBoxOnPlaneMatchesTheRasterPath) {
  // Every pixel has the same coefficient, so the raster mean is exact: the planar path must
  // give it (rounding aside) at any turn of the box against the texture and the frame. The
  // slope is along x, so each turn keeps every direction more than one table step (22.5
  // degrees) from perpendicular to g, where the interpolation between angles is exact.
  const auto map = uniformSlope(32, 0.4f, 0.0f);
  for (const double yaw : {0.0, 0.3, 0.7854, 1.2}) {
    auto planar = boxOnPlane(map, yaw, "cpu_planar"), raster = boxOnPlane(map, yaw, "cpu");
    planar->step();
    raster->step();
    const auto& a = planar->contacts();
    const auto& b = raster->contacts();
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GT(a.size(), 0u);
    EXPECT_EQ(planar->profile().planar, static_cast<int>(a.size())) << "yaw " << yaw;
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].covered_pixels, b[i].covered_pixels);
      for (int k = 0; k < a[i].mu.count; ++k)
        EXPECT_NEAR(a[i].mu.mu[static_cast<size_t>(k)], b[i].mu.mu[static_cast<size_t>(k)], 2e-5)
            << "yaw " << yaw << " contact " << i << " direction " << k;
    }
  }
}

// The coefficients of one contact of `world` by `provider` after turning the box (body 1)
// by `box_turn` about the contact point and the contact frame by `frame_turn`: each face is
// then tilted against the contact plane.
DirectionalMu tiltedContact(const World& world, const Quat& box_turn, const Quat& frame_turn,
                            const std::string& provider, int& planar) {
  std::vector<Body> bodies(world.bodies().begin(), world.bodies().end());
  Contact c = world.contacts().front();
  Body& box = bodies[1];
  box.pose.position = c.point + box_turn * (box.pose.position - c.point);
  box.pose.rotation = box_turn * box.pose.rotation;
  c.normal = frame_turn * c.normal;
  c.t = frame_turn * c.t;
  c.b = frame_turn * c.b;
  FrictionSettings settings = world.settings().friction;
  settings.reuse_pixels = 0.0;
  auto sampler = FrictionProviders::builtIn().make(provider);
  sampler->computeCoefficients(bodies, std::span<Contact>(&c, 1), settings);
  planar = sampler->lastPlanarCount();
  return c.mu;
}

TEST(PlanarPath, UniformSlopeTiltedFacesMatchTheRasterPathToSecondOrder) {
  // A face tilted against the contact plane turns every meso normal: for a uniform slope p,
  // f = (2 / pi) (p . e - tau . e) / (1 + p . tau) exactly. Shaded as if flat, a tilt of 8.5e-3
  // rad is off by up to (2 / pi) |tau| (1 + |p|^2), 6e-3 here; the tables' gradient leaves the
  // second order, a few 1e-5. Both faces tilt, A and B each its own way (8.5e-3 and 4.3e-3 rad
  // about axes at right angles: the box's face by 9.5e-3 against the contact plane).
  // The slope points 56.25 degrees off the map's x: half a table step from every tabulated
  // angle perpendicular to it (below: a map with one there is rasterised when tilted), and no
  // direction the box or the plane reads lies within a table step of perpendicular to it,
  // where the interpolation between angles is exact.
  const float heading = static_cast<float>(56.25 * kPi / 180.0);
  const auto map = uniformSlope(32, 0.4f * std::cos(heading), 0.4f * std::sin(heading));
  auto world = boxOnPlane(map, 0.3, "cpu");
  world->step();
  ASSERT_FALSE(world->contacts().empty());
  double worst_flat = 0.0;
  for (const double tilt : {0.0, 0.002, 0.005, 0.0085}) {
    for (const Vec3& axis : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, -1, 0).normalized()}) {
      const Quat box_turn(Eigen::AngleAxisd(tilt, axis));
      const Quat frame_turn(Eigen::AngleAxisd(-0.5 * tilt, Vec3(axis.y(), axis.x(), 0)));
      int planar = 0, raster = 0;
      const DirectionalMu p = tiltedContact(*world, box_turn, frame_turn, "cpu_planar", planar);
      const DirectionalMu r = tiltedContact(*world, box_turn, frame_turn, "cpu", raster);
      ASSERT_EQ(planar, 1) << "tilt " << tilt;
      for (int k = 0; k < r.count; ++k) {
        const auto i = static_cast<size_t>(k);
        EXPECT_NEAR(p.mu[i], r.mu[i], 5e-5) << "tilt " << tilt << " direction " << k;
      }
      if (tilt == 0.0085) {
        // What the tilt changes, so that the bound above means something.
        int unused = 0;
        const DirectionalMu flat =
            tiltedContact(*world, Quat::Identity(), Quat::Identity(), "cpu", unused);
        for (int k = 0; k < r.count; ++k) {
          const auto i = static_cast<size_t>(k);
          worst_flat = std::max(worst_flat, static_cast<double>(std::abs(flat.mu[i] - r.mu[i])));
        }
      }
    }
  }
  EXPECT_GT(worst_flat, 2e-3);
}

TEST(PlanarPath, TiltedFacesWhereFirstOrderMissesTooMuchAreRasterised) {
  // A slope along the map's x: at the tabulated angles across it every fragment lies at the
  // kink of max(0, f), where a tilt of |tau| adds (2 / pi) max(0, -tau . e) that no gradient
  // gives. Its tilt error, (2 / pi) tan(kMaxTilt) at those angles, stops the planar path past
  // about 1.6e-3 rad; a map with no fragment near the kink takes any tilt up to kMaxTilt.
  const auto across = uniformSlope(32, 0.4f, 0.0f);
  const float heading = static_cast<float>(56.25 * kPi / 180.0);
  const auto off_axis = uniformSlope(32, 0.4f * std::cos(heading), 0.4f * std::sin(heading));
  const patch::CoefficientTables kinked(*across, nullptr, kDefaultMuMax,
                                        patch::tableLayout(32, 32, 4), nullptr);
  const patch::CoefficientTables clear(*off_axis, nullptr, kDefaultMuMax,
                                       patch::tableLayout(32, 32, 4), nullptr);
  EXPECT_NEAR(kinked.tiltError(), 2.0 / kPi * std::tan(patch::kMaxTilt), 1e-6);
  EXPECT_EQ(clear.tiltError(), 0.0);
  auto world = boxOnPlane(across, 0.3, "cpu");
  world->step();
  ASSERT_FALSE(world->contacts().empty());
  const Vec3 axis(1, 0, 0);
  for (const double tilt : {0.0, 0.001, 0.003, 0.009}) {
    int planar = 0;
    tiltedContact(*world, Quat(Eigen::AngleAxisd(tilt, axis)), Quat::Identity(), "cpu_planar",
                  planar);
    EXPECT_EQ(planar, tilt < 1.5e-3 ? 1 : 0) << "tilt " << tilt;
  }
}

// The world runs on the raster path; at every call each contact is also sampled by the planar
// path (alone, so that the count tells whether the planar path took it) and by the raster
// path at 4 R (closer to the footprint's continuous mean: the raster path's own sampling
// noise is its difference from that).
class Compared : public FrictionProvider {
 public:
  Compared()
      : raster_(options(PatchPath::Raster)),
        fine_(options(PatchPath::Raster)),
        planar_(options(PatchPath::Planar)) {}
  std::string name() const override { return "cpu"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override {
    FrictionSettings every = settings;
    every.reuse_pixels = 0.0;
    raster_.computeCoefficients(bodies, contacts, every);
    FrictionSettings fine = every;
    fine.patch_resolution = 4 * settings.patch_resolution;
    for (Contact& c : contacts) {
      Contact p = c, f = c;
      planar_.computeCoefficients(bodies, std::span<Contact>(&p, 1), every);
      if (planar_.lastPlanarCount() != 1) continue;
      fine_.computeCoefficients(bodies, std::span<Contact>(&f, 1), fine);
      record(c, p, f, settings.mu0);
    }
  }

  int compared = 0, pixels_differ = 0;
  std::array<double, kMaxDirections> raster_sum{}, planar_sum{}, fine_sum{};
  std::vector<double> planar_apart, noise, planar_fine;  // per contact: largest relative difference

 private:
  static CpuSamplerOptions options(PatchPath path) {
    CpuSamplerOptions o;
    o.path = path;
    return o;
  }
  static double apart(const Contact& a, const Contact& b) {
    double worst = 0.0;
    for (int k = 0; k < a.mu.count; ++k) {
      const double x = a.mu.mu[static_cast<size_t>(k)], y = b.mu.mu[static_cast<size_t>(k)];
      worst = std::max(worst, std::abs(x - y) / std::max(std::abs(y), 1e-9));
    }
    return worst;
  }
  void record(const Contact& r, const Contact& p, const Contact& f, double mu0) {
    (void)mu0;
    ++compared;
    pixels_differ += r.covered_pixels != p.covered_pixels;
    for (int k = 0; k < r.mu.count; ++k) {
      raster_sum[static_cast<size_t>(k)] += r.mu.mu[static_cast<size_t>(k)];
      planar_sum[static_cast<size_t>(k)] += p.mu.mu[static_cast<size_t>(k)];
    }
    planar_apart.push_back(apart(p, r));
    noise.push_back(apart(r, f));
    planar_fine.push_back(apart(p, f));
    for (int k = 0; k < r.mu.count; ++k)
      fine_sum[static_cast<size_t>(k)] += f.mu.mu[static_cast<size_t>(k)];
  }

  CpuPatchSampler raster_, fine_, planar_;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

void checkScene(const std::string& file) {
  SceneDesc desc = loadScene(test::sourcePath(file));
  auto world = instantiate(desc);
  auto compared = std::make_unique<Compared>();
  const Compared& c = *compared;
  world->setFrictionProvider(std::move(compared));
  for (int i = 0; i < 100; ++i) world->step();
  ASSERT_GT(c.compared, 0) << file;
  const int n = desc.settings.friction.directions;
  double worst_mean = 0.0, worst_fine = 0.0, raster_fine = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = c.raster_sum[static_cast<size_t>(k)], p = c.planar_sum[static_cast<size_t>(k)];
    const double f = c.fine_sum[static_cast<size_t>(k)];
    worst_mean = std::max(worst_mean, std::abs(p - r) / r);
    worst_fine = std::max(worst_fine, std::abs(p - f) / f);
    raster_fine = std::max(raster_fine, std::abs(r - f) / f);
  }
  int over = 0, beyond = 0;
  for (size_t i = 0; i < c.planar_apart.size(); ++i) {
    over += c.planar_apart[i] > 0.10;
    beyond += c.planar_apart[i] > 0.10 && c.planar_fine[i] > c.noise[i];
  }
  std::printf(
      "%s: %d planar contacts, |P| differs at %d. Mean mu_d per direction, worst direction: "
      "planar vs raster %.3f %%, planar vs raster at 4R %.3f %%, raster vs raster at 4R %.3f "
      "%%. Per contact, worst direction: planar vs raster median %.2f %%, 99 %% %.2f %%, max "
      "%.2f %% (%d over 10 %%, %d of them farther from 4R than the raster path); raster vs "
      "raster at 4R (its sampling noise) median %.2f %%, 99 %% %.2f %%\n",
      file.c_str(), c.compared, c.pixels_differ, 100 * worst_mean, 100 * worst_fine,
      100 * raster_fine, 100 * quantile(c.planar_apart, 0.5), 100 * quantile(c.planar_apart, 0.99),
      100 * quantile(c.planar_apart, 1.0), over, beyond, 100 * quantile(c.noise, 0.5),
      100 * quantile(c.noise, 0.99));
  // Each contact within 10 % of the raster path, or nearer the raster path at 4R than the
  // raster path is (small footprints, where the raster path's own noise exceeds 10 %: on
  // sawtooth_plane, 64-pixel contacts whose raster path is 10 % from 4R); the same pixels in P.
  EXPECT_EQ(c.pixels_differ, 0) << file;
  EXPECT_EQ(beyond, 0) << file;
  // The means within 2 % of the raster path's, or, where the raster path at R itself strays
  // further from the footprint's mean (a sawtooth of two texels per pixel aliases), closer to
  // the raster path at 4R than R is, and within 1 % of it.
  if (worst_mean >= 0.02) {
    EXPECT_LT(worst_fine, raster_fine) << file;
    EXPECT_LT(worst_fine, 0.01) << file;
  }
}

TEST(PlanarPath, SameBitsOnOneAndTwoThreads) {
  // The tables are built on the pool (a row per item) and the contacts sampled on it.
  auto run = [](int threads) {
    SceneDesc desc = loadScene(test::sourcePath("scenes/examples/oak_stacks.json"));
    desc.friction_provider = "cpu_planar";
    desc.settings.threads = threads;
    auto world = instantiate(desc);
    for (int i = 0; i < 60; ++i) world->step();
    EXPECT_GT(world->profile().planar, 0);
    return world->stateHash();
  };
  EXPECT_EQ(run(1), run(2));
}

TEST(PlanarAgreement, Stacking) {
  checkScene("scenes/stacking.json");
}
TEST(PlanarAgreement, BoxesOnMaterials) {
  checkScene("scenes/boxes_on_materials.json");
}
TEST(PlanarAgreement, SawtoothPlane) {
  checkScene("scenes/sawtooth_plane.json");
}
TEST(PlanarAgreement, CrawlingWorm) {
  checkScene("scenes/crawling_worm.json");
}
TEST(PlanarAgreement, OakStacks) {
  checkScene("scenes/examples/oak_stacks.json");
}

}  // namespace
}  // namespace asperity
