// Scenes that pick the contact-area friction model ("friction_model": "contact_area") and give
// their materials mechanical values (docs/contact-area.md, docs/scene-format.md).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <vector>

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
  EXPECT_EQ(scene.materials.at("concrete").mechanical->hardness,
            findMechanical("concrete").hardness);
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
  EXPECT_NE(what.find("/settings/friction_model: friction model contact_area reads the fragments "
                      "of each patch: it needs a patch sampler (\"cpu\" or \"gl\"), not the "
                      "\"cone\" provider"),
            std::string::npos)
      << what;

  nlohmann::json preset = sceneJson();
  preset["materials"]["concrete"]["mechanical"] = "granite";
  what = errorOf(preset);
  EXPECT_NE(what.find("unknown mechanical preset \"granite\""), std::string::npos) << what;
}

// A concrete ground with two boxes far apart: a plaster box (the pair concrete / plaster picks
// the contact-area model) and an oak box (no pair: the scene's model). Every material has
// mechanical values, so that the same scene runs under either model alone.
nlohmann::json pairsJson(const std::string& scene_model, bool with_pair) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "settings": {"dt": 0.01, "friction_provider": "cpu"},
    "materials": {
      "concrete": {"normal_map": {"generator": "concrete", "size": 128, "seed": 1},
                   "texture_size": 0.128, "gain": 2, "mechanical": "concrete"},
      "plaster": {"normal_map": {"generator": "plaster", "size": 64, "seed": 4},
                  "texture_size": 0.032, "gain": 2,
                  "mechanical": {"E": 10e9, "nu": 0.2, "H": 0.3e9, "tau": 0.05e9}},
      "oak": {"normal_map": {"generator": "oak", "size": 64, "seed": 2},
              "texture_size": 0.1, "gain": 2, "mechanical": "oak"}
    },
    "bodies": [
      {"name": "ground", "type": "static", "shapes": [{"type": "plane", "surface": "concrete"}]},
      {"name": "plaster_box", "position": [0, 0, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1], "surface": "plaster"}]},
      {"name": "oak_box", "position": [0, 2, 0.1], "linear_velocity": [1, 0, 0],
       "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1], "surface": "oak"}]}
    ]
  })");
  j["settings"]["friction_model"] = scene_model;
  if (with_pair)
    j["pairs"] = nlohmann::json::parse(
        R"([{"materials": ["plaster", "concrete"], "friction_model": "contact_area"}])");
  return j;
}

// The coefficients of the contacts of `body` (index), in the world's order.
std::vector<DirectionalMu> musOf(const World& world, size_t body) {
  std::vector<DirectionalMu> out;
  for (const Contact& c : world.contacts())
    if (c.body_a == body || c.body_b == body) out.push_back(c.mu);
  return out;
}

// Returns the contacts compared (none before the boxes settle onto the ground).
size_t expectSame(const std::vector<DirectionalMu>& a, const std::vector<DirectionalMu>& b,
                  const char* what) {
  EXPECT_EQ(a.size(), b.size()) << what;
  if (a.size() != b.size()) return 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].count, b[i].count) << what;
    for (int k = 0; k < a[i].count; ++k)
      EXPECT_EQ(a[i].mu[k], b[i].mu[k]) << what << " contact " << i;
  }
  return a.size();
}

