// MuJoCo's step with Asperity's friction against MuJoCo's own step, side by side in one run:
// 30 boxes launched at 1 m/s along the ridges of a sawtooth ground (engine_setups.hpp). Both
// step from the same states: kSteps consecutive states of a run with Asperity's friction,
// restored (qpos, qvel, warm start, time) before each step, so that both see the same contacts
// and consecutive samples keep their patch reuse.
//   BM_MujocoStep             mj_step alone
//   BM_MujocoAsperity/cpu     MujocoFriction::step with the CPU patch sampler
//   BM_MujocoAsperity/const   the same with the constant provider (no sampling)
// Counters per step (wall clock, from the adapter): its whole edit (edit_us),
// ContactFriction::compute (compute_us) and textured contacts. At the end, on CPU times per
// step (the machine may be shared): sampling = step(cpu) - step(const), the adapter's own cost
// = step(const) - step(MujocoStep), and the target of issue 32,
// step(cpu) <= step(MujocoStep) + 1.2 sampling (medians with --benchmark_repetitions).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "common/engine_setups.hpp"
#include "mujoco/mjcf_scene.hpp"

namespace {

using namespace asperity;

constexpr int kSkip = 5;  // steps of landing before the timed ones
constexpr int kSteps = 40;
constexpr int kBoxes = 30;

// The model and the states the timed steps start from, built once.
struct Setup {
  SceneDesc scene = engine_setups::sawtoothBoxes(kBoxes);
  mjcf_scene::MjcfScene mjcf = mjcf_scene::fromScene(scene);
  mjcf_scene::ModelPtr model = mjcf_scene::loadModel(mjcf.xml);
  mjcf_scene::DataPtr start{mj_makeData(model.get())};

  std::vector<std::vector<mjtNum>> states;  // qpos, qvel, qacc_warmstart, time

  // The states of kSteps steps with Asperity's friction, after landing.
  Setup() {
    mj_resetDataKeyframe(model.get(), start.get(), 0);
    MujocoFriction friction(model.get(), surfaces("cpu"));
    for (int i = 0; i < kSkip + kSteps; ++i) {
      if (i >= kSkip) states.push_back(save(start.get()));
      friction.step(start.get());
    }
  }
  std::vector<mjtNum> save(const mjData* d) const {
    std::vector<mjtNum> s(d->qpos, d->qpos + model->nq);
    s.insert(s.end(), d->qvel, d->qvel + model->nv);
    s.insert(s.end(), d->qacc_warmstart, d->qacc_warmstart + model->nv);
    s.push_back(d->time);
    return s;
  }
  void restore(mjData* d, const std::vector<mjtNum>& s) const {
    const mjtNum* p = s.data();
    std::copy(p, p + model->nq, d->qpos);
    std::copy(p + model->nq, p + model->nq + model->nv, d->qvel);
    std::copy(p + model->nq + model->nv, p + model->nq + 2 * model->nv, d->qacc_warmstart);
    d->time = s.back();
  }
  EngineSurfaces surfaces(const std::string& sampler) const {
    EngineSurfaces s = parseEngineSurfaces(mjcf.surfaces, scene.source_file);
    s.settings.provider = sampler;
    return s;
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

// Per-step means of the last run of each benchmark (us), for the summary.
std::map<std::string, double>& results() {
  static std::map<std::string, double> r;
  return r;
}

void BM_MujocoStep(benchmark::State& state) {
  const Setup& s = setup();
  mjcf_scene::DataPtr d(mj_makeData(s.model.get()));
  for (auto _ : state) {
    for (const auto& saved : s.states) {
      s.restore(d.get(), saved);
      mj_step(s.model.get(), d.get());
    }
  }
}

void BM_MujocoAsperity(benchmark::State& state, const std::string& sampler) {
  const Setup& s = setup();
  mjcf_scene::DataPtr d(mj_makeData(s.model.get()));
  MujocoFriction friction(s.model.get(), s.surfaces(sampler));
  double edit_ms = 0.0, compute_ms = 0.0, contacts = 0.0;
  for (auto _ : state) {
    // The adapter's own clocks split each step.
    for (const auto& saved : s.states) {
      s.restore(d.get(), saved);
      friction.step(d.get());
      edit_ms += friction.lastStats().friction_ms;
      compute_ms += friction.lastStats().compute_ms;
      contacts += friction.lastStats().textured;
    }
  }
  const double steps = static_cast<double>(state.iterations()) * kSteps;
  state.counters["edit_us"] = 1e3 * edit_ms / steps;
  state.counters["compute_us"] = 1e3 * compute_ms / steps;
  state.counters["contacts"] = contacts / steps;
  results()[sampler + " edit"] = 1e3 * edit_ms / steps;
  results()[sampler + " compute"] = 1e3 * compute_ms / steps;
}

// Records the per-step CPU time of each benchmark's last run.
class Summary : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    // With --benchmark_repetitions, the median of the repetitions (reported after them).
    for (const Run& r : runs) {
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      const std::string& args = r.run_name.args;
      results()[r.run_name.function_name + (args.empty() ? "" : "/" + args)] =
          r.GetAdjustedCPUTime() / kSteps;  // us (kMicrosecond)
    }
  }
};

BENCHMARK(BM_MujocoStep)->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_MujocoAsperity, cpu, std::string("cpu"))
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_MujocoAsperity, const, std::string("constant"))
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  Summary summary;
  benchmark::RunSpecifiedBenchmarks(&summary);
  benchmark::Shutdown();
  // The target: MuJoCo's plain step plus 1.2 times the sampling time (CPU time per step).
  auto& r = results();
  const char* keys[] = {"BM_MujocoStep", "BM_MujocoAsperity/cpu", "BM_MujocoAsperity/const"};
  for (const char* key : keys)
    if (!r.count(key)) return 0;
  const double plain = r[keys[0]], with = r[keys[1]], constant = r[keys[2]];
  const double sampling = with - constant, target = plain + 1.2 * sampling;
  std::printf(
      "CPU per step: MuJoCo %.1f us; MuJoCo + Asperity %.1f us = MuJoCo + adapter %.1f us + "
      "sampling %.1f us; target plain + 1.2 sampling = %.1f us: %s\n",
      plain, with, constant - plain, sampling, target, with <= target ? "met" : "NOT met");
  return 0;
}
