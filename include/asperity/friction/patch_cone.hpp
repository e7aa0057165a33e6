// The friction limit surface of a flat patch covering every texel of both textures (the
// paper's Fig. 8 and `asperity cone`). Surface B faces +n with u along t and v along b;
// surface A faces -n with u along t and v along -b (flat when absent).
#pragma once

#include "asperity/friction/fragment_model.hpp"
#include "asperity/texture/normal_map.hpp"

namespace asperity {

struct PatchConeOptions {
  int directions = 16;
  PatchGains gains{0.0, 1.0, 1.0};
  float mu_max = kDefaultMuMax;
  SimdCopy simd = SimdCopy::Auto;  // which copy of the summing loop runs
};

// `a` may be null (flat A). When both are given they may differ in size: each surface's mean
// is taken over its own texels. Throws asperity::Error for a bad direction count or mu_max.
DirectionalMu flatPatchCone(const NormalMap* a, const NormalMap& b, const PatchConeOptions& opt);

}  // namespace asperity
