// PRIME (O'Reilly, DCU 1991) as a system of `prime`: a scene directory of
// text inputs and Turbo C databases, traced, probed, timed and exported by
// the shared verbs with this system's parts (src/cli/prime/cmd_*.cpp); its
// graph files exported and viewed. The default system: a directory, or a
// path that is no other system's, is PRIME's.
#include "src/cli/prime/commands.h"

namespace prime::cli::prime_system {

namespace {
bool recognises(const std::string&, bool isFile, std::string_view) {
  return !isFile;
}
}  // namespace

extern const System kSystem{
    "prime",         "PRIME (1991)",      recognises,       addTraceOptions, addProbeOptions,
    addBenchOptions, addExportPovOptions, addExportOptions, addViewOptions,  nullptr,
    nullptr,         addWalkOptions,      pieceKind};

}  // namespace prime::cli::prime_system
