// Malone's parts of the shared verbs (src/cli/system.h): `prime trace`,
// `probe`, `bench` and `export-pov` run them when the scene reads as Malone's
// numbers (or with --format malone); src/cli/malone/adapter.cpp is the row.
#pragma once
#include "src/cli/system.h"

namespace prime::cli::malone {

TraceFactory addTraceOptions(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags);
ProbeFactory addProbeOptions(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags);
void addBenchOptions(CLI::App* cmd, Action& action);      // cmd_bench.cpp
void addExportPovOptions(CLI::App* cmd, Action& action);  // cmd_export_pov.cpp
WalkFactory addWalkOptions(CLI::App* cmd, const std::shared_ptr<WalkFlags>& flags);  // cmd_walk.cpp
const PieceKind* pieceKind(const std::string& output);                               // stitch.cpp

}  // namespace prime::cli::malone
