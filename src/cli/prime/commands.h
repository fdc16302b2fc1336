// PRIME's parts of the shared verbs (src/cli/system.h); its own commands
// (model, dump, diff, palette, plate1, stress, check, new, compare) are
// in src/cli/commands.h. src/cli/prime/adapter.cpp is the system's row.
#pragma once
#include "src/cli/system.h"

namespace prime::cli {

TraceFactory addTraceOptions(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags);
ProbeFactory addProbeOptions(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags);
void addBenchOptions(CLI::App* cmd, Action& action);      // cmd_bench.cpp: time against error
void addExportPovOptions(CLI::App* cmd, Action& action);  // cmd_export_pov.cpp
void addExportOptions(CLI::App* cmd, Action& action);     // cmd_export.cpp: graph file -> PNG
void addViewOptions(CLI::App* cmd, Action& action);       // cmd_view.cpp
WalkFactory addWalkOptions(CLI::App* cmd, const std::shared_ptr<WalkFlags>& flags);  // cmd_walk.cpp
const PieceKind* pieceKind(const std::string& output);                               // stitch.cpp

}  // namespace prime::cli
