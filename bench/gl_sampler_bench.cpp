// The OpenGL patch sampler per contact (SPEC 3) on this machine's OpenGL (llvmpipe without a
// GPU): boxes resting on a textured plane, four corner contacts each, N = 4 and 16, R = 16, a
// 1024 x 1024 RGBA8 atlas (2048 contacts per pass). Counters: time per contact, and the
// provider's own split into patch (collect + render + read-back) and averaging.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "asperity/sampler/gl_patch_sampler.hpp"
#include "asperity/texture/generators.hpp"

namespace asperity {
namespace {

std::shared_ptr<const NormalMap> material(const std::string& name) {
  GeneratorSpec spec;
  spec.name = name;
  spec.size = 256;
  return std::make_shared<NormalMap>(generateNormalMap(spec));
}

struct Scene {
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

// A textured plane and `count` contacts at the corners of 0.2 m boxes (phi = 0.1 mm).
Scene boxesOnPlane(int count) {
  Scene scene;
  Body plane;
  plane.type = BodyType::Static;
  Shape ground;
  ground.type = ShapeType::Plane;
  ground.surface.normal_map = material("stone");
  ground.surface.gain = 2.0;
  plane.shapes.push_back(ground);
  scene.bodies.push_back(plane);
  const auto oak = material("oak");
  for (int i = 0; i < (count + 3) / 4; ++i) {
    Body b;
    b.pose.position = Vec3(0.3 * (i % 100), 0.3 * (i / 100), 0.1 - 1e-4);
    b.pose.rotation = Quat(Eigen::AngleAxisd(0.1 * i, Vec3::UnitZ()));
    Shape s;
    s.type = ShapeType::Box;
    s.half_extents = Vec3(0.1, 0.1, 0.1);
    s.surface.normal_map = oak;
    s.surface.gain = 2.0;
    b.shapes.push_back(s);
    scene.bodies.push_back(b);
    for (int k = 0; k < 4 && static_cast<int>(scene.contacts.size()) < count; ++k) {
      Contact c;
      c.body_a = static_cast<BodyId>(i + 1);
      c.body_b = 0;
      c.shape_a = c.shape_b = 0;
      c.point =
          b.pose.apply(Vec3(k & 1 ? 0.1 : -0.1, k & 2 ? 0.1 : -0.1, -0.1)) + Vec3(0, 0, 0.5e-4);
      c.phi = 1e-4;
      scene.contacts.push_back(c);
    }
  }
  return scene;
}

void BM_GlBoxOnPlane(benchmark::State& state) {
  Scene scene = boxesOnPlane(static_cast<int>(state.range(1)));
  GlPatchSampler sampler;
  FrictionSettings settings;
  settings.directions = static_cast<int>(state.range(0));
  sampler.computeCoefficients(scene.bodies, scene.contacts, settings);  // uploads textures
  double patch = 0.0, averaging = 0.0;
  for (auto _ : state) {
    sampler.computeCoefficients(scene.bodies, scene.contacts, settings);
    patch += sampler.lastPatchTimeMs();
    averaging += sampler.lastAveragingTimeMs();
  }
  const auto contacts = static_cast<double>(scene.contacts.size());
  const auto iterations = static_cast<double>(state.iterations());
  state.counters["per_contact"] = benchmark::Counter(
      contacts, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["patch_ms"] = patch / iterations;
  state.counters["averaging_ms"] = averaging / iterations;
  state.SetLabel(sampler.renderer());
}
BENCHMARK(BM_GlBoxOnPlane)
    ->ArgNames({"N", "contacts"})
    ->Args({4, 100})
    ->Args({4, 1000})
    ->Args({16, 1000})
    ->Args({4, 4000})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace asperity

BENCHMARK_MAIN();
