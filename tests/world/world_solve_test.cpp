// Physics oracles for the collide -> friction -> solve stages on hand-built worlds (a static
// plane and boxes): stick/slip on an incline, asymmetric friction bounds, sliding distances,
// stacking, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "asperity/error.hpp"
#include "asperity/sampler/constant_provider.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

constexpr double kG = 9.81;
constexpr double kHalf = 0.1;  // 0.2 m cubes

// Fixed coefficients for every contact (SPEC 1 order: +t, +b, -t, -b), checking that the
// cube is body A (normal from the plane up into the cube).
class FixedProvider : public FrictionProvider {
 public:
  explicit FixedProvider(DirectionalMu mu) : mu_(mu) {}
  std::string name() const override { return "fixed"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings&) override {
    for (Contact& c : contacts) {
      EXPECT_TRUE(bodies[c.body_a].isDynamic());
      c.mu = mu_;
    }
  }

 private:
  DirectionalMu mu_;
};

DirectionalMu box4(float pt, float pb, float nt, float nb) {
  DirectionalMu mu = DirectionalMu::uniform(4, 0.0f);
  mu.mu = {pt, pb, nt, nb};
  return mu;
}

// A cube resting on a plane tilted by `angle` about y (downhill = +x of the incline).
double inclineSlide(double angle, double mu, LimitSurfaceKind kind) {
  WorldSettings s;
  s.limit_surface = kind;
  s.friction.mu0 = mu;
  World world(s);
  const Quat tilt(Eigen::AngleAxisd(angle, Vec3::UnitY()));
  world.createBody(groundPlaneDesc(tilt * Vec3::UnitZ()));
  const BodyId cube =
      world.createBody(boxDesc("cube", Vec3::Constant(kHalf), {tilt * Vec3(0, 0, kHalf), tilt}));
  // Measured from t = 0.1 s, once the contacts exist, over 1 s.
  for (int i = 0; i < 10; ++i) world.step();
  const Vec3 start = world.body(cube).pose.position;
  for (int i = 0; i < 100; ++i) world.step();
  return (world.body(cube).pose.position - start).norm();
}

TEST(WorldSolve, InclineSticksIffTanBelowMu) {
  // tan(angle) = mu at 26.57 degrees for mu = 0.5: one degree below sticks, one above slides.
  const double critical = std::atan(0.5);
  const double below = critical - 1.0 * kPi / 180, above = critical + 1.0 * kPi / 180;
  for (const LimitSurfaceKind kind : {LimitSurfaceKind::Coulomb, LimitSurfaceKind::Box}) {
    EXPECT_LT(inclineSlide(below, 0.5, kind), 1e-3);
    // Sliding from 0.1 s to 1.1 s at a = g (sin - mu cos): a (1.1^2 - 0.1^2) / 2.
    const double expected = 0.5 * kG * (std::sin(above) - 0.5 * std::cos(above)) * 1.2;
    EXPECT_TRUE(near(inclineSlide(above, 0.5, kind), expected, 0.05));
  }
}

// A cube on a flat plane pushed by a constant horizontal force; its displacement after 0.5 s.
double pushed(const DirectionalMu& mu, const Vec3& force) {
  World world;
  world.setFrictionProvider(std::make_unique<FixedProvider>(mu));
  world.createBody(groundPlaneDesc());
  const BodyId cube = world.createBody(
      boxDesc("cube", Vec3::Constant(kHalf), {Vec3(0, 0, kHalf), Quat::Identity()}));
  // The push starts at 0.1 s, once the cube rests on its contacts.
  world.addLoad(LoadDesc{"push", cube, LoadDesc::Kind::Force, force, Vec3::Zero(), 0.1, 1e9});
  for (int i = 0; i < 10; ++i) world.step();
  const Vec3 start = world.body(cube).pose.position;
  for (int i = 0; i < 50; ++i) world.step();
  return (world.body(cube).pose.position - start).head<2>().norm();
}

TEST(WorldSolve, AsymmetricBoxHoldsEachDirectionByItsOwnBound) {
  // SPEC 1: pushing along d is resisted along -d, bounded by mu_{-d}.
  const DirectionalMu mu = box4(0.2f, 0.3f, 0.4f, 0.5f);
  const double weight = 8.0 * std::pow(kHalf, 3) * 1000.0 * kG;
  const struct {
    Vec3 dir;
    double bound;
  } cases[] = {
      {Vec3::UnitX(), 0.4}, {-Vec3::UnitX(), 0.2}, {Vec3::UnitY(), 0.5}, {-Vec3::UnitY(), 0.3}};
  for (const auto& c : cases) {
    EXPECT_LT(pushed(mu, 0.95 * c.bound * weight * c.dir), 1e-4) << c.dir.transpose();
    EXPECT_GT(pushed(mu, 1.05 * c.bound * weight * c.dir), 1e-2) << c.dir.transpose();
  }
}

// How far a cube launched at `speed` along `dir` slides (dt = 1 ms).
double slideDistance(World& world, const Vec3& velocity) {
  world.settings().dt = 0.001;
  world.createBody(groundPlaneDesc());
  BodyDesc d = boxDesc("cube", Vec3::Constant(kHalf), {Vec3(0, 0, kHalf), Quat::Identity()});
  d.linear_velocity = velocity;
  const BodyId cube = world.createBody(d);
  for (int i = 0; i < 600; ++i) world.step();
  EXPECT_LT(world.body(cube).linear_velocity.norm(), 1e-6);
  return world.body(cube).pose.position.head<2>().norm();
}

