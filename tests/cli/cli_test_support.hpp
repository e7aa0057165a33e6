// Helpers shared by the command-line tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace asperity::test {

// A failed run: exit code 1 or 2 (no crash), one stderr line `asperity: error: ...` that
// names the culprit.
inline void expectOneLineError(const CommandResult& r, const std::string& culprit) {
  EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << "exit code " << r.exit_code;
  EXPECT_EQ(r.err.rfind("asperity: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(culprit), std::string::npos) << "'" << culprit << "' not in: " << r.err;
}

// A whole file as bytes.
inline std::string slurpBinary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace asperity::test
