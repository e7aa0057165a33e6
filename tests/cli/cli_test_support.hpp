// Helpers shared by the command-line tests.
#pragma once

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

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

// Lines of a file (0 when it does not exist yet).
inline long lineCount(const std::string& path) {
  const std::string text = std::filesystem::exists(path) ? slurpBinary(path) : "";
  return std::count(text.begin(), text.end(), '\n');
}

// `asperity ARGS` started in the background and killed with SIGKILL `delay` after `ready()`
// first holds (polled every 2 ms; after 20 s it is killed anyway). Returns whether it was still
// running when killed.
inline bool killWhen(const std::vector<std::string>& args, const std::function<bool()>& ready,
                     std::chrono::milliseconds delay = std::chrono::milliseconds(0)) {
  std::vector<std::string> argv_text = {std::string(ASPERITY_BIN_DIR) + "/asperity"};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
    ADD_FAILURE() << "cannot start " << argv_text[0];
    return false;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!ready() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  std::this_thread::sleep_for(delay);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

}  // namespace asperity::test
