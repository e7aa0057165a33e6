// The friction provider registry: built-in names, unknown names listed, added factories used.
#include "asperity/scene/friction_registry.hpp"

#include <gtest/gtest.h>

#include "asperity/error.hpp"
#include "asperity/sampler/constant_provider.hpp"

namespace asperity {
namespace {

TEST(FrictionRegistry, BuiltInProviders) {
  for (const char* name : {"constant", "cone", "cpu"}) {
    EXPECT_TRUE(hasFrictionProvider(name)) << name;
    EXPECT_EQ(makeFrictionProvider(name)->name(), name);
  }
}

TEST(FrictionRegistry, UnknownNameListsTheAvailableOnes) {
  try {
    makeFrictionProvider("velvet");
    FAIL();
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("unknown friction sampler \"velvet\" (available: ", 0), 0u);
    EXPECT_NE(message.find("cone"), std::string::npos);
  }
}

TEST(FrictionRegistry, RegisteredFactoryIsUsed) {
  // A provider under a new name (here the constant one, so the name tells them apart).
  struct Renamed : ConstantProvider {
    std::string name() const override { return "renamed-constant"; }
  };
  registerFrictionProvider("renamed-constant", [] { return std::make_unique<Renamed>(); });
  EXPECT_TRUE(hasFrictionProvider("renamed-constant"));
  EXPECT_EQ(makeFrictionProvider("renamed-constant")->name(), "renamed-constant");
  const std::vector<std::string> names = frictionProviderNames();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_THROW(registerFrictionProvider("", [] { return std::make_unique<Renamed>(); }), Error);
}

}  // namespace
}  // namespace asperity
