// Options shared by the commands that show or write pictures of the emulated
// 8514/A screen (`trace`, `view`, `export`, `diff`, `palette`): palette, DAC
// conversion, screen geometry, image area, window.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "legacy_io/prime/graph_file.h"
#include "palette/prime/dac.h"
#include "palette/prime/export.h"
#include "palette/prime/graph_info.h"
#include "palette/prime/palettes.h"
#include "palette/prime/screen.h"
#include "palette/window/window_fit.h"

namespace prime::cli {

struct DisplayOptions {
  std::string palette;           // empty: the one the graph type (or the mapping) implies
  std::string dac = "round";     // 6-to-8-bit conversion
  std::string monitor = "8514";  // --monitor 8514|8503|8503-summed
  std::string area = "image";    // PNG area
  std::vector<int> at;           // --at X Y
  std::vector<int> screen;       // --screen W H (view, export)
  int zoom = 1;
  bool fullscreen = false;        // --fullscreen
  std::string scale = "integer";  // --scale integer|aspect (G23)
  bool noWindow = false;
  bool noInfo = false;                      // --no-info: ignore the graph file's companion (G8)
  std::string pngUpscaled;                  // --png-upscaled FILE
  std::vector<int> upscaleFit{3840, 2160};  // --upscale-fit W H
};

void addPaletteOption(CLI::App* cmd, DisplayOptions& o, const std::string& defaultText);
void addDacOption(CLI::App* cmd, DisplayOptions& o);
void addAreaOption(CLI::App* cmd, DisplayOptions& o, const std::string& name);
// --screen W H and --at X Y, for a graph file whose screen is not known.
void addGeometryOptions(CLI::App* cmd, DisplayOptions& o);
// --no-window, --zoom, --fullscreen and --scale.
void addWindowOptions(CLI::App* cmd, DisplayOptions& o);
display::ScaleMode scaleOf(const DisplayOptions& o);

// --png-upscaled FILE and --upscale-fit W H: an integer-upscaled copy of the
// PNG (nearest neighbour, the largest whole factor that fits W x H), as
// DOSBox Staging's upscaled screenshots.
void addUpscaleOptions(CLI::App* cmd, DisplayOptions& o);
// Writes the screen's PNG `path` (indexed: the 8514/A's 256 indices and the
// DAC as its palette) and, when --png-upscaled names one, its upscaled copy,
// both with `meta` and the palette's lines (paletteText). Returns the files
// written.
std::vector<std::string> write8514Pngs(const std::string& path, const IndexedImage8& image,
                                       PngMeta meta, const DisplayOptions& o,
                                       const std::string& paletteName);
// What an indexed PNG's palette is: "Palette" (its name) and "DAC to 8 bits"
// (the rule that made 8-bit PLTE entries of the DAC's 6-bit values).
std::vector<PngText> paletteText(const std::string& paletteName, DacTo8 how);
// What made a graph file's picture, as its companion says (the render's
// provenance; without one, the program only), for the PNGs export and the
// view window's S key write; square pixels. The palette's lines are left
// to write8514Pngs.
PngMeta companionMeta(const std::optional<GraphInfo>& info);
// The palette as a PNG names it: a built-in's name, else its description (a
// quantized palette: the same from trace and from export of its companion).
std::string paletteLabel(const Palette& palette);

// --record FILE and its clip's length, speed and frame rate (trace, view):
// the drawing kept as an animated GIF (palette/prime/drawing_record.h).
struct RecordFlags {
  std::string file;   // --record FILE.gif
  double length = 0;  // --record-length SECONDS: the clip, before its hold (0: 20 s, or as
                      // drawn when the drawing is shorter)
  double speed = 0;   // --record-speed X: drawing seconds a clip second (0: from length)
  double fps = 25;    // --record-fps N
};
void addRecordOptions(CLI::App* cmd, RecordFlags& r);
// Records the drawing of `graph` (rows timed by `rowSeconds`) into r.file
// and says what it wrote unless quiet.
void recordGraphDrawing(const RecordFlags& r, const io::GraphFile& graph, Placement at, int screenW,
                        int screenH, const Rgb8Table& colours, std::span<const double> rowSeconds,
                        const std::string& timeSource, bool quiet);

// The window's R key: the same recording into the first
// prime-recording-N.gif (N = 1, 2, ...) not taken in the current directory;
// a failure is said on stderr (the window stays).
void recordOnKey(const RecordFlags& r, const io::GraphFile& graph, Placement at, int screenW,
                 int screenH, const Rgb8Table& colours, std::span<const double> rowSeconds,
                 const std::string& timeSource);

DacTo8 dacOf(const DisplayOptions& o);
ImageArea areaOf(const DisplayOptions& o);
// The palette to show: --palette if given, else `impliedName`.
Palette paletteOf(const DisplayOptions& o, const std::string& impliedName);
// `first`, then the other built-in palettes: what the window's P key cycles.
// `first` is already on the monitor; the others are put on `o`'s.
std::vector<Palette> windowPalettes(const Palette& first, const DisplayOptions& o);
// --monitor: the palette as that display shows it (palette/prime/palettes.h).
Palette onMonitorOf(const DisplayOptions& o, Palette palette);

struct Geometry {
  int width = Screen::kWidth, height = Screen::kHeight;
  Placement at;
};
// --screen (default 1024 x 768) and --at (default: the listing's placement).
Geometry geometryOf(const DisplayOptions& o);

// --no-info (view, export).
void addInfoOption(CLI::App* cmd, DisplayOptions& o);
// The companion beside a graph file (palette/prime/graph_info.h), unless
// --no-info; a stale one is ignored with a warning on stderr (G9), a damaged
// one is an io::InputError (G8).
std::optional<GraphInfo> graphInfoFor(const DisplayOptions& o, const std::string& graphPath);
// The geometry with the companion's screen and placement where --screen and
// --at are not given (G10).
Geometry geometryOf(const DisplayOptions& o, const std::optional<GraphInfo>& info);
// --palette if given, else the companion's palette, else `impliedName` (G10).
Palette paletteOf(const DisplayOptions& o, const std::optional<GraphInfo>& info,
                  const std::string& impliedName);

// Reads a graph file, complete or cut short; says on stderr when it is partial
// and when the image does not fit the screen (beyond the listing's off-screen
// column and row).
io::GraphFilePrefix readGraphForDisplay(const std::string& path, const Geometry& g, bool quiet);

}  // namespace prime::cli
