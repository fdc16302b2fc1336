// The verbs every system plugs into, each written once: `trace`, `probe`,
// `bench`, `export-pov`, `export` and `view`. A verb registers itself under
// its own name with the flags every system shares, then the chosen system's
// part (src/cli/system.h). Which system: systemFor(), from --format or the
// scene the command line names.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "legacy_io/common/output_file.h"
#include "palette/window/live_frame.h"
#include "src/cli/camera_path_file.h"
#include "src/cli/film.h"
#include "src/cli/option_values.h"
#include "src/cli/step.h"
#include "src/cli/system.h"

namespace prime::cli {

namespace {

std::string fileHead(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

std::string systemNames() {
  std::string s;
  for (const System& sys : systems()) s += (s.empty() ? "" : ", ") + std::string(sys.name);
  return s;
}

CLI::App* addVerb(CLI::App& app, const std::string& verb, const std::string& what,
                  const System& system) {
  auto* cmd = app.add_subcommand(verb, what);
  cmd->footer(systemFooter(system, verb));
  return cmd;
}

}  // namespace

// --format, on every verb: one of the systems (the one chosen, whose flags
// follow; systemFor() read it before the command line was parsed).
// The value was read by systemFor() before parsing: here it is only checked.
void addFormatOption(CLI::App* cmd, const std::string& what) {
  std::vector<std::string> names;
  for (const System& sys : systems()) names.push_back(sys.name);
  cmd->add_option_function<std::string>(
         "--format", [](const std::string&) {},
         "The " + what + "'s system: " + systemNames() +
             " (default: detected; a directory is "
             "PRIME's)")
      ->check(CLI::IsMember(names));
}

// The help's last lines: which system's flags these are, and how to see the others'.
std::string systemFooter(const System& system, const std::string& verb) {
  std::string others;
  for (const System& sys : systems())
    if (&sys != &system) others += std::string(others.empty() ? "" : "; ") + sys.title;
  const bool picture = verb == "export" || verb == "view";
  return std::string("These are the options for ") + system.title +
         (picture ? " pictures" : " scenes") + ". The other systems' " +
         (picture ? "pictures" : "scenes") + " take their own: prime " + verb + " " +
         (picture ? "PICTURE" : "SCENE") + " --help names one (" + others + ").";
}

const System* findSystem(std::string_view name) {
  for (const System& sys : systems())
    if (name == sys.name) return &sys;
  return nullptr;
}

const System& systemFor(std::string_view verb, const std::vector<std::string>& args) {
  std::string format;
  std::vector<std::string> words;  // the words that are not flags: the scene, and flags' values
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--format" && i + 1 < args.size()) {
      format = args[++i];
    } else if (a.rfind("--format=", 0) == 0) {
      format = a.substr(9);
    } else if (!a.empty() && a[0] != '-') {
      words.push_back(a);
    }
  }
  const std::span<const System> all = systems();
  if (verb == "export" || verb == "view") {  // PRIME's graph files are the default
    // The first word that names a file, else the first word.
    std::string picture = words.empty() ? std::string() : words.front();
    for (const std::string& w : words)
      if (std::filesystem::exists(w)) {
        picture = w;
        break;
      }
    for (const System& sys : all)
      if (sys.picture != nullptr && sys.picture(picture, format)) return sys;
    return all.front();
  }
  if (const System* named = findSystem(format)) return *named;
  // The scene: the first file a system reads as its own (a flag's value, such
  // as the existing picture of `-o pic.rle scene.cgl`, is not one), else the
  // first directory (PRIME's), else the first word.
  std::error_code ec;
  for (const std::string& w : words)
    if (std::filesystem::is_regular_file(w, ec)) {
      const std::string head = fileHead(w);
      for (const System& sys : all)
        if (sys.recognises(w, true, head)) return sys;
    }
  for (const std::string& w : words)
    if (std::filesystem::is_directory(w, ec))
      for (const System& sys : all)
        if (sys.recognises(w, false, {})) return sys;
  return all.front();
}

std::string rowsRenderedText(bool aborted, int rowsDone, int rowsAsked, int pictureRows) {
  if (aborted) return std::to_string(rowsDone) + " of " + std::to_string(rowsAsked) + " rows of ";
  if (rowsAsked != pictureRows)
    return std::to_string(rowsDone) + " of " + std::to_string(pictureRows) + " rows (a band) of ";
  return "";
}

// ---- trace -------------------------------------------------------------------

