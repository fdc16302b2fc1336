// The Waterloo CGL package's commands. `prime trace FILE.cgl`, `prime probe
// FILE.cgl`, `prime bench FILE.cgl ...` and `prime export-pov FILE.cgl OUT`
// reach them when FILE reads as a CGL scene-description file (or with
// --format cgl); `prime export` and `prime view` reach the picture commands
// when the file is a CGL picture (.rle, .raw, or --format rle|raw).
// src/cli/main.cpp picks the system.
#pragma once
#include <string>
#include <vector>

#include "src/cli/commands.h"

namespace prime::cli::cgl {

inline constexpr const char* kTraceCommand = "cgl-trace";
inline constexpr const char* kProbeCommand = "cgl-probe";
inline constexpr const char* kBenchCommand = "cgl-bench";
inline constexpr const char* kExportPovCommand = "cgl-export-pov";
inline constexpr const char* kExportCommand = "cgl-export";
inline constexpr const char* kViewCommand = "cgl-view";
inline constexpr const char* kSplinesCommand = "cgl-splines";

void addTraceCommand(CLI::App& app, Action& action);      // cmd_trace.cpp
void addProbeCommand(CLI::App& app, Action& action);      // cmd_probe.cpp
void addBenchCommand(CLI::App& app, Action& action);      // cmd_bench.cpp
void addExportPovCommand(CLI::App& app, Action& action);  // cmd_export_pov.cpp
void addPictureCommands(CLI::App& app, Action& action);   // cmd_picture.cpp: export, view
void addSplinesCommand(CLI::App& app, Action& action);    // cmd_splines.cpp: Tables 3 and 6
// The package's utilities (Appendix 1 section 9): `prime cook OUT` and
// `prime tovector R G B`.
void addCookCommand(CLI::App& app, Action& action);      // cmd_cook.cpp
void addTovectorCommand(CLI::App& app, Action& action);  // cmd_tovector.cpp

// The package's own call statement (Appendix 2: `trace -yh 511 -d 3 -s -a 2
// scene`): its one-dash flags rewritten as this port's long options, so a
// 1985 command line works after `prime trace`. Arguments from `first` on.
void translateCallStatement(std::vector<std::string>& args, std::size_t first);

}  // namespace prime::cli::cgl
