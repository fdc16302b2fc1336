// prime: the command-line front end. Every error a user can cause (bad scene
// data, missing files) is reported on stderr as "prime: <file:line: ...>" with
// exit status 1; usage errors exit with CLI11's status (106 and friends).
#include <iostream>

#include "legacy_io/common/error.h"
#include "src/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"PRIME, revived: the 1991 PhotoRealistic Image Modelling Environment"};
  app.require_subcommand(1);
  prime::cli::Action action;
  prime::cli::addModelCommand(app, action);
  prime::cli::addDumpCommand(app, action);
  prime::cli::addTraceCommand(app, action);
  prime::cli::addProbeCommand(app, action);
  prime::cli::addViewCommand(app, action);
  prime::cli::addExportCommand(app, action);
  prime::cli::addDiffCommand(app, action);
  prime::cli::addPaletteCommand(app, action);
  prime::cli::addExportPovCommand(app, action);
  prime::cli::addBenchCommand(app, action);
  prime::cli::addPlate1Command(app, action);
  prime::cli::addStressCommand(app, action);
  CLI11_PARSE(app, argc, argv);
  try {
    return action ? action() : 0;
  } catch (const prime::io::InputError& e) {
    std::cerr << "prime: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "prime: error: " << e.what() << "\n";
    return 1;
  }
}