namespace {

// Refuses an output that cannot be written (a missing directory, a device, an
// input of the run) and two outputs that name one file (the second replaced
// the first): before the render, not after it.
void checkOutputs(const TraceJob& job) {
  std::vector<io::NamedOutput> outputs;
  for (const TraceJob::Output& out : job.outputs()) outputs.push_back({out.flag, out.path});
  io::checkOutputs(outputs);
}

}  // namespace

int runTrace(TraceJob& job, const TraceFlags& flags, const RecordContext* record, bool* skipped) {
  checkOutputs(job);
  std::optional<Step> step;
  step.emplace("reading " + job.scene());
  job.load();
  // Again now that the inputs are known: none may be an output.
  checkOutputs(job);
  const bool band = !flags.rows.empty();
  Range bandRows{0, job.pictureRows() - 1};
  if (band) {
    const Range rows = parseRange(flags.rows, "--rows", job.pictureRows() - 1);
    bandRows = rows;
    if (!flags.quantize.method.empty())
      throw CLI::ValidationError(
          "--rows",
          "--quantize chooses its palette from the whole picture, which a band does "
          "not have: render the pieces without it, stitch them (prime stitch), then "
          "quantize the whole (prime quantize)");
    job.setBand(rows.first, rows.last);
  }
  if (record != nullptr) job.setProvenance(provenanceOf(job, *record, flags.camera));
  const bool records = record != nullptr && (band || record->frame);
  const std::string render = records ? renderDigest(*record) : "";
  if (records && record->frame && outputsDone(job, render)) {
    if (skipped != nullptr) *skipped = true;
    return 0;
  }
  bool writes = job.writesWithoutOutputs();
  for (const TraceJob::Output& out : job.outputs()) writes = writes || !out.path.empty();
  if (!writes)  // said before the render, which Ctrl-C can then spare
    std::cerr << "prime: trace: no output named, so the picture will not be written (add "
              << job.outputHint() << ")\n";
  const bool quiet = job.quiet();
  LiveOptions options = flags.live;
  options.quiet = quiet;
  options.commandName = "trace";
  options.screenshot = job.provenance();
  job.configure(options);
  LiveRender live(job.frame(), options);
  step.emplace("rendering " + job.scene());
  job.render(live);
  if (job.aborted()) {
    live.closeWindow();  // ExitOnEsc: the screen goes at once
    job.abort();
    return 1;  // as the 1991 ExitOnEsc's exit(1)
  }
  step.emplace("writing the picture of " + job.scene());
  const std::vector<std::string> written = job.write();
  if (records) writeRecords(job, written, render, *record, bandRows);
  step.reset();
  if (!quiet) {
    job.summary(written);
    if (written.empty()) std::printf("wrote nothing: no output was named\n");
    // One "wrote PATH" line per file written, as every command.
    for (const std::string& f : written) std::printf("wrote %s\n", f.c_str());
  }
  if (flags.timings) job.timings();
  std::fflush(stdout);
  char status[64];
  std::snprintf(status, sizeof status, "done in %.2f s - Esc to close", job.seconds());
  live.waitForEsc(status);
  return 0;
}

void addTraceVerb(CLI::App& app, Action& action, const System& system) {
  auto* cmd = addVerb(app, "trace",
                      "Render a scene of any system (a PRIME scene directory, a Malone or a CGL "
                      "scene file); --png OUT.png writes the picture as the system showed it",
                      system);
  auto flags = std::make_shared<TraceFlags>();
  addFormatOption(cmd, "scene");
  cmd->add_option("--png", flags->png,
                  "Write the picture as the system itself showed or wrote it, as PNG (PRIME: the "
                  "8514/A screen; Malone: its PPM; CGL: its frame buffer)")
      ->check(outputName());
  cmd->add_option("--true-color-png", flags->trueColourPng,
                  "Write the render before any palette, as PNG (true colour)")
      ->check(outputName());
  cmd->add_option("--png-8514", flags->png8514,
                  "Write the picture as PRIME's IBM 8514/A (1991) would have shown it, as PNG "
                  "(for PRIME the same as --png)")
      ->check(outputName());
  addQuantizeOptions(cmd, flags->quantize, "the --png picture");
  cmd->add_option("--threads", flags->threads, "Render threads (default: all cores)")
      ->check(CLI::Range(0, 1024));
  cmd->add_flag("-q,--quiet", flags->quiet, "No progress, no report and no summary");
  cmd->add_flag("--timings", flags->timings,
                "Print the seconds spent reading, building and rendering")
      ->group("");  // for the benchmark scripts
  auto live = std::shared_ptr<LiveOptions>(flags, &flags->live);
  addLiveWindowOptions(cmd, live, true);
  addFilmOptions(cmd, *flags);
  const TraceFactory make = system.trace(cmd, flags);
  cmd->callback([cmd, flags, make, &action, name = std::string(system.name)] {
    action = [cmd, flags, make, name] { return runFilmOrTrace(cmd, *flags, make, name); };
  });
}

