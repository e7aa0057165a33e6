// `asperity sweep SCENE --vary PATH=SPEC ...`: an ensemble of independent runs of one scene
// with varied numbers, on a oneTBB pool, written as one CSV row per sample (src/sweep).

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/sweep/sweep.hpp"
#include "cli_common.hpp"

namespace asperity::cli {
namespace {

struct SweepOptions {
  std::string scene;
  std::vector<std::string> vary;
  std::vector<std::string> measures;
  int64_t samples = 1;
  uint64_t seed = 1;
  int threads = 0;
  double seconds = 1.0;
  std::string out;
  bool resume = false;
};

// This command's option for each field of a sweep's description.
constexpr std::pair<SweepField, const char*> kFlags[] = {{SweepField::Vary, "--vary"},
                                                         {SweepField::Measures, "--measure"},
                                                         {SweepField::Samples, "--samples"},
                                                         {SweepField::Seconds, "--seconds"},
                                                         {SweepField::Threads, "--threads"}};

std::string flagOf(SweepField field) {
  for (const auto& [f, flag] : kFlags)
    if (f == field) return flag;
  return "sweep";
}

// The sweep the options describe, checked (paths, measures, the scene).
Sweep planSweep(const SweepOptions& opt) {
  // The scene must load as it is (the loader's message names the culprit) before varying it;
  // its warnings are printed once, not once per sample.
  for (const std::string& warning : loadScene(opt.scene).warnings) printWarning(warning);
  std::ifstream in(opt.scene);
  std::ostringstream text;
  text << in.rdbuf();
  SweepDesc desc;
  desc.scene_json = text.str();
  desc.scene_file = opt.scene;
  for (const std::string& v : opt.vary) desc.vary.push_back(parseVariation(v));
  desc.samples = opt.samples;
  desc.seed = opt.seed;
  desc.seconds = opt.seconds;
  desc.measures = opt.measures;
  return Sweep(std::move(desc));
}

void runSweep(const SweepOptions& opt) {
  try {
    const Sweep sweep = planSweep(opt);
    // Each row reaches the file as soon as it and every lower one are done; the library's
    // messages name the file, this command's name its option too.
    try {
      const int64_t ran = runSweepToFile(sweep, {opt.out, opt.threads, opt.resume});
      if (opt.resume && ran == 0)
        std::fprintf(stderr, "sweep: %s already holds all %lld samples: nothing to do\n",
                     opt.out.c_str(), static_cast<long long>(sweep.desc().samples));
    } catch (const SweepFileError& e) {
      throw Error("--out " + std::string(e.what()));
    }
  } catch (const SweepError& e) {
    // The library names the description's fields; the user wrote this command's options.
    throw Error(e.messageNaming(flagOf(e.field())));
  }
}

}  // namespace

void registerSweepCommand(CLI::App& app) {
  auto opt = std::make_shared<SweepOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep",
      "Run an ensemble of a scene with varied numbers on a pool of threads; one CSV row "
      "per sample");
  sub->add_option("SCENE", opt->scene, "Scene file (JSON, docs/scene-format.md)")->required();
  sub->add_option("--vary", opt->vary,
                  "PATH=SPEC: JSON pointer ('*' for every array element) = uniform(a,b), "
                  "normal(m,s), choice(a,b,...) or grid(a,b,n); repeatable");
  sub->add_option("--measure", opt->measures,
                  "KIND:BODY with KIND distance, speed, angle or height; repeatable");
  sub->add_option("--samples", opt->samples, "Number of samples")
      ->check(CLI::Range(int64_t{1}, int64_t{100000000}))
      ->capture_default_str();
  sub->add_option("--seed", opt->seed, "Seed; sample i of a seed is the same on any thread count")
      ->check(notNegative())
      ->capture_default_str();
  sub->add_option("--threads", opt->threads, "Threads of the pool (0 = every core)")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  sub->add_option("--seconds", opt->seconds, "Simulated time per sample (s)")
      ->check(numberInRange(0.0, 1e6))
      ->capture_default_str();
  sub->add_option("--out", opt->out, "Results CSV, written row by row as samples finish")
      ->required();
  sub->add_flag("--resume", opt->resume,
                "Continue a killed sweep from the rows --out holds (same arguments); the file "
                "ends byte-identical to an uninterrupted run's");
  sub->callback([opt] { runSweep(*opt); });
}

}  // namespace asperity::cli
