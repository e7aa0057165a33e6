// The cpu sampler's planar path (sampler/patch_planar.hpp) against its reference, the raster
// path: an analytic oracle (a uniform-slope map, whose coefficient is the same everywhere), the
// tables' budget, and agreement over every contact of 100 steps of the experiments' scenes.
#include "sampler/patch_planar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
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
  std::printf(
      "%s: %d planar contacts, |P| differs at %d. Mean mu_d per direction, worst direction: "
      "planar vs raster %.3f %%, planar vs raster at 4R %.3f %%, raster vs raster at 4R %.3f "
      "%%. Per contact, worst direction: planar vs raster median %.2f %%, 99 %% %.2f %%, max "
      "%.2f %%; raster vs raster at 4R (its sampling noise) median %.2f %%, 99 %% %.2f %%\n",
      file.c_str(), c.compared, c.pixels_differ, 100 * worst_mean, 100 * worst_fine,
      100 * raster_fine, 100 * quantile(c.planar_apart, 0.5), 100 * quantile(c.planar_apart, 0.99),
      100 * quantile(c.planar_apart, 1.0), 100 * quantile(c.noise, 0.5),
      100 * quantile(c.noise, 0.99));
  // Each contact within 10 % of the raster path, the same pixels in P.
  EXPECT_EQ(c.pixels_differ, 0) << file;
  EXPECT_LE(quantile(c.planar_apart, 1.0), 0.10) << file;
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
