// `asperity bench [SCENES...]`: the paper's Table 1 for each scene (parameters k_A k_B mu0 w dt,
// average contacts, dynamics total per step, patch sampling and averaging times from
// StepProfile), with the paper's own figures beside ours. Without scenes: every experiment
// scene in scenes/.
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "cli_common.hpp"
#include "experiments/experiment_outcomes.hpp"

namespace asperity::cli {
namespace {

using experiments::TableRow;

struct BenchOptions {
  std::vector<std::string> scenes;
  std::string scenes_dir = "scenes";
  std::string sampler;
  std::string json;
  int threads = 1;  // > 1: each scene also runs on this many threads, side by side
};

// "ours (paper)" for one column, or just ours when the paper has no such row.
std::string pair(double ours, const std::optional<double>& paper, const char* format) {
  char a[32], b[32];
  std::snprintf(a, sizeof(a), format, ours);
  if (!paper) return a;
  std::snprintf(b, sizeof(b), format, *paper);
  return std::string(a) + " (" + b + ")";
}

void printTable(const std::vector<TableRow>& rows) {
  std::printf("%-50s %-9s %-9s %-11s %-13s %-8s %-7s %-15s %-15s %-13s %-13s %s\n", "scene",
              "k moving", "k fixed", "mu0", "w (m)", "dt (ms)", "sampler", "contacts", "total ms",
              "patch ms", "averaging ms", "prepare ms");
  for (const TableRow& r : rows) {
    const experiments::RunProfile& o = r.ours;
    const experiments::PaperRow q = r.paper.value_or(experiments::PaperRow{});
    auto paper = [&](double v) { return r.paper ? std::optional<double>(v) : std::nullopt; };
    std::printf("%-50s %-9s %-9s %-11s %-13s %-8s %-7s %-15s %-15s %-13s %-13s %.2f\n",
                r.title.c_str(), pair(o.k_a, paper(q.k_a), "%g").c_str(),
                pair(o.k_b, paper(q.k_b), "%g").c_str(), pair(o.mu0, paper(q.mu0), "%g").c_str(),
                pair(o.patch_width, paper(q.w), "%g").c_str(),
                pair(o.dt * 1e3, paper(q.dt_ms), "%g").c_str(), o.sampler.c_str(),
                pair(o.contacts, paper(q.contacts), "%.0f").c_str(),
                pair(o.total_ms, paper(q.total_ms), "%.2f").c_str(),
                pair(o.patch_ms, paper(q.patch_ms), "%.2f").c_str(),
                pair(o.averaging_ms, paper(q.averaging_ms), "%.2f").c_str(), o.prepare_ms);
  }
  std::printf(
      "(paper's Table 1 in parentheses: its k_A, k_B (not always the moving body first: the "
      "sawtooth's k_A 4 is the plane's); its timings on a GTX 1650 and an i9 at 2.4 GHz. Ours: "
      "gains of the moving and the fixed bodies' surfaces; timings on this machine, per step; "
      "prepare: the collision set-up before the first step, once)\n");
}

std::string hex(uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

// Per stage, the mean step time on 1 thread and on N, their ratio, and both state hashes
// (equal: the thread count never changes the results).
void printThreadTable(const std::vector<TableRow>& one, const std::vector<TableRow>& many,
                      int threads) {
  std::printf("\nper-stage ms per step on 1 thread / on %d threads (speed-up)\n", threads);
  std::printf("%-28s", "scene");
  for (int i = 0; i < kStageCount; ++i) std::printf(" %-22s", stageName(static_cast<Stage>(i)));
  std::printf(" %-22s %-22s %s\n", "total", "prepare (once)", "state hash (1 / N)");
  for (size_t k = 0; k < one.size(); ++k) {
    const experiments::RunProfile& a = one[k].ours;
    const experiments::RunProfile& b = many[k].ours;
    auto cell = [](double x, double y) {
      char text[64];
      std::snprintf(text, sizeof(text), "%.3f/%.3f (%.2fx)", x, y, y > 0.0 ? x / y : 0.0);
      return std::string(text);
    };
    std::printf("%-28s", a.scene.c_str());
    for (int i = 0; i < kStageCount; ++i) {
      const auto stage = static_cast<Stage>(i);
      std::printf(" %-22s", cell(a.sums.meanMs(stage), b.sums.meanMs(stage)).c_str());
    }
    std::printf(" %-22s %-22s %s %s %s\n", cell(a.total_ms, b.total_ms).c_str(),
                cell(a.prepare_ms, b.prepare_ms).c_str(), hex(a.state_hash).c_str(),
                a.state_hash == b.state_hash ? "==" : "!=", hex(b.state_hash).c_str());
  }
}

nlohmann::ordered_json rowJson(const TableRow& r) {
  const auto& o = r.ours;
  nlohmann::ordered_json j;
  j["title"] = r.title;
  j["scene"] = o.scene;
  j["ours"] = {{"k_a", o.k_a},
               {"k_b", o.k_b},
               {"mu0", o.mu0},
               {"w", o.patch_width},
               {"dt_ms", o.dt * 1e3},
               {"sampler", o.sampler},
               {"steps", o.steps},
               {"contacts", o.contacts},
               {"fallbacks", o.fallbacks},
               {"total_ms", o.total_ms},
               {"patch_ms", o.patch_ms},
               {"averaging_ms", o.averaging_ms},
               {"solve_ms", o.solve_ms},
               {"prepare_ms", o.prepare_ms},
               {"wall_s", o.wall_s},
               {"threads", o.threads},
               {"state_hash", hex(o.state_hash)}};
  if (r.paper) {
    const auto& p = *r.paper;
    j["paper"] = {{"k_a", p.k_a},
                  {"k_b", p.k_b},
                  {"mu0", p.mu0},
                  {"w", p.w},
                  {"dt_ms", p.dt_ms},
                  {"contacts", p.contacts},
                  {"total_ms", p.total_ms},
                  {"patch_ms", p.patch_ms},
                  {"averaging_ms", p.averaging_ms}};
  }
  return j;
}

void runBench(const BenchOptions& opt) {
  // Every sampler of the tool ("gl" included), checked before the first scene runs.
  const FrictionProviders providers = frictionProviders();
  checkSampler(providers, opt.sampler);
  const std::vector<std::string> scenes =
      opt.scenes.empty() ? experiments::catalogScenePaths(opt.scenes_dir) : opt.scenes;
  // One row per scene, printed as a table and optionally written as JSON.
  std::vector<TableRow> rows, threaded;
  for (const std::string& path : scenes) {
    rows.push_back(experiments::benchScene(path, opt.sampler, providers, 1));
    if (opt.threads != 1)
      threaded.push_back(experiments::benchScene(path, opt.sampler, providers, opt.threads));
  }
  printTable(rows);
  if (opt.threads != 1) printThreadTable(rows, threaded, opt.threads);
  for (const TableRow& r : threaded) rows.push_back(r);
  if (opt.json.empty()) return;
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const TableRow& r : rows) j.push_back(rowJson(r));
  try {
    writeFileAtomically(opt.json, j.dump(2) + "\n");
  } catch (const Error& e) {
    throw Error(std::string("--json ") + e.what());
  }
}

}  // namespace

void registerBenchCommand(CLI::App& app) {
  auto opt = std::make_shared<BenchOptions>();
  CLI::App* sub = app.add_subcommand(
      "bench", "The paper's Table 1: parameters, contacts and per-step timings of scenes");
  sub->add_option("SCENES", opt->scenes, "Scene files (default: every experiment in --scenes)");
  sub->add_option("--scenes", opt->scenes_dir, "Folder of the experiment scenes")
      ->capture_default_str();
  sub->add_option("--sampler", opt->sampler,
                  "Friction provider replacing each scene's (constant, cone, cpu, ...)");
  sub->add_option("--json", opt->json, "Also write the table as JSON to this file");
  sub->add_option("--threads", opt->threads,
                  "Also run each scene on N threads (0 = every core): per-stage times at 1 and N "
                  "and both state hashes")
      ->check(CLI::Range(0, kMaxThreads));
  sub->callback([opt] { runBench(*opt); });
}

}  // namespace asperity::cli
