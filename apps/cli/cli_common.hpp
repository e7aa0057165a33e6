// Shared pieces of the `asperity` command-line tool: one registration function per subcommand
// (each in its own file), the uniform error path, and number validators.
//
// Adding a subcommand: write apps/cli/<name>_command.cpp defining registerXCommand, declare it
// below, and call it from registerAllCommands (cli_common.cpp). Its callback throws
// asperity::Error on bad input; runCli prints `asperity: error: <message>` (one line) and
// returns 1.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "asperity/math/enum_names.hpp"
#include "asperity/sampler/friction_settings.hpp"
#include "asperity/scene/friction_providers.hpp"

namespace asperity {
class World;
}

namespace asperity::cli {

// The names an enumeration's table gives, for CLI11's check.
template <typename E>
std::vector<std::string> namesOf(EnumNames<E> names) {
  std::vector<std::string> out;
  for (const auto& [name, e] : names) out.emplace_back(name);
  return out;
}

// Subcommands (apps/cli/<name>_command.cpp).
void registerTextureCommand(CLI::App& app);
void registerConeCommand(CLI::App& app);
void registerTribometerCommand(CLI::App& app);
void registerCalibrateCommand(CLI::App& app);
void registerRunCommand(CLI::App& app);
void registerSweepCommand(CLI::App& app);
void registerPatchCommand(CLI::App& app);
void registerRenderCommand(CLI::App& app);
void registerBenchCommand(CLI::App& app);
void registerReportCommand(CLI::App& app);
void registerContactAreaCommand(CLI::App& app);

// Every subcommand, in the order `asperity --help` lists them (the tool and its fuzz target).
void registerAllCommands(CLI::App& app);

// Parses argv and runs the chosen subcommand's callback. Returns the process exit code:
// 0 on success and for --help, 2 for a usage error (CLI11's message), 1 for any other error.
// Every error is printed as one line `asperity: error: <message>` on stderr.
int runCli(CLI::App& app, int argc, const char* const* argv);

// Rejects NaN and infinities (CLI::Range lets NaN through). Use before a CLI::Range check:
//   app.add_option("--mu0", x)->check(finiteNumber())->check(CLI::Range(0.0, 1e3));
// or, in one check, ->check(numberInRange(0.0, 1e3)).
CLI::Validator finiteNumber();
// Accepts finite numbers > 0.
CLI::Validator positiveNumber();
// Rejects a leading minus sign (CLI11 wraps "-1" around for unsigned options).
CLI::Validator notNegative();
// Accepts finite numbers in [min, max] (NaN rejected), with a message naming the bounds.
CLI::Validator numberInRange(double min, double max);
// A friction setting's one range (asperity/sampler/friction_settings.hpp), in the words every
// front end uses: "patch_resolution must be an integer in [1, 256], got 512".
CLI::Validator settingRange(const char* field, const SettingRange& range);

// The friction samplers every subcommand offers: the core library's and, when the tool is built
// with OpenGL, "gl" (each call makes a new table; worlds get their providers from it).
FrictionProviders frictionProviders();
// Throws asperity::Error `<option>: unknown friction sampler "x" (available: ...)` unless
// `name` is empty or in `providers`.
void checkSampler(const FrictionProviders& providers, const std::string& name,
                  const std::string& option = "--sampler");

// Prints `asperity: error: <message>` as one line on stderr (newlines become spaces).
void printError(const std::string& message);
// Prints `asperity: warning: <warning>` as one line on stderr.
void printWarning(const std::string& warning);
// Prints the world's warnings (World::diagnostics) now and each later one as it comes.
void printWarnings(World& world);

}  // namespace asperity::cli
