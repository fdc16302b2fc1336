// Each subcommand of `prime` lives in its own cmd_*.cpp and registers itself
// on the CLI11 app; the action runs after parsing and returns the exit code.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace prime::cli {

using Action = std::function<int()>;

// Registration functions; each adds one subcommand and sets `action` when it
// is the one chosen. The verbs every system shares (trace, probe, bench,
// export-pov, export, view) are in src/cli/system.h.
void addModelCommand(CLI::App& app, Action& action);
void addDumpCommand(CLI::App& app, Action& action);
void addDiffCommand(CLI::App& app, Action& action);      // cmd_diff.cpp
void addPaletteCommand(CLI::App& app, Action& action);   // cmd_palette.cpp
void addErrataCommand(CLI::App& app, Action& action);    // cmd_errata.cpp
void addPlate1Command(CLI::App& app, Action& action);    // cmd_plate1.cpp
void addStressCommand(CLI::App& app, Action& action);    // cmd_stress.cpp
void addQuantizeCommand(CLI::App& app, Action& action);  // cmd_quantize.cpp (every system's PNG)
void addFilmCommand(CLI::App& app, Action& action);      // cmd_film.cpp (PNG frames: GIF, video)
void addCheckCommand(CLI::App& app, Action& action);     // cmd_check.cpp
void addNewCommand(CLI::App& app, Action& action);       // cmd_new.cpp
void addCompareCommand(CLI::App& app, Action& action);   // cmd_compare.cpp

}  // namespace prime::cli
