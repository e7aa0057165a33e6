// The friction settings' one range per field (asperity/sampler/friction_settings.hpp): its
// words, and the same words from every C++ front end that takes the settings (a scene, an
// engine surfaces file, ContactFriction, the CPU sampler). The command line's and Python's
// are checked in tests/cli/run_command_test.cpp and python/tests/test_scene_texture.py.
#include "asperity/sampler/friction_settings.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/engines/engine_surfaces.hpp"
#include "asperity/error.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/scene.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

// Every front end names the field (files by its JSON pointer) and says this of it.
constexpr const char* kWords = "must be an integer in [1, 256], got 512";

TEST(FrictionSettings, RangesDescribeThemselves) {
  EXPECT_EQ(friction_range::patch_resolution.describe(), "an integer in [1, 256]");
  EXPECT_EQ(friction_range::mu_max.describe(), "a number in (0, 1000]");
  EXPECT_EQ(friction_range::patch_width.describe(), "a number in [1e-06, 100]");
  EXPECT_EQ(friction_range::reuse_pixels.describe(), "a finite number >= 0");
  EXPECT_EQ(friction_range::directions.check(64), "");
  EXPECT_EQ(friction_range::directions.check(65), "must be an integer in [4, 64], got 65");
  EXPECT_EQ(friction_range::directions.check(4.5), "must be an integer in [4, 64], got 4.5");
  EXPECT_EQ(friction_range::mu_max.check(0.0), "must be a number in (0, 1000], got 0");
  EXPECT_EQ(friction_range::reuse_pixels.check(std::nan("")),
            "must be a finite number >= 0, got nan");
}

TEST(FrictionSettings, DefaultsAreValidAndEachFieldIsNamed) {
  EXPECT_FALSE(firstInvalidSetting(FrictionSettings{}).has_value());
  const auto named = [](auto edit) {
    FrictionSettings s;
    edit(s);
    const auto bad = firstInvalidSetting(s);
    return bad ? bad->field : std::string();
  };
  EXPECT_EQ(named([](FrictionSettings& s) { s.directions = 3; }), "directions");
  EXPECT_EQ(named([](FrictionSettings& s) { s.mu0 = -0.1; }), "mu0");
  EXPECT_EQ(named([](FrictionSettings& s) { s.mu_max = 0.0f; }), "mu_max");
  EXPECT_EQ(named([](FrictionSettings& s) { s.patch_width = 1e-7; }), "patch_width");
  EXPECT_EQ(named([](FrictionSettings& s) { s.patch_resolution = 0; }), "patch_resolution");
  EXPECT_EQ(named([](FrictionSettings& s) { s.reuse_pixels = -1.0; }), "reuse_pixels");
}

// One value out of range, given to each front end in its own form.
TEST(FrictionSettings, EveryFrontEndRefusesAValueWithTheSameWords) {
  const auto contains = [](const std::string& message) {
    const bool named = message.find("patch_resolution") != std::string::npos;
    return named && message.find(kWords) != std::string::npos
               ? testing::AssertionSuccess()
               : testing::AssertionFailure() << message;
  };
  // A scene file's settings.
  const nlohmann::json scene = {{"settings", {{"patch_resolution", 512}}}};
  EXPECT_TRUE(contains(test::errorOf([&] { parseScene(scene, "s.json"); })));
  // An engine adapter's surfaces file.
  const nlohmann::json surfaces = {{"settings", {{"patch_resolution", 512}}},
                                   {"surfaces", nlohmann::json::object()}};
  EXPECT_TRUE(contains(test::errorOf([&] { parseEngineSurfaces(surfaces, "e.json"); })));
  // ContactFriction in code.
  ContactFrictionSettings engine;
  engine.friction.patch_resolution = 512;
  EXPECT_TRUE(contains(test::errorOf([&] { ContactFriction friction(engine); })));
  // A sampler handed the settings directly.
  FrictionSettings settings;
  settings.patch_resolution = 512;
  EXPECT_TRUE(contains(test::errorOf([&] { validate(settings, "cpu sampler"); })));
  CpuPatchSampler sampler;
  std::vector<Contact> none;
  EXPECT_TRUE(contains(test::errorOf([&] { sampler.computeCoefficients({}, none, settings); })));
}

}  // namespace
}  // namespace asperity
