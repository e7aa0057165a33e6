// Physics oracles for the collide -> friction -> solve stages on hand-built worlds (a static
// plane and boxes): stick/slip on an incline, asymmetric friction bounds, sliding distances,
// stacking, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

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

// A cube launched along a static slab (a box, so Bullet's box-box manifold), at the
// experiments' 10 ms steps: it slides several breaking thresholds a step. It keeps its four
// corners in contact every step, does not rock, and stops at v^2 / (2 mu g), over a spread of
// speeds, yaws and directions.
TEST(WorldSolve, ACubeSlidingOnASlabKeepsItsFourCornersAndStopsAtVSquaredOverTwoMuG) {
  constexpr double kMu = 0.3;
  for (const double speed : {0.5, 1.0, 2.0, 3.0})
    for (const double yaw : {0.0, 0.4})
      for (const double heading : {0.0, 0.3}) {
        WorldSettings s;
        s.dt = 0.01;
        s.limit_surface = LimitSurfaceKind::Coulomb;
        s.friction.mu0 = kMu;
        World world(s);
        BodyDesc slab =
            boxDesc("slab", Vec3(3.0, 3.0, 0.05), {Vec3(0, 0, -0.05), Quat::Identity()});
        slab.type = BodyType::Static;
        world.createBody(slab);
        const Quat turn(Eigen::AngleAxisd(yaw, Vec3::UnitZ()));
        BodyDesc d = boxDesc("cube", Vec3::Constant(kHalf), {Vec3(-1.5, 0, kHalf), turn});
        d.linear_velocity = speed * Vec3(std::cos(heading), std::sin(heading), 0.0);
        const BodyId cube = world.createBody(d);
        const std::string where = "v " + std::to_string(speed) + ", yaw " + std::to_string(yaw) +
                                  ", heading " + std::to_string(heading);
        int fewer = 0;
        double most_spin = 0.0;
        for (int i = 0; i < 150; ++i) {
          world.step();
          if (i < 2 || world.body(cube).linear_velocity.norm() < 0.05) continue;
          fewer += world.contacts().size() < 4;
          most_spin = std::max(most_spin, world.body(cube).angular_velocity.norm());
        }
        EXPECT_EQ(fewer, 0) << where << ": steps sliding on fewer than four corners";
        EXPECT_LT(most_spin, 0.05) << where << ": rad/s";
        const double travel = (world.body(cube).pose.position - Vec3(-1.5, 0, kHalf)).norm();
        // Within 3 %, or a step's travel at the start (the discretised stop of a short slide).
        EXPECT_TRUE(near(travel, speed * speed / (2 * kMu * kG), 0.03, speed * s.dt)) << where;
      }
}

TEST(WorldSolve, StackOfTenStandsForAMinute) {
  // 20 iterations, dt = 10 ms, 6000 steps, over a spread of friction: the top cube creeps by
  // about 1 cm (a twentieth of a cube) in the minute; a stack that falls moves it by metres.
  for (const double mu : {0.3, 0.5, 0.8}) {
    WorldSettings s;
    s.friction.mu0 = mu;
    World world(s);
    world.createBody(groundPlaneDesc());
    const std::vector<BodyId> ids = addCubeStack(world, "cube", 0, 0, 10, 2 * kHalf);
    const Vec3 start = world.body(ids.back()).pose.position;
    for (int i = 0; i < 6000; ++i) world.step();
    const double moved = (world.body(ids.back()).pose.position - start).norm();
    EXPECT_LT(moved, 0.02) << "mu0 = " << mu;
  }
}

// A small pile run for `steps`; its state hash.
uint64_t pileHash(int steps) {
  World world;
  world.createBody(groundPlaneDesc());
  addCubePile(world, 18, 2 * kHalf, 3);
  for (int i = 0; i < steps; ++i) world.step();
  return world.stateHash();
}

