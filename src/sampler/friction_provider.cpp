// What every friction provider does unless it says otherwise (friction_provider.hpp).
#include "asperity/sampler/friction_provider.hpp"

#include "asperity/error.hpp"
#include "asperity/math/enum_names.hpp"

namespace asperity {

void FrictionProvider::setFrictionModels(const FrictionModelSettings& models) {
  for (const auto& [name, model] : kFrictionModelNames) {
    if (model == FrictionModel::Paper || !models.uses(model)) continue;
    throw Error("friction model " + std::string(name) + " reads the fragments of each patch: it " +
                "needs a patch sampler (\"cpu\" or \"gl\"), not the \"" + this->name() +
                "\" provider");
  }
}

}  // namespace asperity
