// Diagnostics (asperity/diagnostics.hpp): a world's warnings are recorded, handed to a sink that
// may be set late without missing any, and never printed by the library.
#include "asperity/diagnostics.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "asperity/world/world.hpp"

namespace asperity {
namespace {

TEST(Diagnostics, RecordsAndHandsEachWarningToTheSink) {
  Diagnostics d;
  d.warn("first");
  // A sink set later gets the earlier warnings at once, then each new one.
  std::vector<std::string> seen;
  d.setSink([&](const std::string& w) { seen.push_back(w); });
  EXPECT_EQ(seen, std::vector<std::string>{"first"});
  d.warn("second");
  EXPECT_EQ(seen, (std::vector<std::string>{"first", "second"}));
  EXPECT_EQ(d.warnings(), seen);
  // clear() forgets the list; the sink stays.
  d.clear();
  EXPECT_TRUE(d.warnings().empty());
  d.warn("third");
  EXPECT_EQ(seen.back(), "third");
  // An empty sink only records.
  d.setSink({});
  d.warn("fourth");
  EXPECT_EQ(seen.size(), 3u);
  EXPECT_EQ(d.warnings().size(), 2u);
}

// Each world has its own: a warning in one is not seen by another.
TEST(Diagnostics, EachWorldHasItsOwn) {
  World a;
  World b;
  a.diagnostics().warn("only in a");
  EXPECT_EQ(a.diagnostics().warnings().size(), 1u);
  EXPECT_TRUE(b.diagnostics().warnings().empty());
}

}  // namespace
}  // namespace asperity
