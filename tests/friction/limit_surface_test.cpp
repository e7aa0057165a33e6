// Limit-surface projections (SPEC 4): inside stays, outside lands on the closest boundary
// point, box and polygon agree at N = 4 on the axes, idempotence, lambda_n <= 0.
#include "asperity/friction/limit_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

// The polygon's vertex k for coefficients mu and normal impulse ln.
Vec2 vertexOf(const DirectionalMu& mu, int k, double ln) {
  const double angle = 2.0 * kPi * (k % mu.count) / mu.count;
  return mu.mu[k % mu.count] * ln * Vec2(std::cos(angle), std::sin(angle));
}

// Distance from x to the polygon boundary by dense sampling of every edge.
double bruteBoundaryDistance(const DirectionalMu& mu, double ln, const Vec2& x) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < mu.count; ++k) {
    const Vec2 p = vertexOf(mu, k, ln), q = vertexOf(mu, k + 1, ln);
    for (int s = 0; s <= 2000; ++s) {
      best = std::min(best, (p + (q - p) * (s / 2000.0) - x).norm());
    }
  }
  return best;
}

// Distance from y to the nearest polygon edge (0 when y lies on the boundary).
double edgeDistance(const DirectionalMu& mu, double ln, const Vec2& y) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < mu.count; ++k) {
    const Vec2 p = vertexOf(mu, k, ln), e = vertexOf(mu, k + 1, ln) - p;
    const double s = std::clamp((y - p).dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (p + s * e - y).norm());
  }
  return best;
}

// A deterministic, non-convex star polygon with N directions.
DirectionalMu spikyMu(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.05f, 1.0f);
  DirectionalMu mu = DirectionalMu::uniform(n, 0.0f);
  for (int k = 0; k < n; ++k) mu.mu[k] = u(rng);
  return mu;
}

// Coulomb: inside unchanged, outside scaled onto radius mu ln.
TEST(CoulombLimit, Disc) {
  const CoulombLimit c{0.5};
  EXPECT_EQ(c.project(Vec2(0.3, 0.2), 2.0), Vec2(0.3, 0.2));
  const Vec2 out = c.project(Vec2(3.0, 4.0), 2.0);
  EXPECT_TRUE(near(out.norm(), 1.0, 1e-12));
  EXPECT_TRUE(near(out.x() / out.y(), 0.75, 1e-12));
  EXPECT_EQ(c.project(Vec2(3.0, 4.0), 0.0), Vec2::Zero());
  EXPECT_EQ(c.project(Vec2(3.0, 4.0), -1.0), Vec2::Zero());
}

// The asymmetric box clamps each side by its own coefficient (SPEC 4 signs).
TEST(BoxLimit, AsymmetricClamp) {
  const BoxLimit box{0.4, 0.3, 0.1, 0.2};  // +t, +b, -t, -b
  EXPECT_EQ(box.project(Vec2(0.5, 0.1), 2.0), Vec2(0.5, 0.1));
  EXPECT_EQ(box.project(Vec2(5.0, 5.0), 2.0), Vec2(0.8, 0.6));
  EXPECT_EQ(box.project(Vec2(-5.0, -5.0), 2.0), Vec2(-0.2, -0.4));
  EXPECT_EQ(box.project(Vec2(-5.0, 0.1), 2.0), Vec2(-0.2, 0.1));
  EXPECT_EQ(box.project(Vec2(1.0, 1.0), 0.0), Vec2::Zero());
}

