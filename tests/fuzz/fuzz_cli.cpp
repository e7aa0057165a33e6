// libFuzzer target: the `asperity` tool's argument parsing. The input is split at NUL bytes into
// at most 32 arguments after "asperity"; every subcommand is registered as in the tool, and
// once CLI11 has parsed and validated every option, a hook on the top-level app stops the run
// before any subcommand's action, so files named by the arguments are never written and each
// input costs microseconds. runCli must turn every argument list into an exit code (0 for
// --help, 1 or 2 with one error line, 1 for the stop below).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.hpp"

namespace {

// Thrown after parsing, before the actions: the commands' option storage stays owned by their
// actions (replacing those would free it under CLI11's feet).
struct ParsedOnly : std::exception {
  const char* what() const noexcept override { return "parsed"; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> words{"asperity"};
  std::string word;
  for (size_t i = 0; i < size && words.size() < 33; ++i) {
    if (data[i] == 0) {
      words.push_back(word);
      word.clear();
    } else {
      word.push_back(static_cast<char>(data[i]));
    }
  }
  if (words.size() < 33) words.push_back(word);
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());

  CLI::App app{"asperity", "asperity"};
  app.require_subcommand(1);
  asperity::cli::registerAllCommands(app);
  bool parsed = false;
  // The top-level app's parse-complete hook runs after every option's validation and before
  // the subcommands' callbacks.
  app.parse_complete_callback([&parsed] {
    parsed = true;
    throw ParsedOnly();
  });
  // Help and error text would flood the fuzzer's log.
  std::cout.setstate(std::ios::failbit);
  std::cerr.setstate(std::ios::failbit);
  const int code = asperity::cli::runCli(app, static_cast<int>(argv.size()), argv.data());
  std::cout.clear();
  std::cerr.clear();
  if (code < 0 || code > 2 || (parsed && code != 1)) __builtin_trap();
  return 0;
}
