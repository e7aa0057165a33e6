// `asperity run`: the CSV's header and row count, byte-identical reruns, the hash, the stats
// file, setting overrides (checked against edited scene files), and one test per bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;
using test::slurpBinary;

const char* kHeader = "step,time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n";

std::string example(const std::string& name) {
  return test::sourcePath("scenes/examples/" + name);
}

// Lines of a text (without the final newline's empty line).
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

// The hash `asperity run` prints, or "" on failure.
std::string hashOf(const std::vector<std::string>& args) {
  const auto r = runCli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

TEST(RunCommand, CsvHeaderAndRows) {
  const std::string out = test::tempDir("run") + "/traj.csv";
  const auto r =
      runCli({"run", example("minimal.json"), "--steps", "20", "--every", "5", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = slurpBinary(out);
  EXPECT_EQ(csv.rfind(kHeader, 0), 0u);
  // Two bodies, steps 0, 5, 10, 15, 20.
  const std::vector<std::string> rows = lines(csv);
  ASSERT_EQ(rows.size(), 1u + 2u * 5u);
  EXPECT_EQ(rows[1].rfind("0,0,ground,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[2].rfind("0,0,box,0,0,0.1,1,0,0,0,1,0,0,0,0,0", 0), 0u) << rows[2];
  EXPECT_EQ(rows[9].rfind("20,", 0), 0u) << rows[9];
  for (const std::string& row : rows) EXPECT_EQ(std::count(row.begin(), row.end(), ','), 15);
}

TEST(RunCommand, SecondsGiveCeilOfTimeOverDt) {
  const std::string out = test::tempDir("run") + "/traj.csv";
  // dt = 0.01: 0.055 s is 6 steps; rows for steps 0..6 of 2 bodies.
  const auto r = runCli({"run", example("minimal.json"), "--seconds", "0.055", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines(slurpBinary(out)).size(), 1u + 2u * 7u);
}

TEST(RunCommand, RerunsAreByteIdentical) {
  const std::string dir = test::tempDir("run");
  for (const char* file : {"a.csv", "b.csv"}) {
    const auto r =
        runCli({"run", example("loads.json"), "--steps", "60", "--out", dir + "/" + file});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(slurpBinary(dir + "/a.csv"), slurpBinary(dir + "/b.csv"));
}

TEST(RunCommand, HashIsSixteenHexDigitsAndRepeats) {
  const std::string a = hashOf({"run", example("joints.json"), "--steps", "50", "--hash"});
  const std::string b = hashOf({"run", example("joints.json"), "--steps", "50", "--hash"});
  EXPECT_TRUE(std::regex_match(a, std::regex("[0-9a-f]{16}\n"))) << a;
  EXPECT_EQ(a, b);
  EXPECT_NE(a, hashOf({"run", example("joints.json"), "--steps", "51", "--hash"}));
}

TEST(RunCommand, StatsHoldPerStepAverages) {
  const std::string path = test::tempDir("run") + "/stats.json";
  const auto r = runCli({"run", example("minimal.json"), "--steps", "30", "--stats", path});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json stats = nlohmann::json::parse(slurpBinary(path));
  EXPECT_EQ(stats["steps"], 30);
  EXPECT_EQ(stats["sampler"], "cone");
  const nlohmann::json& per_step = stats["per_step"];
  for (const char* key :
       {"contacts", "fallbacks", "reused", "drivers_ms", "collide_ms", "frames_ms", "friction_ms",
        "patch_ms", "averaging_ms", "solve_ms", "solve_iterate_ms", "integrate_ms", "total_ms"})
    EXPECT_TRUE(per_step.contains(key)) << key;
  // The collision set-up before the first step, apart from the per-step means.
  EXPECT_GT(stats["prepare_ms"].get<double>(), 0.0);
  // A box resting on a plane touches it at its four bottom corners.
  EXPECT_GT(per_step["contacts"].get<double>(), 3.0);
  EXPECT_LE(per_step["contacts"].get<double>(), 4.0);
}

// The scene file with settings[key] = value, written to a temporary folder beside copies of
// nothing else (the scene must not use relative files).
std::string editedScene(const std::string& name, const std::string& key, const std::string& value) {
  nlohmann::json j = nlohmann::json::parse(slurpBinary(example(name)));
  j["settings"][key] = value;
  const std::string path = test::tempDir("run") + "/" + name;
  std::ofstream(path) << j.dump(2);
  return path;
}

TEST(RunCommand, FrictionAndFrameOverrideTheScene) {
  // settings.json uses the polygon limit and the world frame, on an anisotropic box.
  const std::string base = example("settings.json");
  const std::vector<std::string> steps = {"--steps", "40", "--hash"};
  auto run = [&](std::vector<std::string> args) {
    args.insert(args.end(), steps.begin(), steps.end());
    return hashOf(args);
  };
  const std::string polygon = run({"run", base});
  const std::string coulomb = run({"run", base, "--friction", "coulomb"});
  EXPECT_NE(polygon, coulomb);
  EXPECT_EQ(coulomb, run({"run", editedScene("settings.json", "limit_surface", "coulomb")}));
  const std::string auto_frame = run({"run", base, "--frame", "auto"});
  EXPECT_EQ(auto_frame, run({"run", editedScene("settings.json", "frame_mode", "auto")}));
  EXPECT_EQ(run({"run", base, "--sampler", "constant"}),
            run({"run", editedScene("settings.json", "friction_provider", "constant")}));
}

TEST(RunCommand, PatchSettingsOverrideTheScene) {
  // settings.json samples with the cone provider; the cpu sampler reads N, w and R.
  const std::string base = example("settings.json");
  nlohmann::json j = nlohmann::json::parse(slurpBinary(base));
  j["settings"]["friction_provider"] = "cpu";
  j["settings"]["directions"] = 12;
  j["settings"]["patch_width"] = 0.05;
  j["settings"]["patch_resolution"] = 8;
  const std::string edited = test::tempDir("run") + "/settings.json";
  std::ofstream(edited) << j.dump(2);
  const std::vector<std::string> common = {"--steps", "40", "--hash", "--sampler", "cpu"};
  auto run = [&](std::vector<std::string> args) {
    args.insert(args.end(), common.begin(), common.end());
    return hashOf(args);
  };
  const std::string overridden =
      run({"run", base, "--directions", "12", "--patch-width", "0.05", "--patch-res", "8"});
  EXPECT_EQ(overridden, run({"run", edited}));
  EXPECT_NE(overridden, run({"run", base}));
}

// --threads spreads a step over worker threads without changing a bit.
TEST(RunCommand, ThreadsDoNotChangeTheHash) {
  const std::string scene = test::sourcePath("scenes/stacking.json");
  const std::string one = hashOf({"run", scene, "--steps", "40", "--threads", "1", "--hash"});
  EXPECT_EQ(hashOf({"run", scene, "--steps", "40", "--threads", "2", "--hash"}), one);
  EXPECT_EQ(hashOf({"run", scene, "--steps", "40", "--threads", "0", "--hash"}), one);
}

TEST(RunCommand, BadValuesAreOneLineErrors) {
  const std::string scene = example("minimal.json");
  expectOneLineError(runCli({"run", scene, "--friction", "cone"}), "--friction");
  expectOneLineError(runCli({"run", scene, "--frame", "tangent"}), "--frame");
  expectOneLineError(runCli({"run", scene, "--every", "0"}), "--every");
  expectOneLineError(runCli({"run", scene, "--steps", "-1"}), "--steps");
  expectOneLineError(runCli({"run", scene, "--seconds", "nan"}), "--seconds");
  expectOneLineError(runCli({"run", scene, "--steps", "3", "--seconds", "1"}), "--seconds");
  expectOneLineError(runCli({"run", scene, "--sampler", "velvet"}), "--sampler: unknown");
  expectOneLineError(runCli({"run", scene, "--directions", "3"}), "--directions");
  expectOneLineError(runCli({"run", scene, "--directions", "65"}), "--directions");
  expectOneLineError(runCli({"run", scene, "--patch-width", "0"}), "--patch-width");
  expectOneLineError(runCli({"run", scene, "--patch-width", "nan"}), "--patch-width");
  expectOneLineError(runCli({"run", scene, "--patch-res", "0"}), "--patch-res");
  expectOneLineError(runCli({"run", scene, "--threads", "-1"}), "--threads");
  expectOneLineError(runCli({"run", scene, "--steps", "1", "--out", "/nonexistent/dir/t.csv"}),
                     "--out");
  expectOneLineError(runCli({"run"}), "SCENE");
}

// A friction setting out of range, as an option and in a scene: the words every front end
// shares (tests/sampler/friction_settings_test.cpp).
TEST(RunCommand, AFrictionSettingOutOfRangeGetsTheSharedWords) {
  const std::string words = "patch_resolution must be an integer in [1, 256], got 512";
  const std::string scene = example("minimal.json");
  expectOneLineError(runCli({"run", scene, "--patch-res", "512"}), words);
  expectOneLineError(runCli({"tribometer", "gen:concrete:1", "--patch-res", "512"}), words);
  nlohmann::json j = nlohmann::json::parse(slurpBinary(example("settings.json")));
  j["settings"]["patch_resolution"] = 512;
  const std::string path = test::tempDir("run_range") + "/settings.json";
  std::ofstream(path) << j.dump(2);
  expectOneLineError(runCli({"run", path}),
                     "/settings/patch_resolution: must be an integer in [1, 256], got 512");
}

TEST(RunCommand, ExplosionsAndDeepNestingAreOneLineErrors) {
  const std::string dir = test::tempDir("run_extreme");
  // A body launched above the speed limit stops the run at step 1, named.
  std::ofstream(dir + "/fast.json") << R"({"bodies": [{"name": "bullet",
      "linear_velocity": [0, 0, 5000], "shapes": [{"type": "sphere", "radius": 0.1}]}]})";
  expectOneLineError(runCli({"run", dir + "/fast.json", "--steps", "3"}),
                     "step 1 (t = 0.01 s): body 'bullet': speed 5e+03 m/s is above the limit");
  // 100 000 nested arrays: the depth is named (this once overflowed the stack).
  std::ofstream(dir + "/deep.json") << std::string(100000, '[') << std::string(100000, ']');
  expectOneLineError(runCli({"run", dir + "/deep.json"}),
                     "JSON nested 65 levels deep, more than the 64 allowed");
  // A spring too stiff for dt is warned about before the run.
  std::ofstream(dir + "/stiff.json") << R"({"bodies": [{"name": "b",
      "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]}],
      "springs": [{"name": "s", "body": "b", "target": [0, 0, 0], "stiffness": 1e6}],
      "settings": {"gravity": [0, 0, 0]}})";
  const auto stiff = runCli({"run", dir + "/stiff.json", "--steps", "1"});
  EXPECT_EQ(stiff.exit_code, 0) << stiff.err;
  EXPECT_NE(stiff.err.find("asperity: warning: " + dir + "/stiff.json: spring 's': period"),
            std::string::npos)
      << stiff.err;
}

// A deprecated key still runs, with one warning line on stderr naming the key to use; the hash
// is the same as with the new key.
TEST(RunCommand, DeprecatedKeysRunWithAWarning) {
  const std::string old_scene = editedScene("minimal.json", "frame", "world");
  const auto old_run = runCli({"run", old_scene, "--steps", "5", "--hash"});
  ASSERT_EQ(old_run.exit_code, 0) << old_run.err;
  EXPECT_EQ(old_run.err, "asperity: warning: " + old_scene +
                             ": /settings/frame: deprecated, use \"frame_mode\"\n");
  const auto new_run = runCli({"run", example("minimal.json"), "--steps", "5", "--hash"});
  EXPECT_EQ(new_run.err, "");
  EXPECT_EQ(old_run.out, new_run.out);
  // Both at once is an error naming the pointer.
  nlohmann::json both = nlohmann::json::parse(slurpBinary(old_scene));
  both["settings"]["frame_mode"] = "world";
  std::ofstream(old_scene) << both.dump();
  expectOneLineError(runCli({"run", old_scene, "--steps", "1"}),
                     old_scene + ": /settings/frame: deprecated name of \"frame_mode\"");
}

TEST(RunCommand, BadSceneFilesAreOneLineErrors) {
  const auto missing = runCli({"run", "/nonexistent/scene.json"});
  EXPECT_EQ(missing.exit_code, 1);
  expectOneLineError(missing, "/nonexistent/scene.json: cannot open file");
  const std::string path = test::tempDir("run") + "/bad.json";
  std::ofstream(path)
      << R"({"bodies": [{"name": "b", "shapes": [{"type": "box", "half_extents": [0.1, -0.1, 0.1]}]}]})";
  const auto bad = runCli({"run", path});
  EXPECT_EQ(bad.exit_code, 1);
  expectOneLineError(
      bad, path + ": /bodies/0/shapes/0/half_extents/1: must be a positive number, got -0.1");
}

// A glTF file that crashes the asset library itself (found by fuzzing; the fuzz input's first
// byte picks the format) ends the run with an error naming it, not with a crash.
TEST(RunCommand, AnAssetThatCrashesTheImporterIsAnError) {
  const std::string dir = test::tempDir("run_asset");
  const std::string input =
      slurpBinary(test::sourcePath("tests/fuzz/regressions/asset/gltf_assimp_segv"));
  std::ofstream(dir + "/evil.gltf", std::ios::binary) << input.substr(1);
  std::ofstream(dir + "/scene.json") << R"({"bodies": [{"name": "thing",
      "shapes": [{"type": "mesh", "file": "evil.gltf"}]}]})";
  const auto r = runCli({"run", dir + "/scene.json", "--steps", "1"});
  EXPECT_EQ(r.exit_code, 1);
  // With Debian's assimp 5.2.5: "evil.gltf: the importer crashed reading it (signal 11; ...)".
  expectOneLineError(r, "evil.gltf: ");
}

}  // namespace
}  // namespace asperity