// Per contact: the plaster box's contacts have the contact-area model's coefficients, the oak
// box's the paper's, bit for bit as each model alone gives them (the boxes never meet, and
// the static ground couples no contacts, so each box moves as in the scene of its model).
TEST(ContactAreaScene, APairPicksTheModelPerContact) {
  const auto mixed = instantiate(parseScene(pairsJson("paper", true), "m.json"));
  const auto area = instantiate(parseScene(pairsJson("contact_area", false), "a.json"));
  const auto paper = instantiate(parseScene(pairsJson("paper", false), "p.json"));
  bool differ = false;
  size_t compared[2] = {0, 0};
  for (int step = 0; step < 6; ++step) {
    mixed->step();
    area->step();
    paper->step();
    compared[0] +=
        expectSame(musOf(*mixed, 1), musOf(*area, 1), "plaster box vs contact_area alone");
    compared[1] += expectSame(musOf(*mixed, 2), musOf(*paper, 2), "oak box vs paper alone");
    // The two models do differ on each box (else the test would show nothing).
    const std::vector<DirectionalMu> p1 = musOf(*paper, 1), a2 = musOf(*area, 2);
    const std::vector<DirectionalMu> m1 = musOf(*mixed, 1), m2 = musOf(*mixed, 2);
    differ = differ || (!p1.empty() && p1.size() == m1.size() && p1[0].mu[0] != m1[0].mu[0] &&
                        !a2.empty() && a2.size() == m2.size() && a2[0].mu[0] != m2[0].mu[0]);
  }
  EXPECT_GE(compared[0], 8u);
  EXPECT_GE(compared[1], 8u);
  EXPECT_TRUE(differ);
  // The pair the other way round, and a scene-wide contact_area with the pair concrete / oak
  // set back to the paper's: the same split.
  nlohmann::json reversed = pairsJson("contact_area", false);
  reversed["pairs"] =
      nlohmann::json::parse(R"([{"materials": ["oak", "concrete"], "friction_model": "paper"}])");
  const auto flipped = instantiate(parseScene(reversed, "r.json"));
  const auto mixed2 = instantiate(parseScene(pairsJson("paper", true), "m.json"));
  size_t flipped_compared = 0;
  for (int step = 0; step < 4; ++step) {
    flipped->step();
    mixed2->step();
    flipped_compared +=
        expectSame(musOf(*flipped, 1), musOf(*mixed2, 1), "plaster box, paper pair for oak");
    flipped_compared +=
        expectSame(musOf(*flipped, 2), musOf(*mixed2, 2), "oak box, paper pair for oak");
  }
  EXPECT_GE(flipped_compared, 8u);
}

// Mixed models give the same bits on one thread or two (SPEC 9).
TEST(ContactAreaScene, PairsGiveTheSameResultOnOneThreadOrTwo) {
  nlohmann::json one = pairsJson("paper", true), two = pairsJson("paper", true);
  one["settings"]["threads"] = 1;
  two["settings"]["threads"] = 2;
  const auto a = instantiate(parseScene(one, "1.json"));
  const auto b = instantiate(parseScene(two, "2.json"));
  for (int step = 0; step < 10; ++step) {
    a->step();
    b->step();
  }
  EXPECT_FALSE(a->contacts().empty());
  EXPECT_EQ(a->stateHash(), b->stateHash());
}

// The one rule of a contact's model: a listed pair of materials (either order) overrides the
// default; surfaces without a material name, or pairs not listed, keep it.
TEST(ContactAreaScene, ModelSettingsPickTheModelOfAPair) {
  const auto named = [](const std::string& material) {
    Surface s;
    s.source.material = material;
    return s;
  };
  const Surface concrete = named("concrete"), plaster = named("plaster"), oak = named("oak"),
                none = named("");
  FrictionModelSettings o;
  EXPECT_FALSE(o.uses(FrictionModel::ContactArea));
  o.setPair("plaster", "concrete", FrictionModel::ContactArea);
  EXPECT_TRUE(o.uses(FrictionModel::ContactArea));
  EXPECT_EQ(o.modelFor(concrete, plaster), FrictionModel::ContactArea);
  EXPECT_EQ(o.modelFor(plaster, concrete), FrictionModel::ContactArea);
  EXPECT_EQ(o.modelFor(oak, concrete), FrictionModel::Paper);
  EXPECT_EQ(o.modelFor(none, plaster), FrictionModel::Paper);
  o.model = FrictionModel::ContactArea;
  o.setPair("concrete", "oak", FrictionModel::Paper);
  EXPECT_EQ(o.modelFor(oak, concrete), FrictionModel::Paper);
  EXPECT_EQ(o.modelFor(none, concrete), FrictionModel::ContactArea);
}

