// Malone's commands. `prime trace FILE` and `prime probe FILE` reach them when
// FILE reads as a Malone scene (src/cli/main.cpp picks the system).
#pragma once
#include "src/cli/commands.h"

namespace prime::cli::malone {

inline constexpr const char* kTraceCommand = "malone-trace";
inline constexpr const char* kProbeCommand = "malone-probe";

void addTraceCommand(CLI::App& app, Action& action);
void addProbeCommand(CLI::App& app, Action& action);

}  // namespace prime::cli::malone
