// The choice of a contact's friction model (friction_model.hpp).
#include "asperity/friction/friction_model.hpp"

#include <algorithm>

namespace asperity {

void FrictionModelSettings::setPair(const std::string& a, const std::string& b, FrictionModel m) {
  pairs[std::minmax(a, b)] = m;
}

FrictionModel FrictionModelSettings::modelFor(const Surface& a, const Surface& b) const {
  if (pairs.empty()) return model;
  const std::string& name_a = a.source.material;
  const std::string& name_b = b.source.material;
  if (name_a.empty() || name_b.empty()) return model;
  const auto found = pairs.find(std::minmax(name_a, name_b));
  return found == pairs.end() ? model : found->second;
}

bool FrictionModelSettings::uses(FrictionModel m) const {
  if (model == m) return true;
  return std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) { return p.second == m; });
}

}  // namespace asperity
