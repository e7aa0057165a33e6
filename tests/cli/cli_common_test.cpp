// The `asperity` tool's shared behaviour (main.cpp, cli_common): usage errors, help, and the
// number validators, seen through the built binary.
#include <gtest/gtest.h>

#include "cli/cli_test_support.hpp"

namespace asperity {
namespace {

using test::expectOneLineError;
using test::runCli;

TEST(Cli, NoSubcommandOrUnknownOneIsAUsageError) {
  expectOneLineError(runCli({}), "subcommand");
  expectOneLineError(runCli({"frobnicate"}), "frobnicate");
}

TEST(Cli, HelpExitsZero) {
  const auto r = runCli({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("texture"), std::string::npos);
  EXPECT_NE(r.out.find("cone"), std::string::npos);
  const auto t = runCli({"texture", "--help"});
  EXPECT_EQ(t.exit_code, 0);
  EXPECT_NE(t.out.find("--size"), std::string::npos);
}

TEST(Cli, UnknownOptionOfAFixedSubcommandIsAUsageError) {
  const auto r = runCli({"cone", test::sourcePath("README.md"), "--bogus-option", "1"});
  EXPECT_EQ(r.exit_code, 2);
  expectOneLineError(r, "--bogus-option");
}

}  // namespace
}  // namespace asperity
