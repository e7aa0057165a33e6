// Scenes that pick the contact-area friction model ("friction_model": "contact_area") and give
// their materials mechanical values (docs/contact-area.md, docs/scene-format.md).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity {
namespace {

// A plaster box sliding on a concrete plane, both materials with mechanical values.
nlohmann::json sceneJson(int threads = 1) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "settings": {"dt": 0.01, "friction_provider": "cpu", "friction_model": "contact_area"},
    "materials": {
      "concrete": {"normal_map": {"generator": "concrete", "size": 128, "seed": 1},
                   "texture_size": 0.128, "gain": 2, "mechanical": "concrete"},
      "plaster": {"normal_map": {"generator": "plaster", "size": 64, "seed": 4},
                  "texture_size": 0.032, "gain": 2,
                  "mechanical": {"E": 10e9, "nu": 0.2, "H": 0.3e9, "tau": 0.05e9}}
    },
    "bodies": [
      {"name": "ground", "type": "static", "shapes": [{"type": "plane", "surface": "concrete"}]},
      {"name": "box", "position": [0, 0, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1], "surface": "plaster"}]}
    ]
  })");
  j["settings"]["threads"] = threads;
  return j;
}

std::string errorOf(const nlohmann::json& json) {
  try {
    instantiate(parseScene(json, "s.json"));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ContactAreaScene, ReadsTheModelAndTheMechanicalValuesAndWritesThemBack) {
  const SceneDesc scene = parseScene(sceneJson(), "s.json");
  EXPECT_EQ(scene.friction_model, FrictionModel::ContactArea);
  ASSERT_TRUE(scene.materials.at("concrete").mechanical.has_value());
  EXPECT_EQ(scene.materials.at("concrete").mechanical->hardness, findMechanical("concrete").hardness);
  EXPECT_EQ(scene.materials.at("plaster").mechanical->shear, 0.05e9);
  const nlohmann::json out = sceneToJson(scene);
  EXPECT_EQ(out["settings"]["friction_model"], "contact_area");
  EXPECT_EQ(out["materials"]["concrete"]["mechanical"], "concrete");
  EXPECT_EQ(out["materials"]["plaster"]["mechanical"]["H"], 0.3e9);
  const SceneDesc again = parseScene(out, "s.json");
  EXPECT_EQ(again.materials.at("plaster").mechanical->modulus, 10e9);
  EXPECT_EQ(parseScene(nlohmann::json::object(), "e.json").friction_model, FrictionModel::Paper);
}

// The box slows down under the area model's friction at the rate its contacts' mu gives,
// the same bits on one thread or two.
TEST(ContactAreaScene, BoxSlowsTheSameOnOneThreadOrTwo) {
  const auto one = instantiate(parseScene(sceneJson(1), "s.json"));
  const auto two = instantiate(parseScene(sceneJson(2), "s.json"));
  // The friction the box feels: its contacts' mu against the motion weighted by their normal
  // impulses, over the steps (few summits touch, so mu varies from contact to contact).
  double friction = 0.0, normal = 0.0;
  for (int i = 0; i < 10; ++i) {
    one->step();
    two->step();
    for (const Contact& c : one->contacts()) {
      friction += c.mu.mu[2] * c.lambda_n;
      normal += c.lambda_n;
    }
  }
  ASSERT_GT(normal, 0.0);
  const double mu = friction / normal;
  EXPECT_EQ(one->stateHash(), two->stateHash());
  // Sliding along +x, t = +x: the friction on the box acts along -x, direction 2 of 4.
  const double slowed = (1.0 - one->bodies()[1].linear_velocity.x()) / (0.1 * 9.81);
  std::printf("contact-area box: mu %.3f, deceleration / g %.3f\n", mu, slowed);
  EXPECT_GT(mu, 0.05);
  EXPECT_LT(mu, 2.0);
  EXPECT_NEAR(slowed, mu, 0.15 * mu);
}

TEST(ContactAreaScene, BadInputIsAClearError) {
  nlohmann::json unknown = sceneJson();
  unknown["settings"]["friction_model"] = "bowden";
  std::string what;
  try {
    parseScene(unknown, "s.json");
  } catch (const Error& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("friction_model"), std::string::npos) << what;
  EXPECT_NE(what.find("contact_area"), std::string::npos) << what;

  nlohmann::json bare = sceneJson();
  bare["materials"]["concrete"].erase("mechanical");
  what = errorOf(bare);
  EXPECT_NE(what.find("/bodies/0/shapes/0/surface"), std::string::npos) << what;
  EXPECT_NE(what.find("material \"concrete\" has none"), std::string::npos) << what;

  nlohmann::json cone = sceneJson();
  cone["settings"]["friction_provider"] = "cone";
  what = errorOf(cone);
  EXPECT_NE(what.find("contact_area needs friction_provider \"cpu\""), std::string::npos) << what;

  nlohmann::json preset = sceneJson();
  preset["materials"]["concrete"]["mechanical"] = "granite";
  what = errorOf(preset);
  EXPECT_NE(what.find("unknown mechanical preset \"granite\""), std::string::npos) << what;
}

}  // namespace
}  // namespace asperity
