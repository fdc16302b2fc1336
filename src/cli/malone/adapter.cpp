// Malone's ray tracer (1995) as a system of `prime`: a scene file of
// numbers (legacy_io/malone), traced, probed, timed and exported by the
// shared verbs with this system's parts (src/cli/malone/cmd_*.cpp).
#include "legacy_io/malone/input.h"
#include "src/cli/malone/commands.h"

namespace prime::cli::malone {

namespace {
bool recognises(const std::string&, bool isFile, std::string_view head) {
  return isFile && prime::malone::looksLikeMalone(std::string(head));
}
}  // namespace

extern const System kSystem{"malone",
                            "Malone's ray tracer (1995)",
                            recognises,
                            addTraceOptions,
                            addProbeOptions,
                            addBenchOptions,
                            addExportPovOptions,
                            nullptr,
                            nullptr,
                            nullptr,
                            nullptr,
                            addWalkOptions,
                            pieceKind};

}  // namespace prime::cli::malone