TEST(ContactAreaScene, PairsAndInlineMechanicalValuesAreWrittenBack) {
  nlohmann::json j = pairsJson("paper", true);
  // The oak box's surface inline, with its own values (a preset and numbers).
  j["bodies"][2]["shapes"][0]["surface"] = nlohmann::json::parse(
      R"({"normal_map": {"generator": "oak", "size": 64, "seed": 2}, "texture_size": 0.1,
          "mechanical": {"E": 12e9, "nu": 0.3, "H": 0.05e9, "tau": 0.01e9}})");
  j["bodies"][1]["shapes"][0]["surface"] = nlohmann::json::parse(
      R"({"normal_map": {"generator": "plaster", "size": 64, "seed": 4}, "mechanical": "acrylic"})");
  j["pairs"].push_back(
      nlohmann::json::parse(R"({"materials": ["oak", "oak"], "friction_model": "paper"})"));
  const SceneDesc scene = parseScene(j, "s.json");
  ASSERT_EQ(scene.pairs.size(), 2u);
  EXPECT_EQ(scene.pairs[0].materials[0], "plaster");
  EXPECT_EQ(scene.pairs[0].materials[1], "concrete");
  EXPECT_EQ(scene.pairs[0].friction_model, FrictionModel::ContactArea);
  ASSERT_EQ(scene.surface_mechanical.count({2, 0}), 1u);
  EXPECT_EQ(scene.surface_mechanical.at({2, 0}).modulus, 12e9);
  EXPECT_EQ(scene.surface_mechanical.at({1, 0}).name, "acrylic");
  const nlohmann::json out = sceneToJson(scene);
  EXPECT_EQ(out["pairs"], j["pairs"]);
  EXPECT_EQ(out["bodies"][1]["shapes"][0]["surface"]["mechanical"], "acrylic");
  EXPECT_EQ(out["bodies"][2]["shapes"][0]["surface"]["mechanical"]["tau"], 0.01e9);
  EXPECT_FALSE(out["bodies"][0]["shapes"][0]["surface"].is_object());  // still "concrete"
  const SceneDesc again = parseScene(out, "s.json");
  EXPECT_EQ(sceneToJson(again), out);
  EXPECT_EQ(again.surface_mechanical.at({2, 0}).hardness, 0.05e9);
  // No pairs: no key written.
  EXPECT_FALSE(sceneToJson(parseScene(pairsJson("paper", false), "s.json")).contains("pairs"));
}

// Inline surfaces with values run under the scene-wide model (no materials needed).
TEST(ContactAreaScene, InlineMechanicalValuesServeTheModel) {
  nlohmann::json j = sceneJson();
  j.erase("materials");
  j["bodies"][0]["shapes"][0]["surface"] = nlohmann::json::parse(
      R"({"normal_map": {"generator": "concrete", "size": 128, "seed": 1},
          "texture_size": 0.128, "gain": 2, "mechanical": "concrete"})");
  j["bodies"][1]["shapes"][0]["surface"] = nlohmann::json::parse(
      R"({"normal_map": {"generator": "plaster", "size": 64, "seed": 4},
          "texture_size": 0.032, "gain": 2,
          "mechanical": {"E": 10e9, "nu": 0.2, "H": 0.3e9, "tau": 0.05e9}})");
  const auto inline_world = instantiate(parseScene(j, "i.json"));
  const auto table_world = instantiate(parseScene(sceneJson(), "t.json"));
  for (int step = 0; step < 4; ++step) {
    inline_world->step();
    table_world->step();
  }
  EXPECT_GE(
      expectSame(musOf(*inline_world, 1), musOf(*table_world, 1), "inline vs materials table"), 1u);
  EXPECT_EQ(inline_world->stateHash(), table_world->stateHash());
  // Without values on the box: the error names its surface.
  j["bodies"][1]["shapes"][0]["surface"].erase("mechanical");
  const std::string what = errorOf(j);
  EXPECT_NE(what.find("/bodies/1/shapes/0/surface: friction_model contact_area needs every "
                      "surface to have \"mechanical\" values"),
            std::string::npos)
      << what;
}

