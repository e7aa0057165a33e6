#include "cli_common.hpp"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/world/world.hpp"
#ifdef ASPERITY_HAVE_GL
#include "asperity/scene/gl_sampler_provider.hpp"
#endif

namespace asperity::cli {

void registerAllCommands(CLI::App& app) {
  registerTextureCommand(app);
  registerConeCommand(app);
  registerTribometerCommand(app);
  registerCalibrateCommand(app);
  registerRunCommand(app);
  registerSweepCommand(app);
  registerPatchCommand(app);
  registerRenderCommand(app);
  registerBenchCommand(app);
  registerReportCommand(app);
  registerContactAreaCommand(app);
}

void printError(const std::string& message) {
  // One line: a message from CLI11 or the library may hold newlines.
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::cerr << "asperity: error: " << line << '\n';
}

void printWarning(const std::string& warning) {
  // One write, so that lines of two threads do not interleave.
  std::cerr << ("asperity: warning: " + warning + "\n");
}

void printWarnings(World& world) {
  world.diagnostics().setSink(printWarning);
}

namespace {
// CLI11 reports `asperity frobnicate` as a missing subcommand; name the word instead.
void checkSubcommandName(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  const std::string word = argv[1];
  const auto matching = app.get_subcommands([&](const CLI::App* s) { return s->check_name(word); });
  if (matching.empty())
    throw CLI::ExtrasError("unknown subcommand '" + word + "' (see asperity --help)",
                           CLI::ExitCodes::ExtrasError);
}
}  // namespace

int runCli(CLI::App& app, int argc, const char* const* argv) {
  try {
    checkSubcommandName(app, argc, argv);
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

CLI::Validator notNegative() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (!text.empty() && text[0] == '-') return "value " + text + " is negative";
        return {};
      },
      "NOT NEGATIVE");
}

CLI::Validator settingRange(const char* field, const SettingRange& range) {
  return CLI::Validator(
      [field, range](std::string& text) -> std::string {
        double value = 0.0;
        if (!parseDouble(text, value)) return {};
        const std::string problem = range.check(value);
        return problem.empty() ? problem : std::string(field) + " " + problem;
      },
      range.describe());
}

CLI::Validator numberInRange(double min, double max) {
  std::ostringstream range;
  range << "[" << min << ", " << max << "]";
  return CLI::Validator(
      [min, max, bounds = range.str()](std::string& text) -> std::string {
        double value = 0.0;
        if (!parseDouble(text, value)) return {};
        // NaN fails both comparisons, so test it explicitly.
        if (!std::isfinite(value) || value < min || value > max)
          return "value " + text + " is not a finite number in " + bounds;
        return {};
      },
      "NUMBER in " + range.str());
}

FrictionProviders frictionProviders() {
  FrictionProviders providers = FrictionProviders::builtIn();
#ifdef ASPERITY_HAVE_GL
  // Scenes and --sampler may ask for the OpenGL patch sampler from every subcommand.
  addGlPatchSampler(providers);
#endif
  return providers;
}

void checkSampler(const FrictionProviders& providers, const std::string& name,
                  const std::string& option) {
  if (name.empty() || providers.has(name)) return;
  // make() throws the message listing the known names.
  try {
    providers.make(name);
  } catch (const Error& e) {
    throw Error(option + ": " + e.what());
  }
}

}  // namespace asperity::cli
