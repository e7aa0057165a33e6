// The boxes on materials (Sec. 5.1) with the contact-area friction model (SPEC 13): the scene's
// surfaces become materials with the mechanical values of what they show, and the model
// computes each contact's friction from the heights of the same generators.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>

#include "experiments/experiment_outcomes.hpp"
#include "support/test_support.hpp"

namespace asperity::experiments {
namespace {

// Which preset each plane gets; the plaster boxes get plaster's values (docs/contact-area.md).
const char* presetOf(const std::string& body) {
  if (body == "plane_concrete") return "concrete";
  if (body == "plane_cast_iron") return "cast_iron";
  if (body == "plane_steel") return "steel";
  return "pvc";
}

// scenes/boxes_on_materials.json under the contact-area model, written into a fresh folder.
std::string contactAreaScene() {
  std::ifstream in(test::sourcePath("scenes/boxes_on_materials.json"));
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["settings"]["friction_model"] = "contact_area";
  scene["materials"]["plaster_box"]["mechanical"] = {
      {"E", 10e9}, {"nu", 0.2}, {"H", 0.3e9}, {"tau", 0.06e9}};
  for (nlohmann::json& body : scene["bodies"]) {
    nlohmann::json& surface = body["shapes"][0]["surface"];
    if (surface.is_string()) continue;
    const std::string name = body["name"].get<std::string>();
    surface["mechanical"] = presetOf(name);
    scene["materials"][name] = surface;
    surface = name;
  }
  const std::string dir = test::tempDir("boxes_contact_area");
  std::ofstream(dir + "/boxes_on_materials.json") << scene.dump(1);
  return dir;
}

TEST(ContactAreaExperiments, BoxesOnMaterialsKeepTheirOrder) {
  RunOptions o;
  o.scenes_dir = contactAreaScene();
  o.record_every = 5;
  const Outcome out = runExperiment("boxes_on_materials", o);
  const double concrete = out.value("slide_concrete"), iron = out.value("slide_cast_iron");
  const double steel = out.value("slide_steel"), plastic = out.value("slide_plastic");
  std::printf("contact_area slides: concrete %.3f cast_iron %.3f steel %.3f plastic %.3f m\n",
              concrete, iron, steel, plastic);
  EXPECT_LT(concrete, iron);
  EXPECT_LT(iron, steel);
  EXPECT_LE(steel, plastic);
  EXPECT_LT(concrete, plastic);
}

}  // namespace
}  // namespace asperity::experiments