// fromDirectional reads k = 0, N/4, N/2, 3N/4, and follows the polygon otherwise.
TEST(BoxLimit, FromDirectional) {
  DirectionalMu mu = DirectionalMu::uniform(8, 0.0f);
  mu.mu = {0.1f, 9.0f, 0.2f, 9.0f, 0.3f, 9.0f, 0.4f, 9.0f};
  const BoxLimit box = BoxLimit::fromDirectional(mu);
  EXPECT_FLOAT_EQ(static_cast<float>(box.mu_pos_t), 0.1f);
  EXPECT_FLOAT_EQ(static_cast<float>(box.mu_pos_b), 0.2f);
  EXPECT_FLOAT_EQ(static_cast<float>(box.mu_neg_t), 0.3f);
  EXPECT_FLOAT_EQ(static_cast<float>(box.mu_neg_b), 0.4f);
  const DirectionalMu odd = spikyMu(5, 3);
  const BoxLimit box5 = BoxLimit::fromDirectional(odd);
  EXPECT_FLOAT_EQ(static_cast<float>(box5.mu_pos_t), odd.mu[0]);
  EXPECT_DOUBLE_EQ(box5.mu_pos_b, odd.along(0.5 * kPi));
  EXPECT_DOUBLE_EQ(box5.mu_neg_t, odd.along(kPi));
  EXPECT_DOUBLE_EQ(box5.mu_neg_b, odd.along(1.5 * kPi));
}

// Projecting twice equals projecting once, for every limit surface.
TEST(LimitSurfaces, Idempotent) {
  const CoulombLimit disc{0.6};
  const BoxLimit box{0.4, 0.3, 0.1, 0.2};
  const PolygonLimit poly{spikyMu(64, 99)};
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coord(-3.0, 3.0);
  for (int i = 0; i < 200; ++i) {
    const Vec2 x(coord(rng), coord(rng));
    const Vec2 c = disc.project(x, 1.7);
    EXPECT_LT((disc.project(c, 1.7) - c).norm(), 1e-12);
    const Vec2 b = box.project(x, 1.7);
    EXPECT_EQ(box.project(b, 1.7), b);
    const Vec2 p = poly.project(x, 1.7);
    EXPECT_LT((poly.project(p, 1.7) - p).norm(), 1e-12);
  }
}

// Points inside the star polygon stay put (random polygons, several N).
TEST(PolygonLimit, InsideStays) {
  for (int n : {4, 5, 16, 64}) {
    const PolygonLimit poly{spikyMu(n, 7u + static_cast<unsigned>(n))};
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> frac(0.0, 0.999), ang(0.0, 2.0 * kPi);
    for (int i = 0; i < 200; ++i) {
      // A point inside: a fraction of the boundary radius along a random angle.
      const double a = ang(rng);
      const Vec2 x = frac(rng) * poly.mu.along(a) * 1.5 * Vec2(std::cos(a), std::sin(a));
      EXPECT_EQ(poly.project(x, 1.5), x) << n << " " << a;
    }
  }
}

// Points outside land on an edge, at the closest boundary point (dense brute force), and
// projecting again changes nothing.
TEST(PolygonLimit, OutsideGoesToClosestBoundaryPoint) {
  for (int n : {4, 5, 16}) {
    const PolygonLimit poly{spikyMu(n, 21u + static_cast<unsigned>(n))};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    int outside = 0;
    for (int i = 0; i < 100; ++i) {
      const Vec2 x(coord(rng), coord(rng));
      const double a = std::atan2(x.y(), x.x());
      if (x.norm() <= poly.mu.along(a) * 2.0) continue;
      ++outside;
      const Vec2 y = poly.project(x, 2.0);
      EXPECT_LT(edgeDistance(poly.mu, 2.0, y), 1e-12);
      EXPECT_LE((y - x).norm(), bruteBoundaryDistance(poly.mu, 2.0, x) + 1e-12);
      EXPECT_TRUE(near((y - x).norm(), bruteBoundaryDistance(poly.mu, 2.0, x), 1e-3, 1e-4));
      const Vec2 z = poly.project(y, 2.0);
      EXPECT_LT((z - y).norm(), 1e-12);
    }
    EXPECT_GT(outside, 50);
  }
}

