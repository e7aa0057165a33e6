// `asperity cone`: the flat-patch limit surface against the Gaussian-slope oracle (SPEC 2:
// mu_d = (2/pi) sigma / sqrt(2 pi), about 0.254 for sigma = 1), Eq. 7's gains, the box read
// from the directions, the figures, and one test per kind of bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "cli/cli_test_support.hpp"

// stb, private to this file, to read the figure back and to write a grayscale PNG.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;

// The Gaussian-slope oracle for sigma = 1 (SPEC 2).
const double kMuSigma1 = (2.0 / 3.14159265358979323846) / std::sqrt(2.0 * 3.14159265358979323846);

// Two isotropic Gaussian textures (sigma = 1, different seeds) and a sawtooth along v, made
// once with the CLI itself.
class ConeCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::tempDir("cone"));
    makeTexture({"gaussian", "--sx", "1", "--sy", "1", "--seed", "1"}, b());
    makeTexture({"gaussian", "--sx", "1", "--sy", "1", "--seed", "2"}, a());
    makeTexture({"sawtooth", "--axis", "90", "--period", "16"}, saw());
  }
  static void TearDownTestSuite() { delete dir_; }
  static void makeTexture(std::vector<std::string> args, const std::string& out) {
    args.insert(args.begin(), "texture");
    for (const char* s : {"--size", "256", "--out"}) args.push_back(s);
    args.push_back(out);
    const auto r = runCli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static std::string b() { return *dir_ + "/b.png"; }
  static std::string a() { return *dir_ + "/a.png"; }
  static std::string saw() { return *dir_ + "/saw.png"; }

  // Runs `cone ... --json` and returns the parsed output.
  static nlohmann::json coneJson(std::vector<std::string> args) {
    args.insert(args.begin(), "cone");
    args.push_back("--json");
    const auto r = runCli(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
  static std::vector<double> mus(const nlohmann::json& j) {
    std::vector<double> v;
    for (const auto& d : j.at("directions")) v.push_back(d.at("mu").get<double>());
    return v;
  }

  static std::string* dir_;
};
std::string* ConeCommand::dir_ = nullptr;

TEST_F(ConeCommand, BothGaussianSurfacesGiveTwiceTheOracleInEveryDirection) {
  const auto j = coneJson({b(), "--a", a()});
  ASSERT_EQ(j.at("directions").size(), 16u);
  for (size_t k = 0; k < 16; ++k) {
    const auto& d = j.at("directions")[k];
    EXPECT_DOUBLE_EQ(d.at("angle_deg").get<double>(), 22.5 * static_cast<double>(k));
    EXPECT_TRUE(test::near(d.at("mu").get<double>(), 2.0 * kMuSigma1, 0.03)) << "k = " << k;
  }
}

TEST_F(ConeCommand, FlatAGivesTheOracle) {
  for (double mu : mus(coneJson({b()}))) EXPECT_TRUE(test::near(mu, kMuSigma1, 0.03));
}

TEST_F(ConeCommand, GainsAndMu0FollowEq7) {
  const std::vector<double> mu_b = mus(coneJson({b()}));
  const std::vector<double> mu_a = mus(coneJson({b(), "--a", a(), "--k-b", "0"}));
  // mu = mu0 + k_b mubar_B (flat A).
  const std::vector<double> scaled = mus(coneJson({b(), "--mu0", "0.3", "--k-b", "2"}));
  // mu = mu0 + k_a mubar_A + k_b mubar_B (Eq. 7).
  const std::vector<double> both =
      mus(coneJson({b(), "--a", a(), "--mu0", "0.1", "--k-a", "3", "--k-b", "0.5"}));
  ASSERT_EQ(scaled.size(), 16u);
  for (size_t k = 0; k < 16; ++k) {
    EXPECT_TRUE(test::near(scaled[k], 0.3 + 2.0 * mu_b[k], 1e-5)) << k;
    EXPECT_TRUE(test::near(both[k], 0.1 + 3.0 * mu_a[k] + 0.5 * mu_b[k], 1e-5)) << k;
  }
}

TEST_F(ConeCommand, BoxReadsDirectionsZeroFourEightTwelve) {
  const auto j = coneJson({saw(), "--a", a()});
  const std::vector<double> mu = mus(j);
  const auto& box = j.at("box");
  EXPECT_DOUBLE_EQ(box.at("+t").get<double>(), mu[0]);
  EXPECT_DOUBLE_EQ(box.at("+b").get<double>(), mu[4]);
  EXPECT_DOUBLE_EQ(box.at("-t").get<double>(), mu[8]);
  EXPECT_DOUBLE_EQ(box.at("-b").get<double>(), mu[12]);
  // Key order as documented: directions first, box keys +t, +b, -t, -b.
  const auto r = runCli({"cone", saw(), "--json"});
  EXPECT_LT(r.out.find("\"directions\""), r.out.find("\"box\""));
  EXPECT_LT(r.out.find("\"+t\""), r.out.find("\"+b\""));
  EXPECT_LT(r.out.find("\"+b\""), r.out.find("\"-t\""));
  EXPECT_LT(r.out.find("\"-t\""), r.out.find("\"-b\""));
}

TEST_F(ConeCommand, DirectionCountSetsTheSamples) {
  const auto j = coneJson({b(), "--directions", "6"});
  ASSERT_EQ(j.at("directions").size(), 6u);
  EXPECT_DOUBLE_EQ(j.at("directions")[1].at("angle_deg").get<double>(), 60.0);
}

TEST_F(ConeCommand, SawtoothIsAsymmetricAndDirectXSwapsB) {
  // Ramps rise toward +v = +b: the steep faces resist one sense of b far more than the other.
  const auto gl = coneJson({saw()});
  const auto dx = coneJson({saw(), "--directx"});
  const double pos_b = gl.at("box").at("+b").get<double>();
  const double neg_b = gl.at("box").at("-b").get<double>();
  EXPECT_GT(std::max(pos_b, neg_b), 2.0 * std::min(pos_b, neg_b));
  // Across the ridges (along t) nothing resists (up to 8-bit quantisation of the normals).
  EXPECT_LT(gl.at("box").at("+t").get<double>(), 0.02);
  EXPECT_LT(gl.at("box").at("-t").get<double>(), 0.02);
  // Read as DirectX, green flips: +b and -b swap.
  EXPECT_TRUE(test::near(dx.at("box").at("+b").get<double>(), neg_b, 0.02, 1e-4));
  EXPECT_TRUE(test::near(dx.at("box").at("-b").get<double>(), pos_b, 0.02, 1e-4));
}

TEST_F(ConeCommand, TableListsDirectionsAndBox) {
  const auto r = runCli({"cone", b(), "--a", a(), "--directions", "8"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("angle_deg"), std::string::npos);
  EXPECT_NE(r.out.find("  315.00"), std::string::npos);
  EXPECT_NE(r.out.find("box: +t "), std::string::npos);
}

TEST_F(ConeCommand, WritesNonTrivialSvgAndPng) {
  const std::string dir = test::tempDir("plot");
  const auto r =
      runCli({"cone", b(), "--a", a(), "--svg", dir + "/c.svg", "--png", dir + "/c.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = test::slurpBinary(dir + "/c.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_GT(svg.size(), 10000u);
  // The PNG loads, has the documented size, and is not blank: many distinct colours.
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load((dir + "/c.png").c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, 900);
  EXPECT_EQ(h, 420);
  std::set<uint32_t> colours;
  for (int i = 0; i < w * h; ++i)
    colours.insert(
        static_cast<uint32_t>(pixels[3 * i] << 16 | pixels[3 * i + 1] << 8 | pixels[3 * i + 2]));
  stbi_image_free(pixels);
  EXPECT_GT(colours.size(), 500u);
}

TEST_F(ConeCommand, MissingFileIsNamed) {
  expectOneLineError(runCli({"cone", *dir_ + "/missing.png"}), "missing.png");
  expectOneLineError(runCli({"cone", b(), "--a", *dir_ + "/missing_a.png"}), "missing_a.png");
}

TEST_F(ConeCommand, CorruptPngIsNamed) {
  const std::string path = test::tempDir("bad") + "/corrupt.png";
  std::ofstream(path, std::ios::binary) << "\x89PNG\r\n\x1a\n this is not a png";
  expectOneLineError(runCli({"cone", path}), "corrupt.png");
}

TEST_F(ConeCommand, GrayscalePngIsNamed) {
  const std::string path = test::tempDir("bad") + "/gray.png";
  const std::vector<unsigned char> gray(16 * 16, 128);
  ASSERT_NE(stbi_write_png(path.c_str(), 16, 16, 1, gray.data(), 16), 0);
  expectOneLineError(runCli({"cone", path}), "gray.png");
}

TEST_F(ConeCommand, BadNumbersAreNamed) {
  for (const char* v : {"nan", "-1", "3", "65", "inf", "x"})
    expectOneLineError(runCli({"cone", b(), "--directions", v}), "--directions");
  for (const char* v : {"nan", "-1", "0", "1e9", "inf"})
    expectOneLineError(runCli({"cone", b(), "--mu-max", v}), "--mu-max");
  for (const char* v : {"nan", "-1", "1e9", "-inf"}) {
    expectOneLineError(runCli({"cone", b(), "--k-a", v}), "--k-a");
    expectOneLineError(runCli({"cone", b(), "--k-b", v}), "--k-b");
    expectOneLineError(runCli({"cone", b(), "--mu0", v}), "--mu0");
  }
}

TEST_F(ConeCommand, UnwritableFiguresAreNamed) {
  const std::string dir = test::tempDir("bad") + "/no/such/folder";
  expectOneLineError(runCli({"cone", b(), "--svg", dir + "/c.svg"}), dir + "/c.svg");
  expectOneLineError(runCli({"cone", b(), "--png", dir + "/c.png"}), dir + "/c.png");
}

}  // namespace
}  // namespace asperity
