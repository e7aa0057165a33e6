// Friction models: what turns the fragments of a contact's patch (each pixel's ploughing vector
// and, where a model reads them, its heights) into the contact's coefficients mu_d. Every patch
// sampler (CPU and OpenGL) serves every model; the model of a contact is chosen here, per pair
// of materials, and nowhere else.
//   paper         the paper's Eqs. 5, 8 and 7: mu_d = mu0 + k_A mean_A + k_B mean_B over P
//   contact_area  the real area of contact (docs/contact-area.md): adhesion tau A_r / W in place
//                 of mu0, ploughing averaged over the pixels in contact only
#pragma once

#include <map>
#include <string>
#include <utility>

#include "asperity/geometry/surface.hpp"

namespace asperity {

enum class FrictionModel { Paper, ContactArea };
inline constexpr std::pair<const char*, FrictionModel> kFrictionModelNames[] = {
    {"paper", FrictionModel::Paper}, {"contact_area", FrictionModel::ContactArea}};

// Which model each contact uses, and what the models need beyond FrictionSettings. A provider
// takes it through FrictionProvider::setFrictionModels.
struct FrictionModelSettings {
  FrictionModel model = FrictionModel::Paper;  // every pair `pairs` does not name
  // The model of contacts between two materials (SurfaceSource::material), keyed by the two
  // names in sorted order (setPair sorts them); a surface without a material name takes `model`.
  std::map<std::pair<std::string, std::string>, FrictionModel> pairs;
  // The time a contact's normal impulse (Contact::lambda_n) was gathered over: a model that
  // reads loads takes W = lambda_n / dt.
  double dt = 0.01;

  void setPair(const std::string& a, const std::string& b, FrictionModel m);
  // The model of a contact between surfaces a and b (each side's first shape's surface).
  FrictionModel modelFor(const Surface& a, const Surface& b) const;
  // Whether any contact may use model m.
  bool uses(FrictionModel m) const;
};

}  // namespace asperity
