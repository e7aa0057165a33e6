// `asperity report --out DIR`: runs every experiment of Sec. 5 and writes DIR/report/index.html,
// a self-contained page (inline CSS and SVG, no scripts, no server): for each experiment what the
// paper shows, the measured outcome (pass or fail, with numbers), plots of the trajectories that
// tell it, a rendered frame when the renderer is available, and the Table 1 reproduction.
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "cli_common.hpp"
#include "experiments/experiment_outcomes.hpp"
#include "report_plot.hpp"

namespace asperity::cli {
namespace {

namespace fs = std::filesystem;
using experiments::Experiment;
using experiments::Outcome;

struct ReportOptions {
  std::string out;
  std::string scenes_dir = "scenes";
  std::string sampler;
  std::optional<int> threads;  // worker threads of each step (the scenes' when unset)
  std::vector<std::string> only;
  bool frames = true;  // when built with the renderer
};

const char* const kStyle = R"(
body{font:15px/1.5 system-ui,-apple-system,"Segoe UI",Helvetica,Arial,sans-serif;color:#1d2430;
background:#f5f6f8;margin:0}
main{max-width:1180px;margin:0 auto;padding:24px 28px 60px}
h1{font-size:26px;margin:8px 0 2px}h2{font-size:20px;margin:0 0 6px}
.sub{color:#5b6472;margin:0 0 18px}
section{background:#fff;border:1px solid #e1e4ea;border-radius:10px;padding:18px 22px;
margin:18px 0;box-shadow:0 1px 2px rgba(0,0,0,.04)}
.badge{display:inline-block;font-weight:600;font-size:13px;padding:2px 10px;border-radius:12px;
margin-left:8px;vertical-align:middle}
.pass{background:#e3f5e7;color:#1b6b32}.fail{background:#fde6e6;color:#a12121}
.claim{color:#3b4452}.expl{font-family:ui-monospace,Menlo,Consolas,monospace;font-size:13px;
background:#f3f5f8;border-radius:6px;padding:6px 10px}
table{border-collapse:collapse;font-size:13px;margin:8px 0}
th,td{border-bottom:1px solid #e8eaef;padding:4px 10px;text-align:right}
th:first-child,td:first-child{text-align:left}th{background:#f3f5f8;font-weight:600}
.paper{color:#7a8391}.plots{display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}
.plot text{font-size:11px;fill:#3b4452}.plot .title{font-size:13px;font-weight:600}
.plot .grid{stroke:#eceef2}.plot .frame{fill:none;stroke:#c5cad3}
img.frame{max-width:560px;border-radius:6px;border:1px solid #e1e4ea}
figure{margin:0}figcaption,caption{font-size:12px;color:#7a8391;text-align:left}
)";

// The measured numbers of one experiment.
std::string measuresTable(const Outcome& out) {
  std::string s = "<table><tr><th>measure</th><th>value</th><th>unit</th></tr>";
  for (const auto& m : out.measures) {
    char value[32];
    std::snprintf(value, sizeof(value), "%.4g", m.value);
    s += "<tr><td>" + htmlEscape(m.name) + "</td><td>" + value + "</td><td>" + htmlEscape(m.unit) +
         "</td></tr>";
  }
  return s + "</table>";
}

// A table an experiment made (cells already formatted).
std::string resultTable(const experiments::Table& table) {
  std::string s = "<table><caption>" + htmlEscape(table.title) + "</caption><tr>";
  for (const auto& c : table.columns) s += "<th>" + htmlEscape(c) + "</th>";
  s += "</tr>";
  for (const auto& row : table.rows) {
    s += "<tr>";
    for (const auto& c : row) s += "<td>" + htmlEscape(c) + "</td>";
    s += "</tr>";
  }
  return s + "</table>";
}

std::string cell(const char* format, double ours, const std::optional<double>& paper) {
  char a[32], b[32];
  std::snprintf(a, sizeof(a), format, ours);
  std::string s = std::string("<td>") + a;
  if (paper) {
    std::snprintf(b, sizeof(b), format, *paper);
    s += " <span class='paper'>(" + std::string(b) + ")</span>";
  }
  return s + "</td>";
}

// Table 1: one row per scene run, ours with the paper's in parentheses.
std::string tableOne(const std::vector<Experiment>& list, const std::vector<Outcome>& outcomes) {
  std::string s =
      "<table><tr><th>scene</th><th>k moving (k_A)</th><th>k fixed (k_B)</th><th>mu0</th><th>w "
      "(m)</th>"
      "<th>dt (ms)</th><th>sampler</th><th>avg contacts</th><th>dynamics total (ms)</th>"
      "<th>patch (ms)</th><th>averaging (ms)</th></tr>";
  for (size_t i = 0; i < outcomes.size(); ++i)
    for (size_t k = 0; k < outcomes[i].profiles.size() && k < list[i].scenes.size(); ++k) {
      const auto& o = outcomes[i].profiles[k];
      const auto& p = list[i].scenes[k].paper;
      auto paper = [&](double experiments::PaperRow::*field) {
        return p ? std::optional<double>((*p).*field) : std::nullopt;
      };
      const std::optional<double> contacts = p ? std::optional<double>(p->contacts) : std::nullopt;
      s += "<tr><td>" + htmlEscape(o.scene) + "</td>" +
           cell("%g", o.k_a, paper(&experiments::PaperRow::k_a)) +
           cell("%g", o.k_b, paper(&experiments::PaperRow::k_b)) +
           cell("%g", o.mu0, paper(&experiments::PaperRow::mu0)) +
           cell("%g", o.patch_width, paper(&experiments::PaperRow::w)) +
           cell("%g", o.dt * 1e3, paper(&experiments::PaperRow::dt_ms)) + "<td>" +
           htmlEscape(o.sampler) + "</td>" + cell("%.0f", o.contacts, contacts) +
           cell("%.2f", o.total_ms, paper(&experiments::PaperRow::total_ms)) +
           cell("%.2f", o.patch_ms, paper(&experiments::PaperRow::patch_ms)) +
           cell("%.2f", o.averaging_ms, paper(&experiments::PaperRow::averaging_ms)) + "</tr>";
    }
  return s + "</table>";
}

// One frame of each of the experiment's scenes (half-way through unless it says when), from
// `asperity render` (this same executable) when built with the renderer; none where rendering fails
// (no GL context): the page then goes without pictures.
std::string renderFrames(const ReportOptions& opt, const Experiment& e, const fs::path& dir) {
  std::string images;
#if ASPERITY_HAVE_RENDER
  if (!opt.frames) return "";
  for (const auto& run : e.scenes) {
    const std::string name = fs::path(run.file).stem().string() + ".png";
    const fs::path png = dir / name;
    const std::string scene = (fs::path(opt.scenes_dir) / run.file).string();
    char at[32];
    std::snprintf(at, sizeof(at), "%g", run.frame_at.value_or(run.seconds * 0.5));
    const std::string cmd = "'" + fs::read_symlink("/proc/self/exe").string() + "' render '" +
                            scene + "' --frame-at " + at + " --size 960x540 --out '" +
                            png.string() + "' > /dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0 || !fs::exists(png)) return images;
    images += "<figure><img class='frame' alt='" + htmlEscape(e.title) + "' src='" + name +
              "'><figcaption>" + htmlEscape(run.file) + " at " + at + " s</figcaption></figure>";
  }
#else
  (void)opt, (void)e, (void)dir;
#endif
  return images;
}

// Seconds as "%g" (3, 0.45), not std::to_string's "3.000000".
std::string seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", s);
  return buffer;
}

std::string experimentSection(const Experiment& e, const Outcome& out, const std::string& images) {
  std::string s = "<section id='" + e.id + "'><h2>" + htmlEscape(e.title) + "<span class='badge " +
                  (out.passed ? "pass'>reproduced" : "fail'>not reproduced") + "</span></h2>";
  s += "<p class='claim'><b>Paper.</b> " + htmlEscape(e.paper) + "</p>";
  s += "<p class='claim'><b>Tested outcome.</b> " + htmlEscape(e.expected) + "</p>";
  s += "<p class='expl'>" + htmlEscape(out.explanation) + "</p>";
  s += "<div class='plots'>";
  s += images;
  for (const auto& plot : out.plots) s += svgPlot(plot);
  s += "</div>";
  for (const auto& table : out.tables) s += resultTable(table);
  s += measuresTable(out);
  s += "<p class='sub'>Scenes:";
  for (const auto& run : e.scenes)
    s += " <code>scenes/" + htmlEscape(run.file) + "</code> (" + seconds(run.seconds) + " s)";
  return s + "</p></section>";
}

// The summary: each experiment's outcome and what was measured.
std::string summaryTable(const std::vector<Experiment>& list,
                         const std::vector<Outcome>& outcomes) {
  std::string summary = "<table><tr><th>experiment</th><th>outcome</th><th>measured</th></tr>";
  for (size_t i = 0; i < list.size(); ++i)
    summary += "<tr><td><a href='#" + list[i].id + "'>" + htmlEscape(list[i].title) +
               "</a></td><td><span class='badge " +
               (outcomes[i].passed ? "pass'>reproduced" : "fail'>not reproduced") +
               "</span></td><td style='text-align:left'>" + htmlEscape(outcomes[i].explanation) +
               "</td></tr>";
  return summary + "</table>";
}

void writeReport(const ReportOptions& opt) {
  // Every sampler of the tool ("gl" included), checked before the first experiment runs.
  const FrictionProviders providers = frictionProviders();
  checkSampler(providers, opt.sampler);
  const fs::path dir = fs::path(opt.out) / "report";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error("report: --out: cannot create \"" + dir.string() + "\": " + ec.message());
  // Which experiments, run in the paper's order.
  std::vector<Experiment> list;
  for (const Experiment& e : experiments::experimentCatalog())
    if (opt.only.empty() || std::find(opt.only.begin(), opt.only.end(), e.id) != opt.only.end())
      list.push_back(e);
  for (const std::string& id : opt.only) experiments::findExperiment(id);
  experiments::RunOptions run;
  run.scenes_dir = opt.scenes_dir;
  run.sampler = opt.sampler;
  run.threads = opt.threads;
  run.providers = providers;
  run.record_every = 2;
  std::vector<Outcome> outcomes;
  std::string sections;
  int passed = 0;
  for (const Experiment& e : list) {
    std::fprintf(stderr, "report: %s\n", e.id.c_str());
    outcomes.push_back(experiments::runExperiment(e.id, run));
    passed += outcomes.back().passed ? 1 : 0;
    sections += experimentSection(e, outcomes.back(), renderFrames(opt, e, dir));
  }
  // The page: summary, one section per experiment, Table 1.
  const std::string summary = summaryTable(list, outcomes);
  const std::string html =
      "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>Asperity: the "
      "paper's experiments</title><style>" +
      std::string(kStyle) +
      "</style></head><body><main><h1>Coupling friction with visual "
      "appearance: the experiments</h1><p class='sub'>" +
      std::to_string(passed) + " of " + std::to_string(list.size()) +
      " experiments reproduce the paper's outcome (Sec. 5, Table 1)." +
      "</p><p class='sub'>Each patch pixel reads the texel under it as one facet, as the paper "
      "builds its materials (a facet per 1 mm texel, Sec. 5.1); blending four texels before "
      "the friction law, the scene setting <code>\"texel_reading\": \"bilinear\"</code>, reads "
      "rough maps up to 40 % smoother (docs/samplers.md).</p><section><h2>Summary</h2>" +
      summary + "</section>" + sections +
      "<section id='table1'><h2>Table 1</h2><p class='sub'>Per step, averaged over each run; the "
      "paper's figures (GTX 1650, i9 2.4 GHz) in parentheses.</p>" +
      tableOne(list, outcomes) + "</section></main></body></html>\n";
  const fs::path index = dir / "index.html";
  try {
    writeFileAtomically(index.string(), html);
  } catch (const Error& e) {
    throw Error(std::string("report: ") + e.what());
  }
  std::printf("%s: %d of %zu experiments reproduced\n", index.string().c_str(), passed,
              list.size());
}

}  // namespace

void registerReportCommand(CLI::App& app) {
  auto opt = std::make_shared<ReportOptions>();
  CLI::App* sub =
      app.add_subcommand("report", "Run the paper's experiments and write DIR/report/index.html");
  sub->add_option("--out", opt->out, "Output folder (the page goes to DIR/report/)")->required();
  sub->add_option("--scenes", opt->scenes_dir, "Folder of the experiment scenes")
      ->capture_default_str();
  sub->add_option("--sampler", opt->sampler,
                  "Friction provider replacing each scene's (constant, cone, cpu, ...)");
  sub->add_option("--threads", opt->threads,
                  "Worker threads of each step (0 = every core); the outcomes do not change")
      ->check(CLI::Range(0, kMaxThreads));
  sub->add_option("--only", opt->only, "Only these experiment ids");
  sub->add_flag("--frames,!--no-frames", opt->frames,
                "One rendered frame per experiment (default, when built with the renderer)");
  sub->callback([opt] { writeReport(*opt); });
}

}  // namespace asperity::cli
