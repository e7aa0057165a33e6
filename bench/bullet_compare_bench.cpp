// Asperity against Bullet's btDiscreteDynamicsWorld on the same scene: three stacks of ten
// 0.2 m cubes on a plane, dt = 10 ms, 20 iterations, isotropic mu = 0.5 (Asperity: Coulomb
// limit with ConstantProvider mu0 = 0.5; Bullet: two friction directions per contact, no
// sleeping, friction 0.5 combined). Both worlds first settle for 1 s, then each step is timed;
// counters give the median step time. BM_StacksRatio runs both and reports their ratio. A run
// whose stacks fall is reported as an error: a stack stands while its top cube stays within
// half a cube (0.1 m) of where it started (Bullet's stacks sway by a few centimetres; ours
// by millimetres; both drifts are reported).
#include <benchmark/benchmark.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "asperity/sampler/constant_provider.hpp"
#include "asperity/world/builders.hpp"
#include "asperity/world/world.hpp"

namespace {

using namespace asperity;
using Clock = std::chrono::steady_clock;

constexpr int kStacks = 3;
constexpr int kHeight = 10;
constexpr double kSize = 0.2;
constexpr double kDt = 0.01;
constexpr double kMu = 0.5;
constexpr int kSettleSteps = 100;
constexpr double kStandingDrift = 0.5 * kSize;

double stackX(int s) {
  return (s - 1) * 0.6;
}

// The Asperity scene.
struct AsperityStacks {
  std::unique_ptr<World> world;
  std::vector<BodyId> tops;
  std::vector<Vec3> top_start;

  AsperityStacks() {
    WorldSettings s;
    s.dt = kDt;
    s.iterations = 20;
    s.limit_surface = LimitSurfaceKind::Coulomb;
    s.friction.mu0 = kMu;
    world = std::make_unique<World>(s);
    world->setFrictionProvider(std::make_unique<ConstantProvider>());
    world->createBody(groundPlaneDesc());
    for (int k = 0; k < kStacks; ++k) {
      std::string prefix = "stack";
      prefix += std::to_string(k);
      const auto ids = addCubeStack(*world, prefix, stackX(k), 0.0, kHeight, kSize);
      tops.push_back(ids.back());
      top_start.push_back(world->body(ids.back()).pose.position);
    }
  }
  void step() { world->step(); }
  // Largest displacement of a top cube since the start (m).
  double topDrift() const {
    double worst = 0.0;
    for (size_t i = 0; i < tops.size(); ++i) {
      worst = std::max(worst, (world->body(tops[i]).pose.position - top_start[i]).norm());
    }
    return worst;
  }
};

// The Bullet scene, set up fairly: same sizes and masses, 20 iterations, two friction
// directions, no deactivation, friction 0.5 after Bullet's product combination.
struct BulletStacks {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btStaticPlaneShape plane{btVector3(0, 0, 1), 0};
  btBoxShape box{btVector3(0.1f, 0.1f, 0.1f)};
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  std::vector<btRigidBody*> tops;
  std::vector<btVector3> top_start;

  btRigidBody* add(btCollisionShape* shape, double mass, const btVector3& position) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    btTransform t;
    t.setIdentity();
    t.setOrigin(position);
    states.push_back(std::make_unique<btDefaultMotionState>(t));
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), states.back().get(),
                                                  shape, inertia);
    // sqrt(0.5)^2 = 0.5: Bullet multiplies the two bodies' friction coefficients.
    info.m_friction = static_cast<btScalar>(std::sqrt(kMu));
    bodies.push_back(std::make_unique<btRigidBody>(info));
    bodies.back()->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(bodies.back().get());
    return bodies.back().get();
  }

  BulletStacks() {
    world.setGravity(btVector3(0, 0, -9.81f));
    world.getSolverInfo().m_numIterations = 20;
    world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    add(&plane, 0.0, btVector3(0, 0, 0));
    const double mass = 1000.0 * kSize * kSize * kSize;
    for (int k = 0; k < kStacks; ++k) {
      btRigidBody* top = nullptr;
      for (int i = 0; i < kHeight; ++i) {
        const btVector3 p(static_cast<btScalar>(stackX(k)), 0,
                          static_cast<btScalar>(0.5 * kSize + i * kSize));
        top = add(&box, mass, p);
      }
      tops.push_back(top);
      top_start.push_back(top->getWorldTransform().getOrigin());
    }
  }
  ~BulletStacks() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
  }
  void step() { world.stepSimulation(static_cast<btScalar>(kDt), 1, static_cast<btScalar>(kDt)); }
  double topDrift() const {
    double worst = 0.0;
    for (size_t i = 0; i < tops.size(); ++i) {
      worst = std::max(
          worst,
          static_cast<double>((tops[i]->getWorldTransform().getOrigin() - top_start[i]).length()));
    }
    return worst;
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// Settles, then times every step (manual time); reports the median and checks the stacks.
template <class Scene>
void runStacks(benchmark::State& state) {
  Scene scene;
  for (int i = 0; i < kSettleSteps; ++i) scene.step();
  std::vector<double> times;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    scene.step();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    state.SetIterationTime(seconds);
    times.push_back(seconds);
  }
  state.counters["median_us"] = median(times) * 1e6;
  state.counters["top_drift_mm"] = scene.topDrift() * 1e3;
  if (scene.topDrift() > kStandingDrift) state.SkipWithError("a stack fell");
}

void BM_AsperityStacks(benchmark::State& state) {
  runStacks<AsperityStacks>(state);
}
void BM_BulletStacks(benchmark::State& state) {
  runStacks<BulletStacks>(state);
}
BENCHMARK(BM_AsperityStacks)->UseManualTime()->Iterations(2000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BulletStacks)->UseManualTime()->Iterations(2000)->Unit(benchmark::kMicrosecond);

// Both scenes stepped alternately (same machine load), median of each and their ratio.
void BM_StacksRatio(benchmark::State& state) {
  AsperityStacks ours;
  BulletStacks bullet;
  for (int i = 0; i < kSettleSteps; ++i) {
    ours.step();
    bullet.step();
  }
  std::vector<double> t_ours, t_bullet;
  for (auto _ : state) {
    Clock::time_point start = Clock::now();
    ours.step();
    t_ours.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    start = Clock::now();
    bullet.step();
    t_bullet.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    state.SetIterationTime(t_ours.back() + t_bullet.back());
  }
  const double m_ours = median(t_ours), m_bullet = median(t_bullet);
  state.counters["asperity_us"] = m_ours * 1e6;
  state.counters["bullet_us"] = m_bullet * 1e6;
  state.counters["ratio"] = m_ours / m_bullet;  // < 1: Asperity is faster
  state.counters["asperity_drift_mm"] = ours.topDrift() * 1e3;
  state.counters["bullet_drift_mm"] = bullet.topDrift() * 1e3;
  if (ours.topDrift() > kStandingDrift) state.SkipWithError("an Asperity stack fell");
  if (bullet.topDrift() > kStandingDrift) state.SkipWithError("a Bullet stack fell");
}
BENCHMARK(BM_StacksRatio)->UseManualTime()->Iterations(2000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
