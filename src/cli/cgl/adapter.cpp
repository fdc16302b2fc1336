// The Waterloo CGL package (1985) as a system of `prime`: a scene-description
// file (legacy_io/cgl) traced, probed, timed and exported by the shared verbs
// with this system's parts, its RLE and raw pictures exported and viewed, and
// its own call statement (Appendix 2) read after `prime trace`, `probe` and
// `bench`.
#include "legacy_io/cgl/scene_file.h"
#include "src/cli/cgl/commands.h"

namespace prime::cli::cgl {

namespace {
bool recognises(const std::string&, bool isFile, std::string_view head) {
  return isFile && prime::cgl::looksLikeCgl(std::string(head));
}
}  // namespace

extern const System kSystem{"cgl",
                            "the Waterloo CGL package (1985)",
                            recognises,
                            addTraceOptions,
                            addProbeOptions,
                            addBenchOptions,
                            addExportPovOptions,
                            addExportOptions,
                            addViewOptions,
                            isPicture,
                            translateCallStatement,
                            addWalkOptions,
                            pieceKind};

}  // namespace prime::cli::cgl
