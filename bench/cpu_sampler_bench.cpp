// The CPU patch sampler per contact (SPEC 3): boxes resting on a textured plane (four corner
// contacts each, a quarter of every patch covered by both surfaces) at N = 4 and 16, R = 16,
// from 10 to 10 000 contacts, each pixel reading its nearest texel or a bilinear blend of four
// (FrictionSettings::texel_reading); and the Stanford
// bunny (glmark2's OBJ through loadObjMesh, all 69 666 triangles or simplified to 2000,
// planar-projected, 1 mm deep) on the plane. Counter `per_contact` is the time per contact.
// BM_SceneContacts samples the contacts that three scenes' worlds meet over their first 2 s
// (every 10th step), each freshly (no reuse): the mix of faces, tilts, footprints and
// textures the sampler meets inside a step, and the number a step's fresh contacts cost.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/geometry/mesh_io.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "sampler_bench_scene.hpp"

namespace asperity {
namespace {

void run(benchmark::State& state, bench::SamplerScene& scene, int n,
         const FrictionModelSettings& models = {}, TexelReading reading = TexelReading::Nearest) {
  CpuPatchSampler sampler;
  sampler.setFrictionModels(models);
  FrictionSettings settings;
  settings.directions = n;
  settings.texel_reading = reading;
  settings.patch_resolution = 16;
  settings.patch_width = 0.02;
  sampler.computeCoefficients(scene.bodies, scene.contacts, settings);  // builds mesh BVHs
  for (auto _ : state) {
    sampler.computeCoefficients(scene.bodies, scene.contacts, settings);
    benchmark::DoNotOptimize(scene.contacts.data());
  }
  const auto contacts = static_cast<double>(scene.contacts.size());
  state.counters["per_contact"] = benchmark::Counter(
      contacts, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  double covered = 0.0;
  for (const Contact& c : scene.contacts) covered += c.covered_pixels;
  state.counters["mean_covered"] = covered / contacts;
}

void BM_BoxOnPlane(benchmark::State& state) {
  bench::SamplerScene scene = bench::boxesOnPlane(static_cast<int>(state.range(1)));
  run(state, scene, static_cast<int>(state.range(0)), {},
      state.range(2) != 0 ? TexelReading::Bilinear : TexelReading::Nearest);
}
// bilinear 1: the blended reading, for comparison.
BENCHMARK(BM_BoxOnPlane)
    ->ArgNames({"N", "contacts", "bilinear"})
    ->Args({4, 1000, 0})
    ->Args({4, 1000, 1})
    ->Args({16, 1000, 0})
    ->Args({16, 1000, 1})
    ->Args({4, 10, 0})
    ->Args({4, 100, 0})
    ->Args({4, 10000, 0});

// The same boxes under the contact-area model (SPEC 13): the plane's and boxes' heights from
// their generators, steel on oak, each contact loaded with 20 N (its previous impulse).
void BM_BoxOnPlaneContactArea(benchmark::State& state) {
  bench::SamplerScene scene = bench::boxesOnPlane(static_cast<int>(state.range(1)));
  FrictionModelSettings models;
  models.model = FrictionModel::ContactArea;
  models.dt = 0.01;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    for (Shape& shape : scene.bodies[i].shapes) {
      shape.surface.source.generator.name = i == 0 ? "stone" : "oak";
      shape.surface.source.generator.size = 256;
      shape.surface.mechanical = findMechanical(i == 0 ? "steel" : "oak");
    }
  }
  for (Contact& c : scene.contacts) c.lambda_n = 20.0 * models.dt;
  run(state, scene, static_cast<int>(state.range(0)), models);
}
BENCHMARK(BM_BoxOnPlaneContactArea)->ArgNames({"N", "contacts"})->Args({4, 1000})->Args({16, 1000});

// The bunny through the project's OBJ loader (0.1 scale, about 0.2 m), simplified to
// `triangles` (0 keeps all 69 666, as the sampler sees an unsimplified scene mesh).
std::shared_ptr<const TriangleMeshData> bunnyMesh(int triangles) {
  std::shared_ptr<TriangleMeshData> mesh = loadObjMesh("/usr/share/glmark2/models/bunny.obj", 0.1);
  if (triangles > 0) mesh = simplifyMesh(*mesh, static_cast<size_t>(triangles));
  return mesh;
}

void BM_BunnyOnPlane(benchmark::State& state) {
  // The bunny resting on the plane, one contact at each of its lowest vertices.
  std::shared_ptr<const TriangleMeshData> mesh;
  try {
    mesh = bunnyMesh(static_cast<int>(state.range(1)));
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  bench::SamplerScene scene;
  scene.bodies.push_back(bench::texturedPlane());
  Body bunny;
  Shape s;
  s.type = ShapeType::TriangleMesh;
  s.mesh = mesh;
  s.surface.normal_map = bench::material("plastic");
  bunny.shapes.push_back(s);
  // The OBJ is y-up: turned +90 degrees about x (as the scenes' euler_deg [90, 0, 0]), then
  // sunk 1 mm into the plane; a contact at each of the 16 lowest vertices (phi = its depth,
  // point halfway between it and the plane).
  bunny.pose.rotation = Quat(Eigen::AngleAxisd(0.5 * kPi, Vec3::UnitX()));
  std::vector<Vec3> low;
  for (const Vec3& v : mesh->vertices) low.push_back(bunny.pose.rotation * v);
  std::sort(low.begin(), low.end(), [](const Vec3& a, const Vec3& b) { return a.z() < b.z(); });
  bunny.pose.position = Vec3(0, 0, -low.front().z() - 1e-3);
  scene.bodies.push_back(bunny);
  for (size_t i = 0; i < 16 && i < low.size(); ++i) {
    const Vec3 v = low[i] + bunny.pose.position;
    if (v.z() >= 0.0) break;
    Contact c;
    c.body_a = 1;
    c.body_b = 0;
    c.shape_a = c.shape_b = 0;
    c.point = Vec3(v.x(), v.y(), 0.5 * v.z());
    c.phi = -v.z();
    scene.contacts.push_back(c);
  }
  run(state, scene, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_BunnyOnPlane)->ArgNames({"N", "triangles"})->Args({4, 0})->Args({4, 2000});

// A world's bodies and contacts after one of its steps.
struct Snapshot {
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
};

const char* const kScenes[] = {"stacking.json", "examples/oak_stacks.json",
                               "boxes_on_materials.json"};

// Snapshots of every 10th step of the scene's first 200 steps, and the scene's settings.
std::vector<Snapshot> sceneSnapshots(const std::string& name, FrictionSettings& settings) {
  const SceneDesc scene = loadScene(std::string(ASPERITY_SOURCE_DIR) + "/scenes/" + name);
  InstantiateOptions options;
  std::unique_ptr<World> world = instantiate(scene, options);
  settings = world->settings().friction;
  std::vector<Snapshot> snapshots;
  for (int step = 1; step <= 200; ++step) {
    world->step();
    if (step % 10 != 0) continue;
    const std::span<const Body> bodies = world->bodies();
    snapshots.push_back({std::vector<Body>(bodies.begin(), bodies.end()), world->contacts()});
  }
  return snapshots;
}

void BM_SceneContacts(benchmark::State& state) {
  FrictionSettings settings;
  std::vector<Snapshot> snapshots;
  try {
    snapshots = sceneSnapshots(kScenes[state.range(0)], settings);
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  settings.reuse_pixels = 0.0;  // every contact sampled afresh
  settings.texel_reading = state.range(1) != 0 ? TexelReading::Bilinear : TexelReading::Nearest;
  CpuPatchSampler sampler;
  size_t contacts = 0;
  for (Snapshot& s : snapshots) {  // builds the mesh BVHs, outside the timing
    sampler.computeCoefficients(s.bodies, s.contacts, settings);
    contacts += s.contacts.size();
  }
  for (auto _ : state) {
    for (Snapshot& s : snapshots) sampler.computeCoefficients(s.bodies, s.contacts, settings);
    benchmark::DoNotOptimize(snapshots.data());
  }
  state.counters["per_contact"] = benchmark::Counter(
      static_cast<double>(contacts),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetLabel(kScenes[state.range(0)]);
}
// scene: 0 stacking, 1 oak_stacks, 2 boxes_on_materials; bilinear: the blended reading.
BENCHMARK(BM_SceneContacts)->ArgNames({"scene", "bilinear"})->ArgsProduct({{0, 1, 2}, {0, 1}});

}  // namespace
}  // namespace asperity

BENCHMARK_MAIN();
