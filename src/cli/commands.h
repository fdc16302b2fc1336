// Each subcommand of `prime` lives in its own cmd_*.cpp and registers itself
// on the CLI11 app; the action runs after parsing and returns the exit code.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace prime::cli {

using Action = std::function<int()>;

// Registration functions; each adds one subcommand and sets `action` when it
// is the one chosen.
void addModelCommand(CLI::App& app, Action& action);
void addDumpCommand(CLI::App& app, Action& action);
void addTraceCommand(CLI::App& app, Action& action);
void addProbeCommand(CLI::App& app, Action& action);

}  // namespace prime::cli
