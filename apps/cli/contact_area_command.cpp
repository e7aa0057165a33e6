// `asperity contact-area`: the real area of contact of a flat square patch of two height maps
// pressed together (SPEC 13, docs/contact-area.md), as numbers or JSON, and optionally a picture
// of which texels touch.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>

#include "asperity/contact_area/contact_area.hpp"
#include "asperity/contact_area/mechanical.hpp"
#include "asperity/error.hpp"
#include "asperity/texture/height_map.hpp"
#include "cli_common.hpp"

namespace asperity::cli {
namespace {

struct ContactAreaOptions {
  std::string b_file;
  std::string a_file;
  double height_scale = 0.0;  // 0: each file's stored scale
  double texture_size = 0.0;
  std::vector<double> loads;
  // NaN: not given (taken from the materials; hardness: none).
  double modulus = std::numeric_limits<double>::quiet_NaN();
  double hardness = std::numeric_limits<double>::quiet_NaN();
  bool json = false;
  std::string map;
  std::string material_a;  // presets (mechanical.hpp); A defaults to B's
  std::string material_b;
};

// E* and H from the options: given numbers (even bad ones, which the solver names) win over the
// materials' values.
ContactMaterial pairFrom(const ContactAreaOptions& opt, double& shear) {
  const bool modulus_given = !std::isnan(opt.modulus);
  const bool hardness_given = !std::isnan(opt.hardness);
  ContactMaterial material{modulus_given ? opt.modulus : 0.0, hardness_given ? opt.hardness : 0.0};
  shear = 0.0;
  if (!opt.material_b.empty() || !opt.material_a.empty()) {
    const std::string b_name = opt.material_b.empty() ? opt.material_a : opt.material_b;
    const Mechanical& b = findMechanical(b_name);
    const Mechanical& a = findMechanical(opt.material_a.empty() ? b_name : opt.material_a);
    const ContactMaterial pair = contactPair(a, b);
    if (!modulus_given) material.modulus = pair.modulus;
    if (!hardness_given) material.hardness = pair.hardness;
    shear = pairShear(a, b);
  }
  if (!modulus_given && opt.material_a.empty() && opt.material_b.empty())
    throw Error("contact-area: give --modulus or --material-b (and --material-a)");
  return material;
}

nlohmann::ordered_json toJson(const ContactArea& r, double shear) {
  nlohmann::ordered_json j;
  j["load"] = r.load;
  j["real_area"] = r.real_area;
  j["apparent_area"] = r.apparent_area;
  j["fraction"] = r.fraction;
  j["mean_pressure"] = r.mean_pressure;
  // No hardness, no plastic limit: the index is undefined.
  j["plasticity_index"] = r.plasticity_index > 0.0 ? nlohmann::ordered_json(r.plasticity_index)
                                                   : nlohmann::ordered_json(nullptr);
  j["separation"] = r.separation;
  j["summits_in_contact"] = r.summits_in_contact;
  j["summits"] = r.summits;
  // Bowden and Tabor's adhesion term, when the materials give a shear strength.
  if (shear > 0.0) j["adhesion_mu"] = adhesionFriction(shear, r);
  return j;
}

// An answer that is not a number is an error, never a line of nulls.
void checkFinite(const ContactArea& r) {
  const double values[] = {r.real_area, r.apparent_area, r.fraction, r.mean_pressure, r.separation};
  for (const double v : values)
    if (!std::isfinite(v))
      throw Error("contact-area: the load " + std::to_string(r.load) +
                  " N gives a non-finite area, pressure or separation (check the maps' heights, "
                  "--texture-size and the materials)");
}

void runContactArea(const ContactAreaOptions& opt) {
  if (!(opt.texture_size > 0.0)) throw Error("contact-area: --texture-size must be positive");
  const HeightMap b = loadHeightMap(opt.b_file, opt.height_scale);
  std::unique_ptr<HeightMap> a;
  if (!opt.a_file.empty())
    a = std::make_unique<HeightMap>(loadHeightMap(opt.a_file, opt.height_scale));
  const SummitSet set = findSummits(b, a.get(), opt.texture_size);
  double shear = 0.0;
  const ContactMaterial material = pairFrom(opt, shear);
  std::vector<ContactArea> results;
  for (double load : opt.loads) {
    results.push_back(solveContact(set, material, load));
    checkFinite(results.back());
  }
  if (!opt.map.empty()) saveContactMapPng(set, results, opt.map);
  if (opt.json) {
    // One load: one object; several: an array in the order given.
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const ContactArea& r : results) out.push_back(toJson(r, shear));
    std::cout << (results.size() == 1 ? out[0] : out).dump(2) << '\n';
    return;
  }
  for (const ContactArea& r : results)
    std::printf(
        "load %.6g N: real area %.6g m2 of %.6g m2 (%.4g %%), mean pressure %.6g Pa, "
        "plasticity index %.4g, %d of %d summits touching\n",
        r.load, r.real_area, r.apparent_area, 100.0 * r.fraction, r.mean_pressure,
        r.plasticity_index, r.summits_in_contact, r.summits);
  if (shear > 0.0)
    for (const ContactArea& r : results)
      std::printf("load %.6g N: adhesion mu = tau A_r / W = %.4g\n", r.load,
                  adhesionFriction(shear, r));
}

}  // namespace

void registerContactAreaCommand(CLI::App& app) {
  auto opt = std::make_shared<ContactAreaOptions>();
  CLI::App* sub = app.add_subcommand(
      "contact-area",
      "Real area of contact of two height maps pressed together over a flat square patch "
      "(Greenwood-Williamson summits, elastic-plastic): contact-area B.png [--a A.png] "
      "--texture-size M --load N --modulus PA [--hardness PA] [--material-b NAME] [--json] "
      "[--map out.png]");
  sub->add_option("b", opt->b_file,
                  "Height map of surface B (grey PNG, 8 or 16 bit, or float OpenEXR)")
      ->required();
  sub->add_option("--a", opt->a_file, "Height map of surface A (default: a smooth plane)");
  sub->add_option("--height-scale", opt->height_scale,
                  "Metres per full grey range (default: the scale stored in each file)")
      ->check(positiveNumber());
  // From a micrometre to a kilometre: past either, the patch's numbers leave a double's range.
  sub->add_option("--texture-size", opt->texture_size, "Side of the square patch (m)")
      ->check(numberInRange(1e-6, 1e3))
      ->required();
  sub->add_option("--load", opt->loads, "Normal load (N); repeat for several loads")->required();
  sub->add_option("--modulus", opt->modulus,
                  "Effective modulus E* of the pair (Pa); default: from the materials");
  sub->add_option("--hardness", opt->hardness, "Hardness H of the softer surface (Pa)");
  sub->add_option("--material-b", opt->material_b,
                  "B's material preset (steel, cast_iron, concrete, oak, pvc, acrylic, rubber): "
                  "E*, H and tau for the adhesion term tau A_r / W");
  sub->add_option("--material-a", opt->material_a, "A's material preset (default: B's)");
  sub->add_flag("--json", opt->json, "Print JSON");
  sub->add_option("--map", opt->map,
                  "Write the contact map (one panel per load; contact in white) to a PNG");
  sub->callback([opt]() { runContactArea(*opt); });
}

}  // namespace asperity::cli