// At N = 4 the polygon is the rhombus through the box's axis points: they agree on the axes
// and the polygon's projection always lies inside the box.
TEST(PolygonLimit, AgreesWithBoxAtFour) {
  DirectionalMu mu = DirectionalMu::uniform(4, 0.0f);
  mu.mu = {0.4f, 0.3f, 0.1f, 0.2f};
  const PolygonLimit poly{mu};
  const BoxLimit box = BoxLimit::fromDirectional(mu);
  for (double s : {-3.0, -0.15, 0.0, 0.05, 0.7, 4.0}) {
    for (const Vec2& x : {Vec2(s, 0.0), Vec2(0.0, s)}) {
      const Vec2 p = poly.project(x, 1.3), q = box.project(x, 1.3);
      EXPECT_TRUE(near(p.x(), q.x(), 1e-12, 1e-12)) << x.transpose();
      EXPECT_TRUE(near(p.y(), q.y(), 1e-12, 1e-12)) << x.transpose();
    }
  }
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  for (int i = 0; i < 200; ++i) {
    const Vec2 p = poly.project(Vec2(coord(rng), coord(rng)), 1.3);
    EXPECT_LT((box.project(p, 1.3) - p).norm(), 1e-12);
  }
}

// A zero coefficient removes friction along that direction only.
TEST(PolygonLimit, ZeroCoefficientDirection) {
  DirectionalMu mu = DirectionalMu::uniform(4, 0.5f);
  mu.mu[0] = 0.0f;
  const PolygonLimit poly{mu};
  const Vec2 y = poly.project(Vec2(1.0, 0.0), 1.0);
  EXPECT_LT(y.norm(), 1e-12);
  EXPECT_EQ(poly.project(Vec2(-0.2, 0.0), 1.0), Vec2(-0.2, 0.0));
  const PolygonLimit none{DirectionalMu::uniform(8, 0.0f)};
  EXPECT_EQ(none.project(Vec2(0.3, -0.1), 1.0), Vec2::Zero());
}

// lambda_n <= 0 gives no friction; a bad direction count throws.
TEST(PolygonLimit, ZeroNormalImpulseAndBadCount) {
  const PolygonLimit poly{DirectionalMu::uniform(16, 0.5f)};
  EXPECT_EQ(poly.project(Vec2(0.1, 0.1), 0.0), Vec2::Zero());
  EXPECT_EQ(poly.project(Vec2(0.1, 0.1), -2.0), Vec2::Zero());
  EXPECT_THROW(PolygonLimit{}.project(Vec2(0.1, 0.1), 1.0), Error);
}

}  // namespace
}  // namespace asperity

namespace asperity {
namespace {

// The solver's form of each projection reports whether the point moved (the contact slides),
// and gives the same point as the plain one.
TEST(LimitSurface, OutsideFlagTellsWhetherThePointMoved) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const CoulombLimit disc{0.6};
  const BoxLimit box{0.2, 0.3, 0.4, 0.5};
  PolygonLimit polygon{DirectionalMu::uniform(8, 0.5f)};
  polygon.mu.mu[3] = 0.1f;
  int moved = 0;
  int stayed = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 x(u(rng), u(rng));
    const double ln = i % 10 == 0 ? 0.0 : std::abs(u(rng));
    auto check = [&](const auto& limit) {
      bool outside = false;
      const Vec2 p = limit.project(x, ln, outside);
      EXPECT_EQ(p, limit.project(x, ln));
      EXPECT_EQ(outside, p != x);
      (outside ? moved : stayed) += 1;
    };
    check(disc);
    check(box);
    check(polygon);
  }
  // Both cases happen: points inside and outside each surface.
  EXPECT_GT(moved, 100);
  EXPECT_GT(stayed, 100);
}

// Each surface builds itself from a contact's coefficients: the disc from mu0 alone.
TEST(LimitSurface, FromContact) {
  DirectionalMu mu = DirectionalMu::uniform(8, 0.5f);
  mu.mu[0] = 0.9f;
  EXPECT_EQ(CoulombLimit::fromContact(mu, 0.3).mu, 0.3);
  EXPECT_FLOAT_EQ(static_cast<float>(BoxLimit::fromContact(mu, 0.3).mu_pos_t), 0.9f);
  EXPECT_EQ(PolygonLimit::fromContact(mu, 0.3).mu.mu[0], 0.9f);
}

}  // namespace
}  // namespace asperity
