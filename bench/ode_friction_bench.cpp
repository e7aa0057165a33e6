// ODE's step with Asperity's friction against ODE's own step, side by side in one run: the
// 30 sliding boxes of mujoco_friction_bench.cpp (engine_setups.hpp) in ODE. Both step from the
// same states: kSteps consecutive states of a run with Asperity's friction, restored (bodies'
// poses and velocities, ODE's random seed) before each step.
//   BM_OdeStep               collision, contact joints and dWorldQuickStep
//   BM_OdeAsperity/cpu       the same with OdeFriction and the CPU patch sampler
//   BM_OdeAsperity/const     the same with the constant provider (no sampling)
// Counters per step (wall clock, from the adapter): OdeFriction::finish (edit_us),
// ContactFriction::compute (compute_us) and textured contacts. On CPU times: sampling =
// step(cpu) - step(const), the adapter's own cost = step(const) - step(OdeStep).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "common/engine_setups.hpp"
#include "ode/ode_scene.hpp"

namespace {

using namespace asperity;

constexpr int kSkip = 5;  // steps of landing before the timed ones
constexpr int kSteps = 40;

// The scene and the states the timed steps start from, built once.
struct Setup {
  SceneDesc scene = engine_setups::sawtoothBoxes(30);
  std::vector<std::vector<double>> states;

  Setup() {
    ode_scene::OdeScene ode(scene);
    auto friction = make("cpu");
    ode.registerGeoms(*friction);
    for (int i = 0; i < kSkip + kSteps; ++i) {
      if (i >= kSkip) states.push_back(ode.state());
      ode.step(friction.get());
    }
  }
  std::unique_ptr<OdeFriction> make(const std::string& sampler) const {
    EngineSurfaces s = parseEngineSurfaces(engine_setups::surfacesFile(scene), scene.source_file);
    s.settings.provider = sampler;
    return std::make_unique<OdeFriction>(s);
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

// Steps from each recorded state; with `sampler` empty, ODE's own friction.
void BM_Ode(benchmark::State& state, const std::string& sampler) {
  const Setup& s = setup();
  ode_scene::OdeScene ode(s.scene);
  std::unique_ptr<OdeFriction> friction;
  if (!sampler.empty()) friction = s.make(sampler);
  if (friction) ode.registerGeoms(*friction);
  double edit_ms = 0.0, compute_ms = 0.0, contacts = 0.0;
  for (auto _ : state) {
    for (const auto& saved : s.states) {
      ode.restore(saved);
      dRandSetSeed(0);
      ode.step(friction.get());
      if (!friction) continue;
      edit_ms += friction->lastStats().friction_ms;
      compute_ms += friction->lastStats().compute_ms;
      contacts += friction->lastStats().textured;
    }
  }
  // Per step, from the adapter's own clocks.
  const double steps = static_cast<double>(state.iterations()) * kSteps;
  state.counters["edit_us"] = 1e3 * edit_ms / steps;
  state.counters["compute_us"] = 1e3 * compute_ms / steps;
  state.counters["contacts"] = contacts / steps;
}

BENCHMARK_CAPTURE(BM_Ode, Step, std::string())->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Ode, Asperity_cpu, std::string("cpu"))
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Ode, Asperity_const, std::string("constant"))
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
