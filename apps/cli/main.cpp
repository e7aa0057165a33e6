// The `asperity` command-line tool: one subcommand per file, registered here.
#include "cli_common.hpp"

namespace asperity::cli {
void registerRenderCommand(CLI::App& app);  // apps/cli/render_command.cpp
void registerRunCommand(CLI::App& app);     // apps/cli/run_command.cpp
void registerPatchCommand(CLI::App& app);   // apps/cli/patch_command.cpp
void registerBenchCommand(CLI::App& app);   // apps/cli/bench_command.cpp
void registerReportCommand(CLI::App& app);  // apps/cli/report_command.cpp
void registerSweepCommand(CLI::App& app);   // apps/cli/sweep_command.cpp
}  // namespace asperity::cli

int main(int argc, char** argv) {
  CLI::App app{"Asperity: friction from the appearance of surfaces (normal maps).", "asperity"};
  app.require_subcommand(1);

  // One call per subcommand, in the order `asperity --help` lists them.
  asperity::cli::registerTextureCommand(app);
  asperity::cli::registerConeCommand(app);
  asperity::cli::registerRunCommand(app);
  asperity::cli::registerSweepCommand(app);
  asperity::cli::registerPatchCommand(app);
  asperity::cli::registerRenderCommand(app);
  asperity::cli::registerBenchCommand(app);
  asperity::cli::registerReportCommand(app);

  return asperity::cli::runCli(app, argc, argv);
}
