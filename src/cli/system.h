// What a system gives the shared verbs of `prime` (src/cli/verbs.cpp): a
// command-level contract, not a renderer base class. Each verb (`trace`,
// `probe`, `bench`, `export-pov`, `export`, `view`) is written once: it
// registers the flags every system shares, with one meaning, then asks the
// chosen system's adapter for its own flags and for the work to do. Shapes,
// shading, tracers and cameras stay each system's own.
//
// A fourth system is one more adapter (src/cli/<system>/adapter.cpp) and one
// row in systems() (src/cli/systems.cpp).
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "palette/png_image.h"
#include "src/cli/commands.h"
#include "src/cli/live_render.h"
#include "src/cli/quantize_options.h"
#include "src/cli/walk.h"

namespace prime::display {
class LiveFrame;
}

namespace prime::cli {

// ---- trace -----------------------------------------------------------------

// The flags `prime trace` has for every system, with one meaning.
struct TraceFlags {
  std::string png;            // --png: the picture as the system itself showed or wrote it
  std::string trueColourPng;  // --true-color-png: the render before any palette
  std::string png8514;        // --png-8514: as PRIME's IBM 8514/A would show it
  QuantizeOptions quantize;   // --quantize, --dither, --colours: the --png picture
  int threads = 0;            // --threads (0: every core)
  bool quiet = false;         // -q
  bool timings = false;       // --timings (hidden: the benchmark scripts')
  LiveOptions live;           // --no-window --zoom --fullscreen --scale --pace --no-wait
  // Films and bands (docs/user-guide.md, "Films and bands").
  std::string cameraPath;  // --camera-path FILE: every frame's camera
  std::string frames;      // --frames FIRST-LAST of the path
  std::string rows;        // --rows FIRST-LAST of the picture, from its top
  // Given by the system's part: its camera flags (each frame's camera goes
  // there) and the names of its own outputs (patterns under --frames).
  CameraFlags* camera = nullptr;
  std::vector<std::string*> ownOutputs;
  // Flags whose work the first frame of a film does for all (PRIME's --model:
  // the databases are built once; a second build would write the files the
  // first frame read): cleared after it.
  std::vector<bool*> firstFrameOnly;
};

// One render of one system, driven by the shared skeleton (runTrace): check
// the outputs, load, open the live window, render, then either the abort
// path or the outputs and the summary.
class TraceJob {
 public:
  virtual ~TraceJob() = default;
  // Every file the job may write, with the flag that names it ("" for none:
  // not written). Checked before the scene is read and again after, when its
  // inputs are known: no output may replace an input, no two may name one file.
  struct Output {
    std::string flag;  // "--png", or what the file is ("the graph file's .partial")
    std::string path;
  };
  virtual std::vector<Output> outputs() const = 0;
  // True when the job writes a picture whatever outputs() names (PRIME's
  // graph file); else a render with no output named writes nothing, and says so.
  virtual bool writesWithoutOutputs() const { return false; }
  // The flags that would write the picture, for that message ("--png OUT.png").
  virtual std::string outputHint() const { return "--png OUT.png"; }
  // The scene file or directory, as the command line named it.
  virtual std::string scene() const = 0;
  // Reads and builds the scene; prints the system's own report unless quiet.
  virtual void load() = 0;
  // False when the scene itself asks for quiet (CGL's quiet parameter).
  virtual bool quiet() const = 0;
  // What the window shows, and the system's own window settings (caption,
  // keys, the frame row of the render's row 0). After load().
  virtual display::LiveFrame& frame() = 0;
  virtual void configure(LiveOptions& options) const = 0;
  // The render, through live.run() with live's abort flag and progress.
  virtual void render(LiveRender& live) = 0;
  virtual bool aborted() const = 0;
  // An aborted render: what it leaves behind, and its messages.
  virtual void abort() = 0;
  // A finished render: writes the outputs; returns the files written, in order.
  virtual std::vector<std::string> write() = 0;
  // The system's counters; `written` as write() returned it.
  virtual void summary(const std::vector<std::string>& written) const = 0;
  virtual void timings() const {}  // --timings
  virtual double seconds() const = 0;
  // The picture's rows (after load()): what --rows counts, from the top.
  virtual int pictureRows() const = 0;
  // The rows of the file `output` names (its flag) that picture rows
  // first .. last fill, and the file's rows: the same rows unless the file
  // places the picture on a screen (PRIME's --png). After load().
  struct FileRows {
    int first = 0, last = -1, rows = 0;
  };
  virtual FileRows fileRows(const std::string& output, int first, int last) const {
    (void)output;
    return {first, last, pictureRows()};
  }
  // --rows: only picture rows first .. last are rendered (render() hands
  // them to the system's render as PictureCallbacks::firstRow, lastRow).
  void setBand(int first, int last) {
    firstRow_ = first;
    lastRow_ = last;
  }
  // The system's own lines of what made the picture (PRIME: the profile, the
  // palette, the DAC's rule, the --fix ids), after load(): provenance()
  // adds them to the shared ones.
  virtual std::vector<PngText> describe() const { return {}; }
  // What the picture files say made them (every PNG's tEXt and pHYs, PRIME's
  // companion): set by runTrace after load(), before render().
  void setProvenance(PngMeta meta) { provenance_ = std::move(meta); }
  const PngMeta& provenance() const { return provenance_; }

