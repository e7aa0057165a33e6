#include "support/test_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

namespace asperity::test {

::testing::AssertionResult near(double actual, double expected, double rel_tol, double abs_tol) {
  const double diff = std::abs(actual - expected);
  const double bound = abs_tol + rel_tol * std::abs(expected);
  if (std::isfinite(actual) && diff <= bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual << " is not within " << bound << " of " << expected
                                       << " (difference " << diff << ")";
}

namespace {
std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The folders tempDir makes: a test's are removed when it passes, those made outside a test
// (suite set-ups) when the whole run passes; failures keep theirs to look into. So runs of
// the suite do not pile up files in the temporary folder.
class TempDirCleaner : public ::testing::EmptyTestEventListener {
 public:
  void add(const std::filesystem::path& dir, bool in_test) {
    (in_test ? test_dirs_ : run_dirs_).push_back(dir);
  }

 private:
  void OnTestEnd(const ::testing::TestInfo& info) override {
    removeIf(info.result() != nullptr && info.result()->Passed(), test_dirs_);
  }
  void OnTestProgramEnd(const ::testing::UnitTest& unit) override {
    removeIf(unit.Passed(), run_dirs_);
  }
  static void removeIf(bool passed, std::vector<std::filesystem::path>& dirs) {
    std::error_code ignored;
    if (passed)
      for (const auto& dir : dirs) std::filesystem::remove_all(dir, ignored);
    dirs.clear();
  }
  std::vector<std::filesystem::path> test_dirs_, run_dirs_;
};

// Appended before main runs; GoogleTest owns and deletes it.
TempDirCleaner* const cleaner = [] {
  auto* c = new TempDirCleaner;
  ::testing::UnitTest::GetInstance()->listeners().Append(c);
  return c;
}();
}  // namespace

CommandResult runCli(const std::vector<std::string>& args) {
  const std::string dir = tempDir("cli");
  std::string cmd = shellQuote(std::string(ASPERITY_BIN_DIR) + "/asperity");
  for (const auto& a : args) cmd += " " + shellQuote(a);
  cmd += " >" + dir + "/out 2>" + dir + "/err </dev/null";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(dir + "/out");
  r.err = slurp(dir + "/err");
  return r;
}

std::string tempDir(const std::string& tag) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "none";
  for (char& c : name)
    if (c == '/') c = '_';
  const fs::path dir =
      fs::temp_directory_path() / "asperity-tests" /
      (name + "." + tag + "." + std::to_string(::getpid()) + "." + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  cleaner->add(dir, info != nullptr);
  return dir.string();
}

std::string sourcePath(const std::string& relative) {
  return std::string(ASPERITY_SOURCE_DIR) + "/" + relative;
}

std::vector<std::string> experimentScenes() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(sourcePath("scenes")))
    if (entry.path().extension() == ".json")
      out.push_back("scenes/" + entry.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace asperity::test
