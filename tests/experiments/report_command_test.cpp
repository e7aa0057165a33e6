// `asperity report` and `asperity bench` (apps/cli/report_command.cpp, bench_command.cpp): the
// page and the table they write, and their errors. The experiments' physics is tested in
// experiment_outcomes_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/test_support.hpp"

namespace asperity {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ReportCommand, WritesAPageWithOutcomePlotsAndTableOne) {
  const std::string dir = test::tempDir("report");
  const auto r = test::runCli({"report", "--out", dir, "--only", "sawtooth_plane", "--no-frames",
                               "--scenes", test::sourcePath("scenes")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = readFile(dir + "/report/index.html");
  EXPECT_NE(html.find("<!DOCTYPE html>"), std::string::npos);
  EXPECT_NE(html.find("id='sawtooth_plane'"), std::string::npos);
  EXPECT_NE(html.find("reproduced"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("<polyline"), std::string::npos);
  // Table 1 with the paper's own dynamics total for the sawtooth plane (2.7 ms).
  EXPECT_NE(html.find("id='table1'"), std::string::npos);
  EXPECT_NE(html.find("(2.70)"), std::string::npos);
  // Self-contained: no scripts, no external style sheets.
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(r.out.find("1 of 1 experiments reproduced"), std::string::npos) << r.out;
}

// The whole report, as `asperity report` writes it: every experiment reproduces with the
// default settings and every scene's frame is rendered (stacking_forward's frame once hung
// Mesa's llvmpipe: renderer_test.cpp, EdgeOnNormalMappedFaceDrawsPromptly).
TEST(ReportCommand, EveryExperimentReproducesWithItsFrames) {
  const std::string dir = test::tempDir("report_all");
  const auto r = test::runCli({"report", "--out", dir, "--scenes", test::sourcePath("scenes")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("8 of 8 experiments reproduced"), std::string::npos) << r.out;
  for (const char* frame :
       {"boxes_on_materials", "sawtooth_plane", "sawtooth_plane_rotated", "stacking",
        "stacking_forward", "crawling_worm", "crawling_worm_reversed", "chain_bolas_rough",
        "chain_bolas_smooth", "tumbling_bunnies", "nut_bolt", "nut_bolt_push"}) {
    std::error_code missing;
    const auto bytes = std::filesystem::file_size(dir + "/report/" + frame + ".png", missing);
    EXPECT_TRUE(!missing && bytes > 1000) << frame;
  }
  // The chain bolas' hold map: held and fallen throws as dots, the rods' sampled mu as lines.
  const std::string html = readFile(dir + "/report/index.html");
  EXPECT_NE(html.find("Hold map"), std::string::npos);
  EXPECT_NE(html.find("<circle"), std::string::npos);
  EXPECT_NE(html.find("the rods' sampled mu"), std::string::npos);
}

TEST(ReportCommand, UnknownExperimentIsAnErrorListingTheKnownOnes) {
  const auto r =
      test::runCli({"report", "--out", test::tempDir("report_bad"), "--only", "boxes_on_marbles"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("boxes_on_marbles"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("boxes_on_materials"), std::string::npos) << r.err;
}

TEST(BenchCommand, JsonHoldsOursBesideThePapersRow) {
  const std::string json = test::tempDir("bench") + "/table.json";
  const auto r =
      test::runCli({"bench", test::sourcePath("scenes/sawtooth_plane.json"), "--json", json});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readFile(json));
  ASSERT_EQ(j.size(), 1u);
  const auto& row = j[0];
  // The scene's own parameters: moving box gain 1, plane gain 4, mu0 0.2, w 0.02, dt 10 ms.
  EXPECT_EQ(row["ours"]["k_a"].get<double>(), 1.0);
  EXPECT_EQ(row["ours"]["k_b"].get<double>(), 4.0);
  EXPECT_EQ(row["ours"]["mu0"].get<double>(), 0.2);
  EXPECT_EQ(row["ours"]["w"].get<double>(), 0.02);
  EXPECT_NEAR(row["ours"]["dt_ms"].get<double>(), 10.0, 1e-9);
  EXPECT_EQ(row["ours"]["steps"].get<int>(), 300);
  EXPECT_GT(row["ours"]["contacts"].get<double>(), 0.0);
  // The paper's Table 1 row: 4 contacts, 2.7 ms total.
  EXPECT_EQ(row["paper"]["contacts"].get<int>(), 4);
  EXPECT_EQ(row["paper"]["total_ms"].get<double>(), 2.7);
}

TEST(BenchCommand, MissingSceneIsAnErrorNamingTheFile) {
  const auto r = test::runCli({"bench", "no_such_scene.json"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no_such_scene.json"), std::string::npos) << r.err;
}

TEST(BenchCommand, UnknownSamplerIsAnErrorListingTheKnownOnes) {
  const auto r = test::runCli(
      {"bench", test::sourcePath("scenes/sawtooth_plane.json"), "--sampler", "velvet"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--sampler: unknown friction sampler \"velvet\""), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("cpu"), std::string::npos) << r.err;
}

#ifdef ASPERITY_HAVE_GL
TEST(BenchCommand, OpenGlSamplerRunsTheScene) {
  // Every subcommand offers "gl": the row says which sampler ran and found the box's contacts.
  const std::string json = test::tempDir("bench_gl") + "/table.json";
  const auto r = test::runCli(
      {"bench", test::sourcePath("scenes/sawtooth_plane.json"), "--sampler", "gl", "--json", json});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readFile(json));
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["ours"]["sampler"], "gl");
  EXPECT_GT(j[0]["ours"]["contacts"].get<double>(), 0.0);
  EXPECT_GT(j[0]["ours"]["patch_ms"].get<double>(), 0.0);
}

TEST(ReportCommand, OpenGlSamplerRunsTheExperiments) {
  const std::string dir = test::tempDir("report_gl");
  const auto r = test::runCli({"report", "--out", dir, "--only", "sawtooth_plane", "--no-frames",
                               "--scenes", test::sourcePath("scenes"), "--sampler", "gl"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = readFile(dir + "/report/index.html");
  EXPECT_NE(html.find("<td>gl</td>"), std::string::npos);
  EXPECT_NE(r.out.find("1 of 1 experiments reproduced"), std::string::npos) << r.out;
}
#endif

}  // namespace
}  // namespace asperity
