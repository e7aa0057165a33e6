// Helpers shared by every test: one tolerance helper and a way to run the CLI.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "asperity/error.hpp"

namespace asperity::test {

// The message of the asperity::Error that `f` throws ("" when it throws none).
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Relative-or-absolute closeness: |a - b| <= abs_tol + rel_tol * |b|.
::testing::AssertionResult near(double actual, double expected, double rel_tol,
                                double abs_tol = 0.0);

// The result of running a command line.
struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs build/bin/asperity with the given arguments (each is shell-quoted).
CommandResult runCli(const std::vector<std::string>& args);

// A fresh, empty temporary directory for one test; removed when the test passes (kept when it
// fails), or, made outside a test, when the whole run passes.
std::string tempDir(const std::string& tag);

// Path of a file in the repository.
std::string sourcePath(const std::string& relative);

// The experiment scenes: "scenes/<name>.json" for every JSON file in scenes/, sorted.
std::vector<std::string> experimentScenes();

}  // namespace asperity::test
