// The `asperity` command-line tool: one subcommand per file, registered here.
#include "cli_common.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Asperity: friction from the appearance of surfaces (normal maps).", "asperity"};
  app.require_subcommand(1);

  // One call per subcommand, in the order `asperity --help` lists them.
  asperity::cli::registerTextureCommand(app);
  asperity::cli::registerConeCommand(app);

  return asperity::cli::runCli(app, argc, argv);
}
