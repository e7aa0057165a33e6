// The constant provider: mu0 in every direction, no fallbacks.
#include "asperity/sampler/constant_provider.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "asperity/error.hpp"

namespace asperity {
namespace {

TEST(ConstantProvider, EveryDirectionIsMu0) {
  std::vector<Contact> contacts(3);
  contacts[1].fallback = true;
  FrictionSettings s;
  s.directions = 8;
  s.mu0 = 0.35;
  ConstantProvider provider;
  provider.computeCoefficients({}, contacts, s);
  for (const Contact& c : contacts) {
    ASSERT_EQ(c.mu.count, 8);
    for (int k = 0; k < 8; ++k) EXPECT_EQ(c.mu.mu[static_cast<size_t>(k)], 0.35f);
    EXPECT_FALSE(c.fallback);
  }
  EXPECT_EQ(provider.name(), "constant");
}

TEST(ConstantProvider, BadDirectionCountThrows) {
  std::vector<Contact> contacts(1);
  FrictionSettings s;
  s.directions = 2;
  ConstantProvider provider;
  EXPECT_THROW(provider.computeCoefficients({}, contacts, s), Error);
}

}  // namespace
}  // namespace asperity
