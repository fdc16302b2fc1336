// Films and bands for every system (docs/user-guide.md, "Films and bands"),
// written once over `prime trace`: --camera-path FILE --frames FIRST-LAST
// renders frames of a camera path (src/cli/camera_path_file.h) into numbered
// pictures, skipping the frames already done; --rows FIRST-LAST renders a
// band of the picture into a piece that `prime stitch` joins. Each frame and
// piece records what made it beside its pictures (src/cli/render_record.h).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "src/cli/camera_path_file.h"
#include "src/cli/system.h"

namespace prime::cli {

// --camera-path, --frames and --rows on `prime trace`.
void addFilmOptions(CLI::App* cmd, TraceFlags& flags);

// The trace verb's action: a film's frames (--camera-path), or one render
// (a band of it with --rows) through runTrace.
int runFilmOrTrace(const CLI::App* cmd, TraceFlags& flags, const TraceFactory& make,
                   const std::string& system);

// The render's digest (RenderRecord::render): the program's version, the
// system, the settings, the frame's camera and the scene's files.
std::string renderDigest(const RecordContext& record);
// Whether every output the job names is recorded as done by this render.
bool outputsDone(const TraceJob& job, const std::string& render);
// The records of the outputs written, the band being picture rows
// band.first .. band.last.
void writeRecords(const TraceJob& job, const std::vector<std::string>& written,
                  const std::string& render, const RecordContext& record, Range band);

// An output pattern as --frames takes it: one %d conversion (%04d: four
// digits, zero-padded); `%%` is a percent sign. Throws CLI::ValidationError
// for anything else; frameName formats it.
void checkFramePattern(const std::string& pattern);
std::string frameName(const std::string& pattern, int frame);

}  // namespace prime::cli