// A shape `speed` m/s toward the ground plane (dt 10 ms, 1 m per step at 100 m/s), along
// `direction`, from 0.5 m above it; returns the lowest and the final height of its centre
// over 2 s. Speculative plane contacts must stop it at the surface.
std::pair<double, double> fallOntoPlane(const Shape& shape, double rest_height, double speed,
                                        const Vec3& direction) {
  World world;
  world.createBody(groundPlaneDesc());
  BodyDesc desc;
  desc.name = "fast";
  desc.pose.position = Vec3(0, 0, rest_height + 0.5);
  desc.linear_velocity = speed * direction.normalized();
  desc.shapes = {shape};
  const BodyId id = world.createBody(desc);
  double lowest = desc.pose.position.z();
  for (int i = 0; i < 200; ++i) {
    world.step();
    lowest = std::min(lowest, world.body(id).pose.position.z());
  }
  return {lowest, world.body(id).pose.position.z()};
}

TEST(WorldSolve, FastShapesDoNotTunnelThroughAPlane) {
  // Box, sphere and capsule (lying down) at 10 and 100 m/s, straight down and at 45 degrees:
  // the centre never drops below its resting height by more than 1 cm, and ends resting.
  Shape box;
  box.type = ShapeType::Box;
  box.half_extents = Vec3::Constant(kHalf);
  Shape sphere;
  sphere.type = ShapeType::Sphere;
  sphere.radius = kHalf;
  Shape capsule;
  capsule.type = ShapeType::Capsule;
  capsule.radius = 0.05;
  capsule.half_height = 0.1;
  capsule.local.rotation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()));
  const std::pair<Shape, double> cases[] = {{box, kHalf}, {sphere, kHalf}, {capsule, 0.05}};
  for (const auto& [shape, rest] : cases) {
    for (const double speed : {10.0, 100.0}) {
      for (const Vec3& dir : {Vec3(0, 0, -1), Vec3(1, 0, -1)}) {
        const auto [lowest, last] = fallOntoPlane(shape, rest, speed, dir);
        SCOPED_TRACE("shape " + std::to_string(static_cast<int>(shape.type)) + " at " +
                     std::to_string(speed) + " m/s");
        EXPECT_GT(lowest, rest - 0.01);
        EXPECT_NEAR(last, rest, 0.01);
      }
    }
  }
}

// A fast body thrown along +x (no gravity) at a static obstacle whose near side is at x = 0:
// how far past that side its leading face got over 100 steps (m; <= 0 when it never passed).
double farthestPastObstacle(const Shape& moving, double lead, double speed, double dt,
                            const Shape& obstacle, double obstacle_x) {
  WorldSettings s;
  s.dt = dt;
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDesc wall;
  wall.name = "obstacle";
  wall.type = BodyType::Static;
  wall.pose.position = Vec3(obstacle_x, 0, 0);
  wall.shapes = {obstacle};
  world.createBody(wall);
  BodyDesc desc;
  desc.name = "fast";
  desc.pose.position = Vec3(-lead - 0.3, 0, 0);
  desc.linear_velocity = Vec3(speed, 0, 0);
  desc.shapes = {moving};
  const BodyId id = world.createBody(desc);
  double farthest = -1.0;
  for (int i = 0; i < 100; ++i) {
    world.step();
    farthest = std::max(farthest, world.body(id).pose.position.x() + lead);
  }
  return farthest;
}

TEST(WorldSolve, FastShapesDoNotTunnelThroughAThinWall) {
  // Box, sphere and capsule at 10 and 100 m/s (up to 1 m per 10 ms step) against a static box
  // wall 1 cm thick: they stop at its face, never beyond its far side.
  Shape wall;
  wall.type = ShapeType::Box;
  wall.half_extents = Vec3(0.005, 1.0, 1.0);
  Shape box;
  box.type = ShapeType::Box;
  box.half_extents = Vec3::Constant(0.05);
  Shape sphere;
  sphere.type = ShapeType::Sphere;
  sphere.radius = 0.05;
  Shape capsule;  // along x, its end cap leading
  capsule.type = ShapeType::Capsule;
  capsule.radius = 0.02;
  capsule.half_height = 0.05;
  capsule.local.rotation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()));
  const std::pair<Shape, double> cases[] = {{box, 0.05}, {sphere, 0.05}, {capsule, 0.07}};
  for (const auto& [shape, lead] : cases) {
    for (const double speed : {10.0, 100.0}) {
      SCOPED_TRACE("shape " + std::to_string(static_cast<int>(shape.type)) + " at " +
                   std::to_string(speed) + " m/s");
      EXPECT_LT(farthestPastObstacle(shape, lead, speed, 0.01, wall, 0.005), 0.005);
    }
  }
}

