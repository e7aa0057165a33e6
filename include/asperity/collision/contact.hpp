// One contact point between two bodies, and its frame.
//
// Conventions (SPEC 1), relied on by every stage:
//  - body A is first, B second; the normal n points from B toward A;
//  - phi >= 0 is the penetration depth;
//  - the frame (t, b, n) is right-handed: b = n x t;
//  - solver impulses act on A: lambda_n n + lambda_t t + lambda_b b; B gets the opposite;
//  - mu.mu[k] bounds the friction on A along d_k = cos(2 pi k/N) t + sin(2 pi k/N) b.
#pragma once

#include "asperity/dynamics/body.hpp"
#include "asperity/friction/directions.hpp"
#include "asperity/math/types.hpp"

namespace asperity {

struct Contact {
  BodyId body_a = kNoBody;
  BodyId body_b = kNoBody;
  int shape_a = -1;  // index into the body's shapes
  int shape_b = -1;
  int feature_a = -1;  // triangle index for meshes, face index for boxes, -1 otherwise
  int feature_b = -1;

  Vec3 point = Vec3::Zero();      // midpoint of the witness points (the patch centre, SPEC 3)
  Vec3 witness_a = Vec3::Zero();  // deepest point of A's surface
  Vec3 witness_b = Vec3::Zero();  // deepest point of B's surface
  Vec3 normal = Vec3::UnitZ();    // from B toward A
  double phi = 0.0;               // penetration depth, >= 0 (m)
  Vec3 t = Vec3::UnitX();         // contact frame (set by the frame stage)
  Vec3 b = Vec3::UnitY();

  // Friction coefficients for this step (set by the friction provider).
  DirectionalMu mu;
  int covered_pixels = 0;  // |P| of Eq. 8 (patch samplers only)
  bool fallback = false;   // P was empty: mu = mu0

  // Identity that persists across steps (for warm starting), from the collision stage.
  uint64_t key = 0;
  // Solver results of this step (impulses on A), valid until the next step.
  double lambda_n = 0.0, lambda_t = 0.0, lambda_b = 0.0;
};

}  // namespace asperity
