// The Bullet adapter's cost per contact beside the sampler's own cost per contact in a World
// (docs/engines.md; target: at most 1.2x). One scene in both engines: 30 oak-textured 0.2 m
// boxes on a stone-textured ground (gains 2, CPU sampler, one thread, patch reuse off so that
// every contact is sampled every step), resting or launched at 1 m/s in turned directions.
// Both are stepped in turn; per step the World's frames + friction stages (StepProfile) and
// the adapter's whole update (BulletFriction::lastUpdateMs: gathering Bullet's manifold
// points, ContactFriction::compute, writing frames and bounds back) are divided by their
// contacts. Counters: medians in microseconds per contact, and their ratio.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "asperity/engines/bullet_scene.hpp"
#include "asperity/world/builders.hpp"

namespace {

using namespace asperity;

constexpr int kBoxes = 30;
constexpr int kSettleSteps = 5;

Surface textured(const std::string& generator) {
  Surface s;
  s.source.generator = {generator, {}, 256, 1};
  s.gain = 2.0;
  s.texture_size = 0.25;
  return s;
}

SceneDesc boxesOnStone(bool sliding) {
  SceneDesc scene;
  scene.friction_provider = "cpu";
  scene.settings.friction.reuse_pixels = 0.0;
  BodyDesc ground = boxDesc("ground", Vec3(3, 3, 0.05), {Vec3(0, 0, -0.05), Quat::Identity()});
  ground.type = BodyType::Static;
  ground.shapes[0].surface = textured("stone");
  scene.bodies.push_back(ground);
  // A 6 x 5 grid, each box turned (and launched) a little differently.
  for (int i = 0; i < kBoxes; ++i) {
    const double angle = 0.7 * i;
    const Vec3 at(-1.5 + 0.6 * (i % 6), -1.2 + 0.6 * (i / 6), 0.1);
    BodyDesc box = boxDesc("box" + std::to_string(i), Vec3::Constant(0.1),
                           {at, Quat(Eigen::AngleAxisd(0.3 * i, Vec3::UnitZ()))});
    box.shapes[0].surface = textured("oak");
    if (sliding) box.linear_velocity = Vec3(std::cos(angle), std::sin(angle), 0.0);
    scene.bodies.push_back(box);
  }
  return scene;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// Both engines stepped alternately (same machine load); one benchmark iteration = one step.
void BM_AdapterCostPerContact(benchmark::State& state) {
  const SceneDesc scene = boxesOnStone(state.range(0) != 0);
  auto world = instantiate(scene);
  BulletScene bullet(scene);
  for (int i = 0; i < kSettleSteps; ++i) world->step(), bullet.step();
  std::vector<double> sampler_us, friction_us, adapter_us;
  double contacts = 0.0;
  for (auto _ : state) {
    world->step();
    bullet.step();
    const StepProfile& p = world->profile();
    const double n_world = std::max(1, p.contacts);
    const auto n_bullet =
        static_cast<double>(std::max<size_t>(1, bullet.friction()->lastContacts().size()));
    sampler_us.push_back(1e3 * (p.ms(Stage::Frames) + p.ms(Stage::Friction)) / n_world);
    friction_us.push_back(1e3 * p.ms(Stage::Friction) / n_world);
    adapter_us.push_back(1e3 * bullet.friction()->lastUpdateMs() / n_bullet);
    contacts += n_bullet;
  }
  state.counters["world_frames_friction_us"] = median(sampler_us);
  state.counters["world_friction_us"] = median(friction_us);
  state.counters["adapter_us"] = median(adapter_us);
  state.counters["ratio"] = median(adapter_us) / median(sampler_us);
  state.counters["bullet_contacts"] = contacts / static_cast<double>(state.iterations());
}
// Argument 0: the boxes rest on the ground; 1: they slide over it.
BENCHMARK(BM_AdapterCostPerContact)
    ->ArgName("sliding")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(200)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
