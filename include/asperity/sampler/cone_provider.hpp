// Whole-texture friction cones: per contact mu_d = mu0 + k_A cone_A(d) + k_B cone_B(d) (Eq. 7
// with each surface's mean over ALL its texels instead of the patch). Each surface's cone is
// computed once (flatPatchCone-style, 64 directions) and cached; at a contact the sample
// directions are rotated into the texture's frame (its +u axis in world, see
// textureTangent) and the cached cone is interpolated. It makes textured scenes anisotropic
// without the patch samplers, and is cheap (no per-contact rasterisation).
#pragma once

#include <map>
#include <memory>

#include "asperity/friction/directions.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/texture/normal_map.hpp"

namespace asperity {

class ConeProvider : public FrictionProvider {
 public:
  std::string name() const override { return "cone"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override;

  // Cached whole-texture mean ploughing cone of one normal map seen as surface B (facing +n,
  // u along t): mubar_d for 64 directions, without mu0 or gain.
  const DirectionalMu& coneOf(const NormalMap& map, float mu_max);

 private:
  std::map<std::pair<const NormalMap*, float>, DirectionalMu> cache_;
  // Keep the maps alive while cached (the cache is keyed by address).
  std::vector<std::shared_ptr<const NormalMap>> keep_alive_;
};

}  // namespace asperity
