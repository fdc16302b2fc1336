// Malone's commands. `prime trace FILE`, `prime probe FILE`, `prime bench
// FILE ...` and `prime export-pov FILE OUT` reach them when
// FILE reads as a Malone scene (src/cli/main.cpp picks the system).
#pragma once
#include "src/cli/commands.h"

namespace prime::cli::malone {

inline constexpr const char* kTraceCommand = "malone-trace";
inline constexpr const char* kProbeCommand = "malone-probe";
inline constexpr const char* kBenchCommand = "malone-bench";
inline constexpr const char* kExportPovCommand = "malone-export-pov";

void addTraceCommand(CLI::App& app, Action& action);
void addProbeCommand(CLI::App& app, Action& action);
void addBenchCommand(CLI::App& app, Action& action);
void addExportPovCommand(CLI::App& app, Action& action);  // cmd_export_pov.cpp

}  // namespace prime::cli::malone
