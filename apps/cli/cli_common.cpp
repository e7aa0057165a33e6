#include "cli_common.hpp"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "asperity/error.hpp"

namespace asperity::cli {

void printError(const std::string& message) {
  // One line: a message from CLI11 or the library may hold newlines.
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::cerr << "asperity: error: " << line << '\n';
}

int runCli(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
    return 0;
  } catch (const CLI::CallForHelp& e) {
    // --help: CLI11 prints the (sub)command's help on stdout and returns 0.
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors: CLI11's own message (it names the option), exit code 2.
    printError(e.what());
    return 2;
  } catch (const asperity::Error& e) {
    printError(e.what());
    return 1;
  } catch (const std::exception& e) {
    printError(e.what());
    return 1;
  }
}

namespace {
// Parses a whole string as a double (overflow gives +-inf); false when it is not a number.
bool parseDouble(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}
}  // namespace

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        // Not-a-number text is left to the option's own conversion, which reports it.
        if (!parseDouble(text, value)) return {};
        if (!std::isfinite(value)) return "value " + text + " is not a finite number";
        return {};
      },
      "FINITE");
}

CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!parseDouble(text, value)) return {};
        if (!std::isfinite(value) || value <= 0.0)
          return "value " + text + " is not a finite number > 0";
        return {};
      },
      "POSITIVE");
}

}  // namespace asperity::cli