// ---- probe -------------------------------------------------------------------

void addProbeVerb(CLI::App& app, Action& action, const System& system) {
  auto* cmd = addVerb(app, "probe",
                      "Explain one pixel of any system's scene: its whole ray tree, the tests, "
                      "hits, lights and shading (--json for machines)",
                      system);
  auto flags = std::make_shared<ProbeFlags>();
  addFormatOption(cmd, "scene");
  cmd->add_option(
         "--pixel", flags->pixel,
         "Column X and row Y of the picture `prime trace` writes, 0-based from its top-left")
      ->expected(2)
      ->allow_extra_args(false);
  cmd->add_flag("--json", flags->json,
                "Print JSON: one object with an events array (docs/user-guide.md, probe)");
  cmd->add_option("--overlay", flags->overlay,
                  "Also write the picture with this pixel's ray tree drawn over it, as PNG "
                  "(needs --pixel)")
      ->type_name("OUT.png")
      ->check(outputName());
  const ProbeFactory make = system.probe(cmd, flags);
  cmd->callback([flags, make, &action] {
    action = [flags, make] {
      if (!flags->overlay.empty()) {
        if (flags->pixel.size() != 2)
          throw CLI::ValidationError("--overlay", "draws a pixel's tree: give --pixel X Y");
        io::checkOutputPath(flags->overlay);
      }
      const ProbeReport r = make();
      if (flags->json)
        std::cout << r.json << "\n";
      else
        std::cout << r.text;
      if (!r.written.empty() && !flags->json) std::cout << "wrote " << r.written << "\n";
      return 0;
    };
  });
}

// ---- the verbs whose whole command is the system's ----------------------------

namespace {
CLI::App* addWholeVerb(CLI::App& app, Action& action, const System& system, const std::string& verb,
                       const std::string& what, void (*part)(CLI::App*, Action&)) {
  auto* cmd = addVerb(app, verb, what, system);
  // export and view take a picture, whose format (--format) is the system's
  // own option; elsewhere --format was read by systemFor() and is only checked.
  if (verb != "export" && verb != "view") addFormatOption(cmd, "scene");
  if (part == nullptr) {
    cmd->callback([&action, verb, title = std::string(system.title)] {
      action = [verb, title] {
        std::cerr << "prime: " << verb << ": " << title << " has no " << verb << " (prime " << verb
                  << " --help)\n";
        return 2;
      };
    });
    return cmd;
  }
  part(cmd, action);
  return cmd;
}
}  // namespace

void addBenchVerb(CLI::App& app, Action& action, const System& system) {
  CLI::App* cmd = addWholeVerb(app, action, system, "bench",
                               "Time scenes: a system's scene files in one table (Malone's, or "
                               "CGL's); PRIME's run time against error study",
                               system.bench);
  // One table is one system's: a scene file another system reads is said to
  // be one, not misread as this system's.
  cmd->parse_complete_callback([cmd, &system] {
    std::error_code ec;
    for (const CLI::Option* opt : cmd->get_options())
      if (opt->get_positional())
        for (const std::string& w : opt->results()) {
          if (!std::filesystem::is_regular_file(w, ec)) continue;
          const std::string head = fileHead(w);
          if (system.recognises(w, true, head)) continue;
          for (const System& other : systems())
            if (&other != &system && other.recognises(w, true, head))
              throw CLI::ValidationError(
                  opt->get_name(), w + " is a scene of " + other.title +
                                       ", and this bench times scenes of " + system.title +
                                       ": one table is one system's (run prime bench once for "
                                       "each)");
        }
  });
}

void addExportPovVerb(CLI::App& app, Action& action, const System& system) {
  addWholeVerb(app, action, system, "export-pov",
               "Write a scene in POV-Ray 3.7's language, for a side-by-side render",
               system.exportPov);
}

void addExportVerb(CLI::App& app, Action& action, const System& system) {
  addWholeVerb(app, action, system, "export",
               "Convert a picture file to PNG: a PRIME graph file through a palette, a CGL RLE or "
               "raw picture",
               system.exportPicture);
}

void addViewVerb(CLI::App& app, Action& action, const System& system) {
  addWholeVerb(app, action, system, "view",
               "Show a picture file in a window: a PRIME graph file on the emulated 8514/A, a CGL "
               "RLE or raw picture",
               system.viewPicture);
}

}  // namespace prime::cli
