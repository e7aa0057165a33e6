// `asperity contact-area` and the height-map side of `asperity texture` (SPEC 13): the JSON the
// issue asks for, its numbers against the library, repeated loads, the contact map, and one
// test per kind of bad input (non-zero exit, one stderr line naming the culprit).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/contact_area/mechanical.hpp"
#include "asperity/texture/generator_heights.hpp"
#include "asperity/texture/height_map.hpp"
#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;

// A generator's heights written by the CLI; returns the file.
std::string heightsFile(const std::string& dir, const std::string& generator, double size) {
  const std::string file = dir + "/" + generator + ".png";
  const auto r = runCli({"texture", generator, "--size", "128", "--texture-size",
                         std::to_string(size), "--height", file});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // The scale is printed as well as stored.
  EXPECT_NE(r.out.find("height_scale"), std::string::npos) << r.out;
  return file;
}

TEST(ContactAreaCommand, JsonMatchesTheLibrary) {
  const std::string dir = test::tempDir("contact");
  const std::string b = heightsFile(dir, "plaster", 0.032);
  const std::string a = heightsFile(dir, "stone", 0.032);
  for (const char* load : {"50", "5000"}) {
    const auto r = runCli({"contact-area", b, "--a", a, "--texture-size", "0.032", "--load", load,
                           "--modulus", "3e9", "--hardness", "2e8", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (const char* key :
         {"load", "real_area", "apparent_area", "fraction", "mean_pressure", "plasticity_index"})
      EXPECT_TRUE(j.contains(key)) << key;
    const HeightMap hb = loadHeightMapPng(b), ha = loadHeightMapPng(a);
    const ContactArea lib = solveContact(findSummits(hb, &ha, 0.032), {3e9, 2e8}, std::stod(load));
    EXPECT_DOUBLE_EQ(j["real_area"].get<double>(), lib.real_area);
    EXPECT_DOUBLE_EQ(j["apparent_area"].get<double>(), 0.032 * 0.032);
    EXPECT_DOUBLE_EQ(j["fraction"].get<double>(), lib.fraction);
    EXPECT_NEAR(j["mean_pressure"].get<double>(), std::stod(load) / lib.real_area, 1e-6);
    EXPECT_GT(j["plasticity_index"].get<double>(), 0.0);
  }
}

TEST(ContactAreaCommand, SeveralLoadsGiveAnArrayAndAMapPanelEach) {
  const std::string dir = test::tempDir("contact");
  const std::string b = heightsFile(dir, "plaster", 0.032);
  const auto r = runCli({"contact-area", b, "--texture-size", "0.032", "--modulus", "3e9", "--load",
                         "100", "--load", "1000", "--json", "--map", dir + "/map.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_LT(j[0]["real_area"].get<double>(), j[1]["real_area"].get<double>());
  EXPECT_TRUE(j[0]["plasticity_index"].is_null());  // no hardness given
  // Two 128-texel panels and a 4-texel gap, grey.
  const std::string png = test::slurpBinary(dir + "/map.png");
  ASSERT_GT(png.size(), 26u);
  EXPECT_EQ(static_cast<unsigned char>(png[19]), 4 + 2 * 128 - 256);  // width 260, low byte
  EXPECT_EQ(static_cast<unsigned char>(png[25]), 0);                  // grey
}

TEST(ContactAreaCommand, MaterialsGiveThePairAndTheAdhesionTerm) {
  const std::string dir = test::tempDir("contact");
  const std::string b = heightsFile(dir, "plaster", 0.032);
  const auto r = runCli({"contact-area", b, "--texture-size", "0.032", "--load", "300",
                         "--material-b", "steel", "--material-a", "pvc", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const Mechanical &pvc = findMechanical("pvc"), &steel = findMechanical("steel");
  const ContactArea lib =
      solveContact(findSummits(loadHeightMapPng(b), nullptr, 0.032), contactPair(pvc, steel), 300);
  EXPECT_DOUBLE_EQ(j["real_area"].get<double>(), lib.real_area);
  EXPECT_DOUBLE_EQ(j["adhesion_mu"].get<double>(), pvc.shear * lib.real_area / 300.0);
  expectOneLineError(runCli({"contact-area", b, "--texture-size", "0.032", "--load", "1",
                             "--material-b", "marble"}),
                     "marble");
  expectOneLineError(runCli({"contact-area", b, "--texture-size", "0.032", "--load", "1"}),
                     "--modulus");
}

TEST(ContactAreaCommand, BadInputIsOneLineAndNonZero) {
  const std::string dir = test::tempDir("contact");
  const std::string b = heightsFile(dir, "plaster", 0.032);
  const auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"contact-area", b,    "--texture-size", "0.032",
                                     "--load",       "10", "--modulus",      "1e9"};
    for (std::string& e : extra) args.push_back(std::move(e));
    return runCli(args);
  };
  expectOneLineError(runCli({"contact-area", dir + "/none.png", "--texture-size", "0.03", "--load",
                             "1", "--modulus", "1e9"}),
                     "none.png");
  expectOneLineError(run({"--load", "-5"}), "load");
  expectOneLineError(run({"--modulus", "0"}), "modulus");
  expectOneLineError(run({"--hardness", "-1"}), "hardness");
  // A patch past a kilometre (its areas leave a double's range) and a zero scale.
  expectOneLineError(
      runCli({"contact-area", b, "--texture-size", "1e300", "--load", "10", "--modulus", "1e9"}),
      "--texture-size");
  expectOneLineError(run({"--height-scale", "0"}), "--height-scale");
  // A normal map (RGB) is no height map.
  const auto normals = runCli({"texture", "plaster", "--size", "16", "--out", dir + "/n.png"});
  ASSERT_EQ(normals.exit_code, 0) << normals.err;
  expectOneLineError(run({"--a", dir + "/n.png"}), "greyscale");
}

TEST(TextureCommand, HeightMapsAreInspectedAtPhysicalScale) {
  const std::string dir = test::tempDir("contact");
  const std::string file = heightsFile(dir, "oak", 0.1);
  const auto r = runCli({"texture", "inspect", file, "--texture-size", "0.1", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const HeightStats s = heightStats(loadHeightMapPng(file), 0.1);
  EXPECT_DOUBLE_EQ(j["rq"].get<double>(), s.rq);
  EXPECT_DOUBLE_EQ(j["ra"].get<double>(), s.ra);
  EXPECT_DOUBLE_EQ(j["correlation_length"].get<double>(), s.correlation_length);
  // oak's rms slope is its `slope` parameter (0.25) by construction.
  EXPECT_NEAR(j["rms_slope"].get<double>(), 0.25, 0.01);
  expectOneLineError(runCli({"texture", "gaussian", "--height", dir + "/g.png"}), "gaussian");
}

}  // namespace
}  // namespace asperity
