#include "src/cli/prime/display_options.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "palette/prime/drawing_record.h"

namespace prime::cli {

void addPaletteOption(CLI::App* cmd, DisplayOptions& o, const std::string& defaultText) {
  cmd->add_option(
      "--palette", o.palette,
      "Palette: listing, plate3, vga, or a palette file (docs/prime/palette.md); default: " +
          defaultText);
}

void addDacOption(CLI::App* cmd, DisplayOptions& o) {
  cmd->add_option("--dac", o.dac,
                  "How the 6-bit DAC values become 8-bit: round (default), replicate, truncate")
      ->check(CLI::IsMember({"round", "replicate", "truncate"}));
  cmd->add_option("--monitor", o.monitor,
                  "The display the 8514/A drove: 8514 (the colour display; default), 8503 (the "
                  "monochrome display: the green signal as grey), 8503-summed (greys summed "
                  "30/59/11 as the VGA BIOS did, for comparison)")
      ->check(CLI::IsMember({"8514", "8503", "8503-summed"}));
}

Palette onMonitorOf(const DisplayOptions& o, Palette palette) {
  return onMonitor(std::move(palette), monitorFromName(o.monitor).value_or(Monitor::Colour8514));
}

void addAreaOption(CLI::App* cmd, DisplayOptions& o, const std::string& name) {
  cmd->add_option(
         name, o.area,
         "PNG area: image (the part of the screen the picture covers; default), screen (all "
         "1024x768), file (every pixel in the graph file)")
      ->check(CLI::IsMember({"image", "screen", "file"}));
}

void addGeometryOptions(CLI::App* cmd, DisplayOptions& o) {
  cmd->add_option("--screen", o.screen, "Emulated screen size W H (default: 1024 768, the 8514/A)")
      ->expected(2)
      ->allow_extra_args(false);
  cmd->add_option("--at", o.at,
                  "Screen position X Y of the file's first pixel (default: where RayTrace.c drew, "
                  "AssignScrPts(0.66, 0, ...): 675 0)")
      ->expected(2)
      ->allow_extra_args(false);
}

void addWindowOptions(CLI::App* cmd, DisplayOptions& o) {
  cmd->add_flag("--no-window", o.noWindow,
                "Do not open a window (also the case when there is no DISPLAY)");
  cmd->add_option("--zoom", o.zoom,
                  "Window zoom, an integer 1..8, reduced to fit the display (keys + and - change "
                  "it)")
      ->check(CLI::Range(1, 8));
  cmd->add_flag("--fullscreen", o.fullscreen, "Show the picture fullscreen (key F11 toggles)");
  cmd->add_option("--scale", o.scale,
                  "How a fullscreen or resized window scales the picture: integer (the largest "
                  "whole factor, black borders; default) or aspect (fills one side, nearest "
                  "neighbour)")
      ->check(CLI::IsMember({"integer", "aspect"}));
}

display::ScaleMode scaleOf(const DisplayOptions& o) {
  return o.scale == "aspect" ? display::ScaleMode::Aspect : display::ScaleMode::Integer;
}

void addUpscaleOptions(CLI::App* cmd, DisplayOptions& o) {
  cmd->add_option("--png-upscaled", o.pngUpscaled,
                  "Also write an integer-upscaled copy of the PNG (nearest neighbour, the "
                  "largest whole factor that fits --upscale-fit)")
      ->type_name("FILE");
  cmd->add_option("--upscale-fit", o.upscaleFit,
                  "The size the upscaled copy must fit, W H (default 3840 2160)")
      ->expected(2)
      ->check(CLI::Range(1, 65535));
}

std::vector<PngText> paletteText(const std::string& paletteName, DacTo8 how) {
  return {{"Palette", paletteName + " (the IBM 8514/A DAC, 6 bits a channel)"},
          {"DAC to 8 bits", std::string(dacTo8Rule(how))}};
}

PngMeta companionMeta(const std::optional<GraphInfo>& info) {
  PngMeta meta;
  meta.aspectX = meta.aspectY = 1;
  if (!info) {
    meta.text.push_back({"Software", std::string("prime ") + PRIME_VERSION});
    return meta;
  }
  for (const auto& [key, value] : info->text)
    if (key != "Palette" && key != "DAC to 8 bits") meta.text.push_back({key, value});
  return meta;
}

std::string paletteLabel(const Palette& palette) {
  // A palette file may keep a built-in's name (`prime palette listing >
  // my.pal` writes "name listing"): with other colours it is the file's.
  const std::optional<Palette> builtin = findBuiltinPalette(palette.name);
  const bool edited =
      palette.description.rfind("user palette ", 0) == 0 && builtin && builtin->dac != palette.dac;
  if ((builtin && !edited) || palette.description.empty()) return palette.name;
  return palette.description;
}

std::vector<std::string> write8514Pngs(const std::string& path, const IndexedImage8& image,
                                       PngMeta meta, const DisplayOptions& o,
                                       const std::string& paletteName) {
  for (PngText& t : paletteText(paletteName, dacOf(o))) meta.text.push_back(std::move(t));
  std::vector<std::string> written;
  if (!path.empty()) {
    writeIndexedPng(path, image, meta);
    written.push_back(path);
  }
  if (!o.pngUpscaled.empty()) {
    const int fitW = o.upscaleFit[0], fitH = o.upscaleFit[1];
    const int k = fitFactor(image.width, image.height, fitW, fitH);
    const std::string box = std::to_string(fitW) + " x " + std::to_string(fitH);
    const bool fits = image.width <= fitW && image.height <= fitH;
    if (!fits)
      std::cerr << "prime: --upscale-fit " + box + ": the picture (" + std::to_string(image.width) +
                       " x " + std::to_string(image.height) + ") is larger even at 1 x 1; " +
                       o.pngUpscaled + " is written at 1 x 1, the same pixels as the PNG\n";
    meta.text.push_back(
        {"Upscaled", std::to_string(k) + " x " + std::to_string(k) + ", nearest neighbour " +
                         (fits ? "(the largest whole factor that fits " + box + ")"
                               : "(1 x 1: the picture is larger than " + box + ")")});
    writeIndexedPng(o.pngUpscaled, upscale(image, k), meta);
    written.push_back(o.pngUpscaled);
  }
  return written;
}

void addRecordOptions(CLI::App* cmd, RecordFlags& r) {
  cmd->add_option("--record", r.file,
                  "Keep the drawing: the screen as it was drawn, pixel by pixel, as an animated "
                  "GIF (timed by --pace; without it by the 1991 estimate), sped up to "
                  "--record-length")
      ->type_name("FILE.gif");
  cmd->add_option("--record-length", r.length,
                  "The recording's length in seconds, the final screen's 3 s hold apart "
                  "(default: 20, or as drawn when the drawing is shorter)")
      ->check(CLI::Range(0.1, 86400.0));
  cmd->add_option("--record-speed", r.speed,
                  "Instead of a length: the drawing's seconds a second of the recording (1: as "
                  "drawn)")
      ->check(CLI::Range(1e-3, 1e9));
  // At most 50: browsers show a GIF frame of under 2 hundredths of a second
  // for 10, which would slow a faster recording fivefold.
  cmd->add_option("--record-fps", r.fps,
                  "The recording's frames a second at most, 1..50 (default 25)")
      ->check(CLI::Range(1.0, 50.0));
}

void recordGraphDrawing(const RecordFlags& r, const io::GraphFile& graph, Placement at, int screenW,
                        int screenH, const Rgb8Table& colours, std::span<const double> rowSeconds,
                        const std::string& timeSource, bool quiet) {
  DrawingRecordOptions o;
  o.fps = r.fps;
  const double total = drawingSeconds(rowSeconds);
  o.speed = r.speed > 0    ? r.speed
            : r.length > 0 ? std::max(total / r.length, 1e-3)
                           : std::max(total / 20.0, 1.0);  // never slower than drawn
  const DrawingRecordSummary done =
      recordDrawing(r.file, graph, at, screenW, screenH, colours, rowSeconds, o);
  if (quiet) return;
  char line[320];
  std::snprintf(line, sizeof line,
                "recorded %s: %d frames, the drawing's %.0f s (%s) at %.4g x in a %.1f s clip "
                "(the final screen held 3 s)\n",
                r.file.c_str(), done.frames, done.drawingSeconds, timeSource.c_str(), o.speed,
                done.clipSeconds);
  std::fputs(line, stdout);
}

void recordOnKey(const RecordFlags& r, const io::GraphFile& graph, Placement at, int screenW,
                 int screenH, const Rgb8Table& colours, std::span<const double> rowSeconds,
                 const std::string& timeSource) {
  RecordFlags key = r;
  for (int n = 1;; ++n) {
    key.file = "prime-recording-" + std::to_string(n) + ".gif";
    std::error_code ec;
    if (!std::filesystem::exists(key.file, ec)) break;
  }
  try {
    recordGraphDrawing(key, graph, at, screenW, screenH, colours, rowSeconds, timeSource, false);
    std::fflush(stdout);
  } catch (const std::exception& e) {
    std::cerr << "prime: recording failed: " << e.what() << "\n";
  }
}

DacTo8 dacOf(const DisplayOptions& o) {
  return dacTo8FromName(o.dac).value_or(kDefaultDacTo8);
}

ImageArea areaOf(const DisplayOptions& o) {
  return imageAreaFromName(o.area).value_or(ImageArea::Image);
}

Palette paletteOf(const DisplayOptions& o, const std::string& impliedName) {
  return onMonitorOf(o, resolvePalette(o.palette.empty() ? impliedName : o.palette));
}

std::vector<Palette> windowPalettes(const Palette& first, const DisplayOptions& o) {
  std::vector<Palette> all{first};
  for (const auto& name : builtinPaletteNames()) {
    Palette p = onMonitorOf(o, *findBuiltinPalette(name));
    if (p.name != first.name) all.push_back(std::move(p));
  }
  return all;
}

Geometry geometryOf(const DisplayOptions& o) {
  Geometry g;
  if (o.screen.size() == 2) {
    g.width = o.screen[0];
    g.height = o.screen[1];
  }
  g.at = o.at.size() == 2 ? Placement{o.at[0], o.at[1]} : listingPlacement(g.width, g.height);
  return g;
}

void addInfoOption(CLI::App* cmd, DisplayOptions& o) {
  cmd->add_flag("--no-info", o.noInfo,
                "Ignore the companion file FILE.info (screen, placement, palette) beside the graph "
                "file");
}

std::optional<GraphInfo> graphInfoFor(const DisplayOptions& o, const std::string& graphPath) {
  if (o.noInfo) return std::nullopt;
  const std::vector<std::uint8_t> bytes =
      io::readInputFile(graphPath, {io::kDefaultInputCap, "a PRIME graph file", ""});
  FoundGraphInfo found = findGraphInfo(graphPath, bytes);
  if (!found.stale.empty()) std::cerr << "prime: warning: " << found.stale << "\n";
  return std::move(found.info);
}

Geometry geometryOf(const DisplayOptions& o, const std::optional<GraphInfo>& info) {
  if (!info) return geometryOf(o);
  DisplayOptions withInfo = o;
  if (withInfo.screen.size() != 2) withInfo.screen = {info->screenWidth, info->screenHeight};
  if (withInfo.at.size() != 2) withInfo.at = {info->at.left, info->at.top};
  return geometryOf(withInfo);
}

Palette paletteOf(const DisplayOptions& o, const std::optional<GraphInfo>& info,
                  const std::string& impliedName) {
  if (o.palette.empty() && info) return onMonitorOf(o, info->palette);
  return paletteOf(o, impliedName);
}

io::GraphFilePrefix readGraphForDisplay(const std::string& path, const Geometry& g, bool quiet) {
  io::GraphFilePrefix f = io::readGraphFilePrefix(path);
  // G30: only the .partial file an aborted trace leaves may stop early; a
  // short graph_scr (a truncated copy, a full disk) is refused rather than
  // shown full-size with its missing rows black.
  const bool partialName = path.size() >= 8 && path.compare(path.size() - 8, 8, ".partial") == 0;
  if (!f.complete() && !partialName)
    throw io::InputError(
        {path, std::nullopt, 6 + 2 * static_cast<std::uint64_t>(f.pixelsPresent)}, "pixel data",
        std::to_string(f.graph.pixels.size()) + " pixels (" +
            std::to_string(6 + 2 * f.graph.pixels.size()) +
            " bytes) for its header's size; only a .partial file (an aborted trace) may be short",
        std::to_string(f.pixelsPresent) + " whole pixels: the file is truncated");
  if (quiet) return f;
  const int w = f.graph.width();
  if (!f.complete())
    std::cerr << "prime: " << path
              << ": partial graph file (an aborted trace): " << f.pixelsPresent / w << " of "
              << f.graph.height() << " rows; the rest is not drawn\n";
  // The listing's own file overhangs by one column and one row (K21); more
  // than that means the screen or the position is not the one it was made for.
  const long long right = static_cast<long long>(g.at.left) + f.graph.numPixAcross;
  const long long bottom = static_cast<long long>(g.at.top) + f.graph.numPixDown;
  if (g.at.left < 0 || g.at.top < 0 || right > g.width || bottom > g.height)
    std::cerr << "prime: warning: the " << w << " x " << f.graph.height() << " image at ("
              << g.at.left << ", " << g.at.top << ") does not fit the " << g.width << " x "
              << g.height << " screen; part of it is clipped (see --screen and --at)\n";
  return f;
}

}  // namespace prime::cli
