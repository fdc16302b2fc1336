// The Waterloo CGL package's commands. The shared verbs `prime trace`,
// `probe`, `bench` and `export-pov` run its parts when the scene reads as a
// CGL scene-description file (or with --format cgl); `prime export` and
// `prime view` when the file is a CGL picture (.rle, .raw, or --format
// rle|raw). src/cli/cgl/adapter.cpp is the system's row.
#pragma once
#include <string>
#include <vector>

#include "src/cli/system.h"

namespace prime::cli::cgl {

// Its parts of the shared verbs (src/cli/system.h).
TraceFactory addTraceOptions(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags);
ProbeFactory addProbeOptions(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags);
void addBenchOptions(CLI::App* cmd, Action& action);      // cmd_bench.cpp
void addExportPovOptions(CLI::App* cmd, Action& action);  // cmd_export_pov.cpp
WalkFactory addWalkOptions(CLI::App* cmd, const std::shared_ptr<WalkFlags>& flags);  // cmd_walk.cpp
const PieceKind* pieceKind(const std::string& output);                               // stitch.cpp
// export and view of its pictures (cmd_picture.cpp): RLE or raw frames.
void addExportOptions(CLI::App* cmd, Action& action);
void addViewOptions(CLI::App* cmd, Action& action);
bool isPicture(const std::string& path, const std::string& format);

// `prime cgl-splines`: Tables 3 and 6 (cmd_splines.cpp).
void addSplinesCommand(CLI::App& app, Action& action);
// The package's utilities (Appendix 1 section 9): `prime cook OUT` and
// `prime tovector R G B`.
void addCookCommand(CLI::App& app, Action& action);      // cmd_cook.cpp
void addTovectorCommand(CLI::App& app, Action& action);  // cmd_tovector.cpp

// The package's own call statement (Appendix 2: `trace -yh 511 -d 3 -s -a 2
// scene`): its one-dash flags rewritten as this port's long options, so a
// 1985 command line works after `prime trace`. Arguments from `first` on.
void translateCallStatement(std::vector<std::string>& args, std::size_t first);

}  // namespace prime::cli::cgl