std::string parseErrorOf(const nlohmann::json& json) {
  try {
    parseScene(json, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ContactAreaScene, BadPairsAndInlineValuesAreClearErrors) {
  const auto expectError = [](const nlohmann::json& j, const std::string& part) {
    const std::string what = parseErrorOf(j);
    EXPECT_NE(what.find(part), std::string::npos) << what;
  };
  nlohmann::json j = pairsJson("paper", true);
  j["pairs"][0]["materials"][1] = "granite";
  expectError(j, "s.json: /pairs/0/materials/1: unknown material \"granite\" (one of \"concrete\"");
  j = pairsJson("paper", true);
  j["pairs"][0]["materials"] = {"plaster"};
  expectError(j, "/pairs/0/materials: must name two materials");
  j = pairsJson("paper", true);
  j["pairs"][0]["materials"] = "plaster";
  expectError(j, "/pairs/0/materials: must be an array");
  j = pairsJson("paper", true);
  j["pairs"][0]["materials"][0] = 3;
  expectError(j, "/pairs/0/materials/0: must be a material name");
  j = pairsJson("paper", true);
  j["pairs"][0]["friction_model"] = "bowden";
  expectError(j, "/pairs/0/friction_model: must be one of \"paper\", \"contact_area\"");
  j = pairsJson("paper", true);
  j["pairs"][0].erase("friction_model");
  expectError(j, "/pairs/0: missing key \"friction_model\"");
  j = pairsJson("paper", true);
  j["pairs"][0]["model"] = "paper";
  expectError(j, "/pairs/0/model: unknown key");
  j = pairsJson("paper", true);
  j["pairs"].push_back(nlohmann::json::parse(
      R"({"materials": ["concrete", "plaster"], "friction_model": "paper"})"));
  expectError(
      j, "/pairs/1/materials: the pair \"concrete\", \"plaster\" is already given at /pairs/0");
  j = pairsJson("paper", true);
  j["materials"]["plaster"].erase("mechanical");
  expectError(j,
              "/pairs/0/materials/0: friction_model contact_area needs \"mechanical\" values; "
              "material \"plaster\" has none");
  j = pairsJson("paper", true);
  j["pairs"] = nlohmann::json::object();
  expectError(j, "/pairs: must be an array");
  // A contact_area pair under a provider other than cpu.
  j = pairsJson("paper", true);
  j["settings"]["friction_provider"] = "cone";
  const std::string what = errorOf(j);
  EXPECT_NE(what.find("/pairs/0/friction_model: friction model contact_area reads the fragments"),
            std::string::npos)
      << what;
  // Inline values: unknown preset, value out of range, wrong type.
  j = pairsJson("paper", false);
  j["bodies"][2]["shapes"][0]["surface"] = {{"mechanical", "granite"}};
  expectError(j, "/bodies/2/shapes/0/surface/mechanical: unknown mechanical preset \"granite\"");
  j["bodies"][2]["shapes"][0]["surface"] = {{"mechanical", {{"E", -1}, {"nu", 0.3}, {"tau", 1e6}}}};
  expectError(j, "/bodies/2/shapes/0/surface/mechanical/E: must be");
  j["bodies"][2]["shapes"][0]["surface"] = {{"mechanical", 5}};
  expectError(j, "/bodies/2/shapes/0/surface/mechanical: must be a preset name or");
  j["bodies"][2]["shapes"][0]["surface"] = {{"mechanical", "oak"}, {"gian", 1}};
  expectError(j, "/bodies/2/shapes/0/surface/gian: unknown key");
}

}  // namespace
}  // namespace asperity
