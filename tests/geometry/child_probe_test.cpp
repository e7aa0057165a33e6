// The child-process guard for untrusted parsers: a crash, a hang or a runaway allocation becomes
// an error naming the input; finished work, thrown errors included, lets the caller go on.
#include "geometry/child_probe.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

namespace asperity::detail {
namespace {

using test::errorOf;

TEST(ChildProbe, FinishedWorkReturns) {
  EXPECT_EQ(errorOf([] { probeInChild("ok.glb", [] {}); }), "");
  // An error in the child is the caller's own read to report: the probe only guards crashes.
  EXPECT_EQ(errorOf([] { probeInChild("bad.glb", [] { throw std::runtime_error("no"); }); }), "");
}

TEST(ChildProbe, ACrashIsAnErrorNamingTheInput) {
  const std::string message =
      errorOf([] { probeInChild("evil.glb", [] { std::raise(SIGSEGV); }); });
  EXPECT_EQ(message.rfind("evil.glb: the importer crashed reading it (", 0), 0u) << message;
}

TEST(ChildProbe, AHangIsKilledAndNamed) {
  const std::string message = errorOf([] {
    probeInChild("slow.gltf", [] { std::this_thread::sleep_for(std::chrono::seconds(30)); },
                 {.time = std::chrono::milliseconds(200)});
  });
  EXPECT_EQ(message, "slow.gltf: reading it did not finish within 0.2 s (the file is malformed)");
}

TEST(ChildProbe, ARunawayAllocationIsKilledAndNamed) {
  ProbeLimits limits;
  limits.memory_bytes = size_t{64} << 20;
  const std::string message = errorOf([&] {
    probeInChild(
        "huge.glb",
        [] {
          std::vector<char> filled(size_t{256} << 20, 1);  // touched: resident
          std::this_thread::sleep_for(std::chrono::seconds(30));
          if (filled[12345] != 1) std::abort();
        },
        limits);
  });
  EXPECT_EQ(message,
            "huge.glb: reading it took more than 64 MB of memory (the file is malformed, or too "
            "large to read)");
}

}  // namespace
}  // namespace asperity::detail
