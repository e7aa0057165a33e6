// A guard for third-party parsers that are not safe on hostile input: the work runs first in a
// forked child process, so that a crash or a hang there becomes an asperity::Error instead of
// taking the whole program down. Debian's assimp 5.2.5 crashes on some malformed glTF files
// (found by tests/fuzz/fuzz_asset.cpp), so asset imports read each file this way first.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace asperity::detail {

// Runs `work` in a forked child and waits for it. Returns when the child finished `work`
// (whether it returned or threw: errors are left for the caller's own run to report). Throws
// asperity::Error naming `what` when the child died (a crash: signal or sanitizer exit) or did
// not finish within `limit` (it is killed). Where no child can be made, returns at once.
void probeInChild(const std::string& what, const std::function<void()>& work,
                  std::chrono::milliseconds limit = std::chrono::seconds(60));

}  // namespace asperity::detail
