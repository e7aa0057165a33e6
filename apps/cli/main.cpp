// The `asperity` command-line tool: one subcommand per file (apps/cli/<name>_command.cpp).
#include "cli_common.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Asperity: friction from the appearance of surfaces (normal maps).", "asperity"};
  app.require_subcommand(1);
  asperity::cli::registerAllCommands(app);
  return asperity::cli::runCli(app, argc, argv);
}
