// Helpers shared by the texture tests: map statistics computed directly from the texels.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "asperity/error.hpp"
#include "asperity/math/types.hpp"
#include "asperity/texture/generators.hpp"

namespace asperity::test {

// tan(theta) of a texel's tilt from the macro normal (0, 0, 1).
inline double tanTilt(const Vec3f& m) {
  return std::hypot(static_cast<double>(m.x()), static_cast<double>(m.y())) / m.z();
}

// Mean ploughing (2 / pi) tan(theta) over the map (SPEC 2, without the direction factor).
inline double meanPloughing(const NormalMap& map) {
  double sum = 0.0;
  for (const Vec3f& m : map.texels()) sum += tanTilt(m);
  return 2.0 / kPi * sum / static_cast<double>(map.texels().size());
}

// mu_d of a surface B under a flat contact with n = (0, 0, 1) (SPEC 2, Eqs. 3 to 6):
// mean over texels of max(0, m' . d) (2 / pi) tan(theta), d a unit tangent direction.
inline double muAlong(const NormalMap& map, double dx, double dy) {
  double sum = 0.0;
  for (const Vec3f& m : map.texels()) {
    // m' . d tan(theta) = (m_x d_x + m_y d_y) / m_z.
    const double along = (m.x() * dx + m.y() * dy) / m.z();
    sum += std::max(0.0, along);
  }
  return 2.0 / kPi * sum / static_cast<double>(map.texels().size());
}

// Expects fn to throw asperity::Error whose one-line message contains every fragment.
template <class Fn>
void expectErrorContaining(Fn fn, std::initializer_list<std::string> fragments) {
  try {
    fn();
    ADD_FAILURE() << "no asperity::Error thrown";
  } catch (const Error& e) {
    const std::string what = e.what();
    for (const std::string& f : fragments) {
      EXPECT_NE(what.find(f), std::string::npos) << "'" << f << "' not in: " << what;
    }
    EXPECT_EQ(what.find('\n'), std::string::npos) << "message must be one line";
  }
}

// Generates a map with the given parameters.
inline NormalMap generate(const std::string& name, std::map<std::string, std::string> params = {},
                          int size = 128, uint64_t seed = 1) {
  GeneratorSpec spec;
  spec.name = name;
  spec.params = std::move(params);
  spec.size = size;
  spec.seed = seed;
  return generateNormalMap(spec);
}

}  // namespace asperity::test
