// Friction provider tables: built-in names, unknown names listed, added factories used, and
// tables that do not share state (each front end or world owner has its own).
#include "asperity/scene/friction_providers.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "asperity/error.hpp"
#include "asperity/sampler/constant_provider.hpp"
#include "asperity/scene/scene.hpp"

namespace asperity {
namespace {

// A provider under a new name (the constant one, so the name tells them apart).
struct Renamed : ConstantProvider {
  std::string name() const override { return "renamed-constant"; }
};

TEST(FrictionProviders, BuiltInProviders) {
  const FrictionProviders providers = FrictionProviders::builtIn();
  EXPECT_EQ(providers.names(), (std::vector<std::string>{"cone", "constant", "cpu"}));
  for (const char* name : {"constant", "cone", "cpu"}) {
    EXPECT_TRUE(providers.has(name)) << name;
    EXPECT_EQ(providers.make(name)->name(), name);
  }
}

TEST(FrictionProviders, UnknownNameListsTheAvailableOnes) {
  try {
    FrictionProviders::builtIn().make("velvet");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown friction sampler \"velvet\" (available: cone, constant, cpu)");
  }
}

TEST(FrictionProviders, AddedFactoryIsUsed) {
  FrictionProviders providers = FrictionProviders::builtIn();
  providers.add("renamed-constant", [] { return std::make_unique<Renamed>(); });
  EXPECT_TRUE(providers.has("renamed-constant"));
  EXPECT_EQ(providers.make("renamed-constant")->name(), "renamed-constant");
  const std::vector<std::string> names = providers.names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(names.size(), 4u);
  EXPECT_THROW(providers.add("", [] { return std::make_unique<Renamed>(); }), Error);
  EXPECT_THROW(providers.add("empty", FrictionProviderFactory()), Error);
}

TEST(FrictionProviders, TablesAreIndependent) {
  // Adding to one table leaves a new built-in table and a copy made before unchanged.
  FrictionProviders a = FrictionProviders::builtIn();
  const FrictionProviders before = a;
  a.add("renamed-constant", [] { return std::make_unique<Renamed>(); });
  EXPECT_FALSE(FrictionProviders::builtIn().has("renamed-constant"));
  EXPECT_FALSE(before.has("renamed-constant"));
  EXPECT_THROW(FrictionProviders().make("cone"), Error);  // an empty table offers nothing
}

TEST(FrictionProviders, InstantiateUsesTheGivenTable) {
  SceneDesc scene;
  scene.friction_provider = "renamed-constant";
  // The built-in table does not know the name; the table given to instantiate() does.
  EXPECT_THROW(instantiate(scene), Error);
  InstantiateOptions options;
  options.providers.add("renamed-constant", [] { return std::make_unique<Renamed>(); });
  EXPECT_EQ(instantiate(scene, options)->frictionProvider().name(), "renamed-constant");
}

}  // namespace
}  // namespace asperity
