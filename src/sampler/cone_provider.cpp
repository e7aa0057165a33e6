// Whole-texture friction cones turned into each contact's frame (see cone_provider.hpp).
#include "asperity/sampler/cone_provider.hpp"

#include <cmath>

#include "asperity/friction/patch_cone.hpp"
#include "dynamics/texture_axis.hpp"

namespace asperity {

namespace {

// One surface of a contact as the cone sees it: its cone, gain and texture angle.
struct SideCone {
  const DirectionalMu* cone = nullptr;
  double gain = 0.0;
  double angle = 0.0;  // angle of the texture's +u axis from t toward b (rad)
};

}  // namespace

const DirectionalMu& ConeProvider::coneOf(const std::shared_ptr<const NormalMap>& map, Side side,
                                          float mu_max) {
  const auto key = std::make_tuple(map.get(), side == Side::A ? 0 : 1, mu_max);
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second.cone;
  // Eq. 8 over every texel of the map on its side, the other surface flat (gain 1, mu0 0).
  PatchConeOptions opt;
  opt.directions = kConeDirections;
  opt.mu_max = mu_max;
  opt.simd = simd_;
  DirectionalMu cone;
  if (side == Side::B) {
    opt.gains = PatchGains{0.0, 0.0, 1.0};
    cone = flatPatchCone(nullptr, *map, opt);
  } else {
    const NormalMap flat(1, 1);
    opt.gains = PatchGains{0.0, 1.0, 0.0};
    cone = flatPatchCone(map.get(), flat, opt);
  }
  return cache_.emplace(key, Entry{map, cone}).first->second.cone;
}

void ConeProvider::computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                                       const FrictionSettings& settings) {
  const int n = settings.directions;
  const DirectionalMu base = DirectionalMu::uniform(n, static_cast<float>(settings.mu0));
  for (Contact& c : contacts) {
    c.mu = base;
    c.covered_pixels = 0;
    c.fallback = false;
    // Each textured surface of the contact adds k_X cone_X turned by its texture angle.
    for (const Side side : {Side::A, Side::B}) {
      const BodyId id = side == Side::A ? c.body_a : c.body_b;
      const int shape = side == Side::A ? c.shape_a : c.shape_b;
      if (id >= bodies.size() || shape < 0) continue;
      const Body& body = bodies[id];
      if (static_cast<size_t>(shape) >= body.shapes.size()) continue;
      const Surface& surface = body.shapes[static_cast<size_t>(shape)].surface;
      if (!surface.normal_map || surface.normal_map->empty() || surface.gain == 0.0) continue;
      SideCone sc;
      sc.cone = &coneOf(surface.normal_map, side, settings.mu_max);
      sc.gain = surface.gain;
      const Vec3& witness = side == Side::A ? c.witness_a : c.witness_b;
      const int feature = side == Side::A ? c.feature_a : c.feature_b;
      if (const auto u = textureAxisWorld(body, shape, feature, witness)) {
        sc.angle = std::atan2(u->dot(c.b), u->dot(c.t));
      }
      // Contact direction at angle theta_k is at theta_k - angle in the texture's frame.
      for (int k = 0; k < n; ++k) {
        const double theta = 2.0 * kPi * k / n;
        c.mu.mu[static_cast<size_t>(k)] +=
            static_cast<float>(sc.gain * sc.cone->along(theta - sc.angle));
      }
    }
  }
}

}  // namespace asperity