 protected:
  int firstRow_ = 0, lastRow_ = -1;
  PngMeta provenance_;
};

using TraceFactory = std::function<std::unique_ptr<TraceJob>()>;

// ---- probe -----------------------------------------------------------------

// The flags `prime probe` has for every system.
struct ProbeFlags {
  std::vector<int> pixel;  // --pixel X Y: column X, row Y from the top of what `trace` writes
  bool json = false;       // --json
  std::string overlay;     // --overlay OUT.png: the ray tree drawn over the picture
};

// One pixel explained: the human-readable text and the same as one JSON
// object (schema in docs/user-guide.md, "probe"): "scene", "where",
// "events" [{"depth", "event", "data"}], "color", "rays", and the system's
// own fields (PRIME's "profile", "index", "paletteRgb" at the top level, as
// they always were; "malone" and "cgl" objects for the others).
struct ProbeReport {
  std::string text;
  std::string json;
  std::string written;  // the overlay written (--overlay), "" for none
};

using ProbeFactory = std::function<ProbeReport()>;

// ---- stitch ------------------------------------------------------------------

// A picture file as rows of equal size, for `prime stitch`: the bytes before
// the rows, then `rows` rows of `rowBytes` bytes (the file's own bytes where
// the format is plain rows; decoded where it is not).
struct RowPicture {
  std::vector<std::uint8_t> head;
  std::size_t rowBytes = 0;
  int rows = 0;
  std::vector<std::uint8_t> pixels;  // rows * rowBytes
};

// One kind of picture file as stitch reads and writes it. write() writes
// `path` all or nothing; `piece` is one of the pieces (PRIME copies its
// companion's settings). Both throw io::InputError naming the file.
struct PieceKind {
  RowPicture (*read)(const std::string& path);
  void (*write)(const std::string& path, const RowPicture& picture, const std::string& piece);
};

// ---- the systems -------------------------------------------------------------

struct System {
  const char* name;   // as --format takes it: prime, malone, cgl
  const char* title;  // for help and messages: "PRIME (1991)"
  // Whether `scene` is this system's (`head`: the first 4 KiB of a file; empty
  // for a directory).
  bool (*recognises)(const std::string& scene, bool isFile, std::string_view head);
  // Each verb's system part: adds the system's own flags and arguments to the
  // verb's command (the shared flags are on it) and returns what the verb
  // runs once the command line is parsed. Null: the system has no such verb.
  TraceFactory (*trace)(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags);
  ProbeFactory (*probe)(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags);
  // The whole of bench (Malone's and CGL's through the shared table of
  // src/cli/bench_table.h; PRIME's is its run time against error study) and of
  // export-pov SCENE OUT (each system's exporter is its own).
  void (*bench)(CLI::App* cmd, Action& action);
  void (*exportPov)(CLI::App* cmd, Action& action);
  // export PICTURE OUT and view PICTURE, for the system's own picture files.
  void (*exportPicture)(CLI::App* cmd, Action& action);
  void (*viewPicture)(CLI::App* cmd, Action& action);
  // Whether `path` is one of the system's picture files (export, view); null
  // for PRIME, whose graph files are what any other file is taken for.
  bool (*picture)(const std::string& path, const std::string& format);
  // The system's own way of writing a command line, rewritten to its flags
  // before parsing (CGL's 1985 call statement: `trace -yh 511 -d 3 scene`);
  // arguments from `first` on. Null: none.
  void (*callStatement)(std::vector<std::string>& args, std::size_t first);
  // walk's system part (src/cli/walk.h): the system's own flags (its camera
  // flags among them) and the scene to walk. Null: the system has no walk.
  WalkFactory (*walk)(CLI::App* cmd, const std::shared_ptr<WalkFlags>& flags);
  // stitch's system part: the kind of the pieces its own output flag
  // (RenderRecord::output: "--out", "--ppm", "--rle") writes; null for a
  // flag that is not its own (the PNGs are every system's). Null: none.
  const PieceKind* (*pieceKind)(const std::string& output);
};

// Every system, PRIME first (the default for a directory or nothing).
std::span<const System> systems();
const System* findSystem(std::string_view name);

// The system a verb's command line names: --format, else the system of the
// first file a system reads as its scene, else of the first directory (PRIME),
// else PRIME. For export and view, the system
// whose picture the file is.
const System& systemFor(std::string_view verb, const std::vector<std::string>& args);

// A trace summary's rows, before "W x H pixels": after an abort "R of N rows
// of " (N: the rows asked for), for a band (--rows) "R of H rows (a band)
// of ", for the whole picture nothing.
std::string rowsRenderedText(bool aborted, int rowsDone, int rowsAsked, int pictureRows);

// The verbs every system plugs into, as the command table registers them.
void addTraceVerb(CLI::App& app, Action& action, const System& system);
void addProbeVerb(CLI::App& app, Action& action, const System& system);
void addBenchVerb(CLI::App& app, Action& action, const System& system);
void addExportPovVerb(CLI::App& app, Action& action, const System& system);
void addExportVerb(CLI::App& app, Action& action, const System& system);
void addViewVerb(CLI::App& app, Action& action, const System& system);
void addWalkVerb(CLI::App& app, Action& action, const System& system);  // src/cli/walk.cpp
void addPathVerb(CLI::App& app, Action& action, const System& system);  // src/cli/film.cpp

// For the verbs: --format (checked; systemFor() read it before parsing), and
// the help's last lines naming whose options these are.
void addFormatOption(CLI::App* cmd, const std::string& what);
std::string systemFooter(const System& system, const std::string& verb);

// What a film's frame or a band's piece records beside its pictures
// (src/cli/render_record.h); null for a plain render.
struct RecordContext {
  std::string system;
  std::string settings;  // every setting that changes pixels, as text
  std::string camera;    // the frame's camera, as flags ("" for none)
  std::optional<int> frame;
  std::vector<std::string> notInputs;  // files read that are not the scene's (the path)
};

// What made a picture, for its files (docs/user-guide.md, "What a picture
// says about itself"): the program and its version, the system, the scene's
// name (its last path component: the same on every machine) and the XXH3 of
// every file it read, the job's own lines (describe()), every setting that
// changes pixels, and a film frame's camera; square pixels (pHYs 1:1). One
// line each, no time: the same render gives the same bytes.
// A scene's name as a picture gives it: its last path component ("plate2"
// for "scenes/prime/plate2/"), the same on every machine.
std::string sceneNameOf(std::string scene);
// `camera`: the system's camera flags (TraceFlags::camera), or null.
PngMeta provenanceOf(const TraceJob& job, const RecordContext& record,
                     const CameraFlags* camera = nullptr);

// The shared skeleton of `prime trace`. With `record`, a frame whose
// outputs are recorded as done is skipped (returns 0 and sets *skipped).
int runTrace(TraceJob& job, const TraceFlags& flags, const RecordContext* record = nullptr,
             bool* skipped = nullptr);

// `prime stitch OUT PIECE...` (src/cli/stitch.cpp).
void addStitchCommand(CLI::App& app, Action& action);

}  // namespace prime::cli
