// Whole-texture friction cones: per contact mu_d = mu0 + k_A cone_A(d) + k_B cone_B(d), i.e.
// Eq. 7 with each surface's mean taken over ALL its texels (flatPatchCone) instead of the
// patch. Each surface's cone is computed once (64 directions) and cached; at a contact the
// sample directions are turned into the texture's frame (its +u axis in world from
// textureAxisWorld) and the cached cone is interpolated (DirectionalMu::along). Textured scenes
// thus behave anisotropically without the patch samplers, at almost no cost per contact.
// Gain masks are ignored here (the patch samplers apply them); contacts never fall back.
#pragma once

#include <map>
#include <memory>
#include <tuple>

#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "asperity/math/simd_copy.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/texture/normal_map.hpp"

namespace asperity {

class ConeProvider : public FrictionProvider {
 public:
  static constexpr int kConeDirections = 64;

  // `simd`: which compiled copy of the cones' summing loop runs (the same bits either way).
  explicit ConeProvider(SimdCopy simd = SimdCopy::Auto) : simd_(simd) {}

  std::string name() const override { return "cone"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override;

  // The cached whole-texture mean cone mubar_d of one map on `side` (B faces +n with u along
  // t; A faces -n with u along t and v along -b), without mu0 or gain.
  const DirectionalMu& coneOf(const std::shared_ptr<const NormalMap>& map, Side side, float mu_max);

 private:
  struct Entry {
    std::shared_ptr<const NormalMap> map;  // keeps the keyed address alive
    DirectionalMu cone;
  };
  SimdCopy simd_;
  std::map<std::tuple<const NormalMap*, int, float>, Entry> cache_;
};

}  // namespace asperity
