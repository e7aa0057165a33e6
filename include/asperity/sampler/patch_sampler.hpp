// What the patch samplers (CPU reference and OpenGL, SPEC 3) share in their public API: the
// per-pixel images of one contact's patch (the paper's Fig. 7), for tests, the `asperity
// patch` command and debugging. Their settings are checked by validate(FrictionSettings).
//
// Pixel layout: R x R, index j * R + i, pixel (i, j) centred at (-w/2 + (i + 1/2) w/R) t +
// (-w/2 + (j + 1/2) w/R) b from the contact point (row 0 at -b, as an OpenGL viewport).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "asperity/math/types.hpp"
#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

// One contact's patch, per surface (index 0 = A, 1 = B).
struct PatchImages {
  int resolution = 0;
  int directions = 0;
  std::array<std::vector<uint8_t>, 2> covered;  // 1 where the surface has a fragment
  std::array<std::vector<Vec3f>, 2> normals;    // unit meso normal, contact frame (t, b, n)
  std::array<std::vector<float>, 2> mu;         // [pixel * directions + k]: Eq. 5 (mask applied,
                                                // without k), 0 where not covered
  std::vector<uint8_t> in_patch;                // the set P of Eq. 8: covered by both
};

}  // namespace asperity