TEST(WorldSolve, FastChainLinkDoesNotTunnelThroughARod) {
  // A flat 5 mm chain link (5 x 40 x 25 mm, thin side leading) at 10 m/s against a static rod
  // 2 cm across, at dt 1 ms (1 cm per step) and 10 ms (10 cm per step): it never gets past
  // the rod's axis.
  Shape link;
  link.type = ShapeType::Box;
  link.half_extents = Vec3(0.0025, 0.02, 0.0125);
  Shape rod;  // along y
  rod.type = ShapeType::Cylinder;
  rod.radius = 0.01;
  rod.half_height = 0.4;
  rod.local.rotation = Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()));
  for (const double dt : {0.001, 0.01}) {
    SCOPED_TRACE("dt " + std::to_string(dt));
    EXPECT_LT(farthestPastObstacle(link, 0.0025, 10.0, dt, rod, 0.01), 0.01);
  }
}

TEST(WorldSolve, BodyBelowAPlaneIsPushedOut) {
  // A plane is a half-space: a cube found wholly 0.5 m under the ground comes back up.
  World world;
  world.createBody(groundPlaneDesc());
  const BodyId cube =
      world.createBody(boxDesc("cube", Vec3::Constant(kHalf), Transform{Vec3(0, 0, -0.5)}));
  for (int i = 0; i < 200; ++i) world.step();
  EXPECT_NEAR(world.body(cube).pose.position.z(), kHalf, 0.01);
}

TEST(WorldSolve, IdenticalRunsGiveIdenticalState) {
  const uint64_t first = pileHash(150);
  EXPECT_EQ(first, pileHash(150));
  EXPECT_NE(first, pileHash(149));
}

// FixedProvider's coefficients, written only when the world finishes the call (as a GPU
// sampler's arrive): a world that read them before would solve with the wrong bounds.
class DeferredProvider : public FrictionProvider {
 public:
  explicit DeferredProvider(DirectionalMu mu) : fixed_(mu) {}
  std::string name() const override { return "deferred"; }
  bool runsAsynchronously() const override { return true; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override {
    fixed_.computeCoefficients(bodies, contacts, settings);
  }
  void startCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                         const FrictionSettings& settings) override {
    EXPECT_TRUE(contacts_.empty()) << "started twice";
    for (Contact& c : contacts) c.mu = DirectionalMu::uniform(4, 0.0f);  // not there yet
    bodies_ = bodies, contacts_ = contacts, settings_ = settings;
    ++starts;
  }
  void finishCoefficients() override {
    fixed_.computeCoefficients(bodies_, contacts_, settings_);
    contacts_ = {};
  }
  int starts = 0;

 private:
  FixedProvider fixed_;
  std::span<const Body> bodies_;
  std::span<Contact> contacts_;
  FrictionSettings settings_;
};

TEST(WorldSolve, AsynchronousProviderGivesTheBitsOfOneCall) {
  // A pile settling on asymmetric friction, the provider's work split in start and finish
  // (the solver's rows set up in between) and in one call: the same state, bit for bit.
  const DirectionalMu mu = box4(0.2f, 0.3f, 0.4f, 0.5f);
  auto run = [&](std::unique_ptr<FrictionProvider> provider) {
    World world;
    FrictionProvider& used = *provider;
    world.setFrictionProvider(std::move(provider));
    world.createBody(groundPlaneDesc());
    addCubePile(world, 18, 2 * kHalf, 3);
    int steps_with_contacts = 0;
    for (int i = 0; i < 120; ++i) {
      world.step();
      steps_with_contacts += !world.contacts().empty();
    }
    if (auto* deferred = dynamic_cast<DeferredProvider*>(&used)) {
      EXPECT_EQ(deferred->starts, steps_with_contacts);
      EXPECT_GT(steps_with_contacts, 100);
    }
    return world.stateHash();
  };
  EXPECT_EQ(run(std::make_unique<DeferredProvider>(mu)), run(std::make_unique<FixedProvider>(mu)));
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
