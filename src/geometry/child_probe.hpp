// A guard for third-party parsers that are not safe on hostile input: the work runs first in a
// forked child process, so that a crash, a hang or a runaway allocation there becomes an
// asperity::Error instead of taking the whole program down. Debian's assimp 5.2.5 crashes on
// some malformed glTF files, and a GLB header that claims a 4 GB chunk makes it allocate and
// fill 4 GB for a 1 kB file (both found by tests/fuzz/fuzz_asset.cpp), so asset imports read
// each file this way first.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace asperity::detail {

// How long the child may take, and how much memory it may add to what it shares with the
// caller (resident bytes beyond the caller's own at the fork).
struct ProbeLimits {
  std::chrono::milliseconds time = std::chrono::seconds(60);
  size_t memory_bytes = size_t{1} << 30;
};

// Runs `work` in a forked child and waits for it. Returns when the child finished `work`
// (whether it returned or threw: errors are left for the caller's own run to report). Throws
// asperity::Error naming `what` when the child died (a crash: signal or sanitizer exit) or
// went beyond a limit (it is killed). Where no child can be made, returns at once.
void probeInChild(const std::string& what, const std::function<void()>& work,
                  const ProbeLimits& limits = {});

}  // namespace asperity::detail