TEST(WorldSolve, IsotropicSlideStopsAtVSquaredOverTwoMuG) {
  // Coulomb, mu = 0.5, v = 1 m/s: d = v^2 / (2 mu g) = 0.102 m in 8 directions.
  for (int k = 0; k < 8; ++k) {
    const double a = 2.0 * kPi * k / 8;
    WorldSettings s;
    s.limit_surface = LimitSurfaceKind::Coulomb;
    s.friction.mu0 = 0.5;
    World world(s);
    const double d = slideDistance(world, Vec3(std::cos(a), std::sin(a), 0.0));
    EXPECT_TRUE(near(d, 1.0 / (2 * 0.5 * kG), 0.02)) << "direction " << k;
  }
}

TEST(WorldSolve, AsymmetricSlideUsesTheResistingDirection) {
  // Sliding along d is braked by mu_{-d}: +t by 0.4, -t by 0.2, +b by 0.5, -b by 0.3.
  const DirectionalMu mu = box4(0.2f, 0.3f, 0.4f, 0.5f);
  const struct {
    Vec3 v;
    double mu;
  } cases[] = {
      {Vec3::UnitX(), 0.4}, {-Vec3::UnitX(), 0.2}, {Vec3::UnitY(), 0.5}, {-Vec3::UnitY(), 0.3}};
  for (const auto& c : cases) {
    World world;
    world.setFrictionProvider(std::make_unique<FixedProvider>(mu));
    const double d = slideDistance(world, c.v);
    EXPECT_TRUE(near(d, 1.0 / (2 * c.mu * kG), 0.02)) << c.v.transpose();
  }
}

TEST(WorldSolve, StackOfTenStandsForAMinute) {
  // 20 iterations, dt = 10 ms, 6000 steps: the top cube moves less than 1 cm.
  WorldSettings s;
  s.friction.mu0 = 0.5;
  World world(s);
  world.createBody(groundPlaneDesc());
  const std::vector<BodyId> ids = addCubeStack(world, "cube", 0, 0, 10, 2 * kHalf);
  const Vec3 start = world.body(ids.back()).pose.position;
  for (int i = 0; i < 6000; ++i) world.step();
  EXPECT_LT((world.body(ids.back()).pose.position - start).norm(), 0.01);
}

// A small pile run for `steps`; its state hash.
uint64_t pileHash(int steps) {
  World world;
  world.createBody(groundPlaneDesc());
  addCubePile(world, 18, 2 * kHalf, 3);
  for (int i = 0; i < steps; ++i) world.step();
  return world.stateHash();
}

TEST(WorldSolve, IdenticalRunsGiveIdenticalState) {
  const uint64_t first = pileHash(150);
  EXPECT_EQ(first, pileHash(150));
  EXPECT_NE(first, pileHash(149));
}

// Sub-steps: a falling cube with `substeps` 4 at dt moves exactly as with dt / 4 (semi-implicit
// Euler: the same velocity and position sums), and a cube resting on the plane stays put
// (its contact is carried along between sub-steps, so the penetration is not corrected four
// times over).
TEST(WorldSolve, SubstepsOfAFreeFallEqualSmallerSteps) {
  auto fall = [](double dt, int substeps, int steps) {
    WorldSettings s;
    s.dt = dt;
    s.substeps = substeps;
    World world(s);
    const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(kHalf), {}));
    for (int i = 0; i < steps; ++i) world.step();
    return world.body(cube);
  };
  const Body a = fall(0.01, 4, 10), b = fall(0.0025, 1, 40);
  EXPECT_NEAR(a.pose.position.z(), b.pose.position.z(), 1e-12);
  EXPECT_NEAR(a.linear_velocity.z(), b.linear_velocity.z(), 1e-12);
  // z = -g dt^2 n (n + 1) / 2 for n steps of semi-implicit Euler.
  EXPECT_NEAR(a.pose.position.z(), -kG * 0.0025 * 0.0025 * 40 * 41 / 2, 1e-12);
}

TEST(WorldSolve, SubstepsKeepARestingCubeAtRest) {
  WorldSettings s;
  s.substeps = 4;
  World world(s);
  world.createBody(groundPlaneDesc());
  const BodyId cube = world.createBody(boxDesc("cube", Vec3::Constant(kHalf), {Vec3(0, 0, kHalf)}));
  for (int i = 0; i < 200; ++i) world.step();
  EXPECT_NEAR(world.body(cube).pose.position.z(), kHalf, 1e-3);
  EXPECT_LT(world.body(cube).linear_velocity.norm(), 1e-3);
  // The contacts report the whole step's impulse: the cube's weight times dt.
  double lambda = 0.0;
  for (const Contact& c : world.contacts()) lambda += c.lambda_n;
  EXPECT_TRUE(near(lambda, kG * s.dt / world.body(cube).inverse_mass, 0.01));
}

TEST(WorldSolve, SubstepsBelowOneAreRejected) {
  WorldSettings s;
  s.substeps = 0;
  World world(s);
  EXPECT_THROW(world.step(), Error);
}

}  // namespace
}  // namespace asperity
