// prime trace DIR: render a scene as RayTrace.c did, to DIR/graph_scr, while
// the emulated 8514/A screen shows each row where PutPixel put it.
//
// With a display, a window shows the whole screen as the render proceeds; Esc
// (or closing it, or Ctrl-C) aborts like ExitOnEsc; when the render is done
// the window stays until Esc or close, like WaitForEsc. Without one (no
// DISPLAY, or --no-window) it runs headless, says so, and Ctrl-C aborts.
//
// An aborted render never writes its target: a previous complete graph file
// there is kept as it was, and TARGET.partial holds the header and the rows
// finished from the top, as the listing's exit(1) would have left them.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <span>

#include "legacy_io/common/output_file.h"
#include "legacy_io/prime/graph_file.h"
#include "palette/prime/export.h"
#include "palette/prime/graph_info.h"
#include "palette/prime/live_screen.h"
#include "palette/window/screen_window.h"
#include "src/cli/commands.h"
#include "src/cli/live_render.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/display_options.h"
#include "src/cli/prime/probe_pixel.h"
#include "src/cli/prime/render_options.h"
#include "src/cli/quantize_options.h"
#include "src/cli/system.h"
#include "src/prime/render/era_cost.h"

namespace prime::cli {

namespace {

void printSummary(const RenderResult& r, const std::string& out, const std::string& profile) {
  const auto& s = r.stats;
  // An abort or a band (--rows): the rows rendered, of how many.
  const std::string rows = rowsRenderedText(r.aborted, r.rowsDone, r.rows, r.graph.height());
  std::printf("%s %s%d x %d pixels (graph file header %d x %d) in %.2f s with %d thread(s): %s\n",
              r.aborted ? "ABORTED after" : "traced", rows.c_str(), r.graph.width(),
              r.graph.height(), r.graph.numPixAcross, r.graph.numPixDown, r.seconds, r.threads,
              out.c_str());
  std::printf("rays: %llu (primary %llu, reflected %llu, transmitted %llu), %.0f rays/s\n",
              static_cast<unsigned long long>(s.rays()),
              static_cast<unsigned long long>(s.primaryRays),
              static_cast<unsigned long long>(s.reflectedRays),
              static_cast<unsigned long long>(s.transmittedRays),
              r.seconds > 0 ? s.rays() / r.seconds : 0.0);
  if (s.shadowRays > 0 || r.samples > 0)  // the thesis profile's shadow rays; pixel samples
    std::printf(
        "shadow rays: %llu; pixel samples: %llu (%.2f a pixel)\n",
        static_cast<unsigned long long>(s.shadowRays), static_cast<unsigned long long>(r.samples),
        r.rowsDone == 0
            ? 0.0
            : static_cast<double>(r.samples) / (static_cast<double>(r.rowsDone) * r.graph.width()));
  std::printf(
      "tests: %llu bound, %llu object, %llu primitive; hits %llu; TIR %llu; primary rays that "
      "could meet no object box (background, not traced) %llu\n",
      static_cast<unsigned long long>(s.boundTests), static_cast<unsigned long long>(s.objectTests),
      static_cast<unsigned long long>(s.primitiveTests), static_cast<unsigned long long>(s.hits),
      static_cast<unsigned long long>(s.totalInternalReflections),
      static_cast<unsigned long long>(s.maskedPrimaryRays));
  // The listing's failures, counted: said for the 1991 profile, and for
  // another only when one happened.
  const bool any = s.emptyTransmitLists + s.cappedTirLoops + s.failedTexelReads + s.noFaceMatched +
                       s.nanColours + s.indicesOutOfRange >
                   0;
  if (profile == "1991" || any)
    std::printf(
        "1991 diagnostics (X3): E46 empty transmit lists %llu, E59 capped TIR loops %llu, "
        "E51 failed texel reads %llu, E44 no face %llu, NaN colours %llu, indices outside "
        "0..255 %llu\n",
        static_cast<unsigned long long>(s.emptyTransmitLists),
        static_cast<unsigned long long>(s.cappedTirLoops),
        static_cast<unsigned long long>(s.failedTexelReads),
        static_cast<unsigned long long>(s.noFaceMatched),
        static_cast<unsigned long long>(s.nanColours),
        static_cast<unsigned long long>(s.indicesOutOfRange));
}

// A picture whose every pixel is one palette index although rays met objects:
// its shading never crosses a step of the mapping (plate 2 under the thesis
// profile stays below the first, docs/prime/plates.md). Said on stderr, with
// what shows the picture.
void noteOneIndex(const RenderResult& r) {
  const auto& px = r.graph.pixels;
  if (px.empty() || r.stats.hits == 0) return;
  for (const std::int16_t v : px)
    if (v != px.front()) return;
  std::fprintf(stderr,
               "prime: note: every pixel has palette index %d although rays met objects: the "
               "shading never crosses a step of the palette mapping (as plate 2 under the thesis "
               "profile, docs/prime/plates.md); --true-color-png FILE or --quantize METHOD shows "
               "the picture\n",
               static_cast<int>(px.front()));
}

// The companion file beside a graph file (G7): what view and export need to
// show it as the render did. Written after the graph file, each through
// OutputFile; a companion that does not match its graph file's bytes is
// ignored by view and export (G9).
// `info` is what the render knows (profile, screen, placement, palette,
// provenance); the size and hash are of the bytes written.
void writeCompanion(const std::string& graphPath, std::size_t graphBytes, std::uint64_t graphHash,
                    GraphInfo info) {
  info.graphBytes = graphBytes;
  info.graphHash = graphHash;
  writeGraphInfo(graphInfoPath(graphPath), info);
}
void writeCompanion(const std::string& graphPath, const io::GraphFile& graph,
                    const GraphInfo& info) {
  const std::vector<std::uint8_t> bytes = io::toBytes(graph);
  writeCompanion(graphPath, bytes.size(), graphHash(GraphHashKind::Xxh3_64, bytes), info);
}

// The graph file written while the render runs: each finished row goes out
// as soon as every row above it has, from the thread that waits on the
// render anyway, so that when the last render thread stops only the sync and
// the rename are left (writing megabytes is work no render thread shares).
// Uncommitted (an aborted render, an error), the temporary is removed and
// the target is untouched, as with any OutputFile.
class GraphStream {
 public:
  GraphStream(const std::string& target, const io::GraphFile& header, int rows)
      : out_(target), pending_(static_cast<std::size_t>(rows)) {
    io::forEachGraphFileBytes(header, [this](std::span<const std::uint8_t> b) { put(b); });
  }
  // `pixels` stays where it is (the render's picture) until the render
  // returns: a row that waits for those above it is written from there.
  void row(int i, std::span<const std::int16_t> pixels) {
    pending_[static_cast<std::size_t>(i)] = pixels;
    while (next_ < pending_.size() && pending_[next_].data() != nullptr) {
      io::forEachPixelBytes(pending_[next_], [this](std::span<const std::uint8_t> b) { put(b); });
      ++next_;
    }
  }
  bool complete() const { return next_ == pending_.size(); }
  void commit() { out_.commit(); }
  // The companion's size and hash of what was written (G7).
  std::size_t bytes() const { return bytes_; }
  std::uint64_t hash() const { return hash_.digest(); }

 private:
  void put(std::span<const std::uint8_t> b) {
    out_.write(b);
    hash_.add(b);
    bytes_ += b.size();
  }
  io::OutputFile out_;
  std::vector<std::span<const std::int16_t>> pending_;  // finished rows (null: not yet)
  std::size_t next_ = 0;                                // the first row not written yet
  Xxh3Stream hash_;
  std::size_t bytes_ = 0;
};

// The graph file and its companion: the file's bytes written from the
// pixels as they are, then hashed (a streamed render's file was hashed as
// it was written).
void writeGraphAndCompanion(const std::string& target, const io::GraphFile& graph,
                            const GraphInfo& info, GraphStream* streamed = nullptr) {
  if (streamed && streamed->complete()) {  // every row is in it already, and in its hash
    streamed->commit();
    writeCompanion(target, streamed->bytes(), streamed->hash(), info);
    return;
  }
  io::writeGraphFile(target, graph);
  Xxh3Stream hash;  // (XXH3: a millisecond for a 4x picture, G12)
  io::forEachGraphFileBytes(graph, [&hash](std::span<const std::uint8_t> b) { hash.add(b); });
  const std::size_t bytes = 2 * (3 + graph.pixels.size());  // toBytes' size
  writeCompanion(target, bytes, hash.digest(), info);
}

// --quantize (thesis 4.4, T59): every pixel of the graph file (the listing's
// off-screen column and row too) from its unquantised colour, by the chosen
// quantizer; the indices replace ColorNum's and the palette is returned.
Palette quantizeGraph(RenderResult& result, const QuantizeOptions& q) {
  Image8 whole{result.graph.width(), result.graph.height(), {}};
  whole.rgb.reserve(result.rgb.pixels.size() * 3);
  for (const Rgb& c : result.rgb.pixels) {
    const Rgb8 t = trueColour(c);
    whole.rgb.insert(whole.rgb.end(), {t.r, t.g, t.b});
  }
  const quantize::Result r = quantize::quantize(whole, settingsOf(q));
  for (std::size_t i = 0; i < r.indices.size(); ++i)
    result.graph.pixels[i] = static_cast<std::int16_t>(r.indices[i]);
  Palette p;
  p.name = "quantized";
  p.description = q.method + ", dither " + q.dither + ", " +
                  std::to_string(r.palette.levels.size()) + " colours (thesis 4.4)";
  for (std::size_t i = 0; i < r.palette.levels.size(); ++i)
    p.dac[i] = {r.palette.levels[i][0], r.palette.levels[i][1], r.palette.levels[i][2]};
  return p;  // entries past the palette's size stay black
}

// An aborted render never writes its target: a previous good render there is
// kept (an interrupted re-render must not cost the last finished picture),
// and `partial` gets the header and the rows finished from the top, as the
// listing's exit(1) would have left them.
void writeAborted(const RenderResult& result, const std::vector<char>& finished,
                  const std::string& target, const std::string& partial,
                  const std::function<void(const io::GraphFile&)>& companion) {
  std::size_t prefix = 0;
  while (prefix < finished.size() && finished[prefix]) ++prefix;
  std::error_code ec;
  const bool kept = std::filesystem::exists(target, ec);
  io::GraphFile head = result.graph;
  head.pixels.resize(prefix * static_cast<std::size_t>(head.width()));
  io::writeGraphFile(partial, head);
  companion(head);
  const auto rowsFinished = std::count(finished.begin(), finished.end(), 1);
  std::cerr << "prime: trace aborted after " << rowsFinished << " of " << finished.size()
            << " rows: " << target << " not written" << (kept ? " (the previous one is kept)" : "")
            << "; the " << prefix << " rows finished from the top are in " << partial
            << " (prime view shows it); no PNG written\n";
}

// The PNGs of a finished render: the emulated screen's area as the screen
// holds it (its indices, the DAC as the palette) and its upscaled copy, and
// the unquantised colours of the same area. Returns the files written.
std::vector<std::string> writePngs(const RenderResult& result, const PrimeCamera& camera,
                                   Placement at, const Palette& palette,
                                   const DisplayOptions& display, const std::string& png,
                                   const std::string& trueColourPng, const PngMeta& meta) {
  // The listing's screen, or a free camera's picture as its own screen (T32).
  const int screenW = camera.screenWidth(), screenH = camera.screenHeight();
  const ImageArea area = areaOf(display);
  std::vector<std::string> written;
  if (!png.empty() || !display.pngUpscaled.empty()) {
    Screen screen(screenW, screenH);
    drawGraph(screen, result.graph, at);
    written = write8514Pngs(png,
                            exportIndexed(screen, result.graph, result.graph.pixels.size(), at,
                                          present(palette.dac, dacOf(display)), area),
                            meta, display, paletteLabel(palette));
  }
  if (!trueColourPng.empty()) {
    writePng(trueColourPng,
             exportTrueColour(screenW, screenH, result.graph, result.rgb.pixels, at, area), meta);
    written.push_back(trueColourPng);
  }
  return written;
}

class PrimeTrace : public TraceJob {
 public:
  PrimeTrace(std::shared_ptr<std::string> dir, std::shared_ptr<std::string> out,
             std::shared_ptr<RenderOptions> options, std::shared_ptr<DisplayOptions> display,
             std::shared_ptr<TraceFlags> flags, std::shared_ptr<RecordFlags> record)
      : record_(std::move(record)),
        dir_(std::move(dir)),
        options_(std::move(options)),
        display_(std::move(display)),
        flags_(std::move(flags)),
        target_(out->empty() ? *dir_ + "/graph_scr" : *out),
        partial_(target_ + ".partial") {}

  // Found before the render: a missing directory, a directory, an input (M23).
  std::vector<Output> outputs() const override {
    return {{"--out", target_},
            {"the graph file's .partial", partial_},
            {"the graph file's .info", graphInfoPath(target_)},
            {"the .partial's .info", graphInfoPath(partial_)},
            {"--png", flags_->png},
            {"--true-color-png", flags_->trueColourPng},
            {"--png-8514", flags_->png8514},
            {"--png-upscaled", display_->pngUpscaled},
            {"--record", record_->file}};
  }
  bool writesWithoutOutputs() const override { return true; }  // the graph file
  std::string scene() const override { return *dir_; }
  void load() override {
    finishRenderOptions(*options_);
    options_->settings.threads = flags_->threads;
    scene_.emplace(prepareScene(*dir_, options_->model));
    quantizing_ = !flags_->quantize.method.empty();
    options_->settings.keepColours =
        !flags_->trueColourPng.empty() || quantizing_;  // only these read them
    // --record and --pace 1991 time each row by the era model, from the
    // counts of the listing's own work (no skipped tests: the same pixels).
    // (Every render keeps the rows' counts: the window's R key records by
    // them; without --record or --pace 1991 they are the port's, which
    // skips work the listing did.)
    options_->settings.rowStats = &rowStats_;
    listingCounts_ = !record_->file.empty() || flags_->live.pace1991;
    if (listingCounts_) options_->settings.trace.skipUnneededWork = false;
    const RenderSettings& settings = options_->settings;
    camera_.emplace(settings.camera);
    at_ = {camera_->screenX(0), camera_->screenY(0)};
    mappingPalette_ = settings.mapping == ColorMapping::Plate3
                          ? "plate3"
                          : paletteNameForGraphType(settings.graphType);
    palette_ = paletteOf(*display_, mappingPalette_);
    // The emulated screen, in a window if there can be one. Without one
    // nothing draws on it: a one-pixel stand-in, not megabytes to clear
    // before the render can start (4096 x 3072 at --screen 4096 3072).
    display_->noWindow = flags_->live.noWindow;
    const bool headless = display::headlessReason(display_->noWindow).has_value();
    screen_.emplace(headless ? 1 : camera_->screenWidth(), headless ? 1 : camera_->screenHeight(),
                    windowPalettes(palette_, *display_), dacOf(*display_));
  }
  bool quiet() const override { return flags_->quiet; }
  display::LiveFrame& frame() override { return *screen_; }
  void configure(LiveOptions& options) const override {
    options.caption = *dir_;
    options.keys = "P palette, D DAC";
    options.firstRow = at_.top;  // the image's row 0 on the screen
    if (listingCounts_) options.seconds1991 = [this] { return seconds1991Done_.load(); };
    // R: the drawing of the finished render, timed as --record would time it.
    options.recordKey = [this] {
      if (!rendered_ || result_.aborted) {
        std::cerr << "prime: R records the drawing once the render is done\n";
        return;
      }
      recordOnKey(*record_, result_.graph, at_, camera_->screenWidth(), camera_->screenHeight(),
                  present(palette_.dac, dacOf(*display_)), rowTimes(), rowTimesSource());
    };
    const auto& s = options_->settings;
    options.cameraKey = [free = s.camera.free, dir = *dir_,
                         profile = options_->profile +
                                   (s.trace.fixes.any() ? " --fix " + fixIds(s.trace.fixes) : "")] {
      cameraKey(free, "prime trace " + dir + ", profile " + profile, kDefaultCameraFile,
                "the listing's camera: prime trace " + dir +
                    " renders this frame with no camera flag (any of them makes a free camera)");
    };
    // A click: the pixel's probe, with the render's scene and settings; the
    // picture sits at at_ of the screen.
    options.probe = [this](int column, int row) -> std::optional<ProbedPixel> {
      const int x = column - at_.left, y = row - at_.top;
      if (x < 0 || y < 0 || x >= camera_->columns() || y >= camera_->rows()) return std::nullopt;
      return probePixel(*scene_, options_->settings, camera_->primaryRay(y, x),
                        pixelWhere(*camera_, x, y), x, y)
          .placedAt(at_.left, at_.top);
    };
  }
  void render(LiveRender& live) override {
    const RenderSettings& settings = options_->settings;
    // Which rows are done (rowDone runs on one thread, the render's caller).
    finished_.assign(static_cast<std::size_t>(camera_->rows()), 0);
    RenderCallbacks cb;
    cb.abort = live.abortFlag();
    cb.progress = live.progress();
    cb.firstRow = firstRow_;
    cb.lastRow = lastRow_;
    // Quantizing replaces the indices after the render: written then; a
    // band's rows are not the file's first ones: written whole at the end.
    const bool band = firstRow_ > 0 || lastRow_ >= 0;
    if (!quantizing_ && !band) {
      io::GraphFile header;
      header.graphType = static_cast<std::int16_t>(settings.graphType);
      header.numPixAcross = static_cast<std::int16_t>(camera_->numPixAcross());
      header.numPixDown = static_cast<std::int16_t>(camera_->numPixDown());
      stream_.emplace(target_, header, camera_->rows());
    }
    cb.rowDone = [&](int row, std::span<const std::int16_t> indices) {
      finished_[static_cast<std::size_t>(row)] = 1;
      if (listingCounts_)  // written before this call (RenderSettings::rowStats)
        seconds1991Done_ = seconds1991Done_ + rowSeconds1991(row);
      if (stream_) stream_->row(row, indices);
      if (live.windowed()) screen_->drawRow(at_, row, indices);  // PutPixel(j, i, color)
    };
    live.run([&] {
      result_ = prime::render(*scene_, settings, cb);
      rendered_ = true;
    });
  }
  bool aborted() const override { return result_.aborted; }
  void abort() override {
    writeAborted(result_, finished_, target_, partial_, [&](const io::GraphFile& head) {
      writeCompanion(partial_, head, companion(*findBuiltinPalette(mappingPalette_), false));
    });
    if (!flags_->quiet) printSummary(result_, partial_, options_->profile);
  }
  // What the companion says besides the graph file's size and hash (G7).
  GraphInfo companion(const Palette& palette, bool inlinePalette) const {
    GraphInfo info;
    info.profile = options_->profile;
    // A free camera's picture is its own screen (T32).
    info.screenWidth = camera_->screenWidth();
    info.screenHeight = camera_->screenHeight();
    info.at = at_;
    info.palette = palette;
    info.inline_ = inlinePalette;
    for (const PngText& t : provenance_.text) info.text.emplace_back(t.keyword, t.text);
    return info;
  }
  std::vector<std::string> write() override {
    if (quantizing_) {
      const Palette quantized = quantizeGraph(result_, flags_->quantize);
      if (display_->palette.empty()) palette_ = onMonitorOf(*display_, quantized);
      writeGraphAndCompanion(target_, result_.graph, companion(quantized, true));
    } else {
      writeGraphAndCompanion(target_, result_.graph,
                             companion(*findBuiltinPalette(mappingPalette_), false),
                             stream_ ? &*stream_ : nullptr);
    }
    std::error_code ec;
    std::filesystem::remove(partial_, ec);  // an older aborted run's
    std::filesystem::remove(graphInfoPath(partial_), ec);
    // --png and --png-8514 are the same picture here: PRIME's own screen.
    std::vector<std::string> written = {target_};
    for (std::string& f : writePngs(result_, *camera_, at_, palette_, *display_, flags_->png,
                                    flags_->trueColourPng, provenance_))
      written.push_back(std::move(f));
    if (!record_->file.empty()) {
      recordGraphDrawing(*record_, result_.graph, at_, camera_->screenWidth(),
                         camera_->screenHeight(), present(palette_.dac, dacOf(*display_)),
                         rowTimes(), rowTimesSource(), flags_->quiet);
      written.push_back(record_->file);
    }
    if (!flags_->png8514.empty()) {
      DisplayOptions once = *display_;
      once.pngUpscaled.clear();  // written with --png
      writePngs(result_, *camera_, at_, palette_, once, flags_->png8514, "", provenance_);
      written.push_back(flags_->png8514);
    }
    return written;
  }
  void summary(const std::vector<std::string>&) const override {
    printSummary(result_, target_, options_->profile);
    if (listingCounts_) {  // --pace 1991, --record: the era model beside the flat rate
      double era = 0.0;
      for (int r = 0; r < camera_->rows(); ++r) era += rowSeconds1991(r);
      std::printf(
          "1991 estimate: %s on a 20 MHz 386 + 387 (docs/prime/pace-1991.md); the flat "
          "%.0f rays a second would say %s\n",
          durationText(era).c_str(), kRaysPerSecond1991,
          durationText(static_cast<double>(result_.stats.rays()) / kRaysPerSecond1991).c_str());
    }
    if (const std::string ids = fixIds(options_->settings.trace.fixes); !ids.empty())
      std::printf("1991 profile with listing quirks corrected: --fix %s (prime errata)\n",
                  ids.c_str());
    if (!quantizing_) noteOneIndex(result_);
  }
  double seconds() const override { return result_.seconds; }
  // The era model's time of row r (its counts, its pixels, the scene's lights).
  double rowSeconds1991(int r) const {
    return seconds1991(rowStats_[static_cast<std::size_t>(r)],
                       static_cast<std::uint64_t>(camera_->columns()),
                       static_cast<int>(scene_->lights.size()));
  }
  // Each row's time in a recording: 1 / N with --pace N, else the era model.
  std::vector<double> rowTimes() const {
    std::vector<double> t(static_cast<std::size_t>(camera_->rows()));
    for (int r = 0; r < camera_->rows(); ++r)
      t[static_cast<std::size_t>(r)] =
          flags_->live.pace > 0 ? 1.0 / flags_->live.pace : rowSeconds1991(r);
    return t;
  }
  std::string rowTimesSource() const {
    if (flags_->live.pace > 0) return "--pace rows a second";
    return listingCounts_ ? "the 1991 estimate"
                          : "the 1991 estimate of the port's counts, which skip work the listing "
                            "did: --pace 1991 counts the listing's";
  }
  std::vector<PngText> describe() const override {
    const std::string fixes = fixIds(options_->settings.trace.fixes);
    std::vector<PngText> t = {{"Profile", options_->profile}};
    if (!fixes.empty()) t.push_back({"Fixes", "--fix " + fixes + " (prime errata)"});
    return t;
  }
  int pictureRows() const override { return camera_->rows(); }
  // The screen PNGs hold the picture where it sits on the screen (--png-area).
  FileRows fileRows(const std::string& output, int first, int last) const override {
    if (output != "--png" && output != "--png-8514" && output != "--true-color-png")
      return {first, last, pictureRows()};
    const int screenH = camera_->screenHeight();
    int top = 0, rows = pictureRows();  // the file area: the graph's own rows
    switch (areaOf(*display_)) {
      case ImageArea::Screen:
        top = at_.top;
        rows = screenH;
        break;
      case ImageArea::Image:  // the picture clipped to the screen
        top = std::min(at_.top, 0);
        rows = std::min(screenH, at_.top + pictureRows()) - std::max(0, at_.top);
        break;
      case ImageArea::File:
        break;
    }
    const int a = std::max(0, first + top), b = std::min(rows - 1, last + top);
    return {a, b, rows};
  }

 private:
  std::shared_ptr<RecordFlags> record_;
  std::vector<TraceStats> rowStats_;  // --record, --pace 1991: each row's counts
  std::atomic<double> seconds1991Done_{0.0};
  bool listingCounts_ = false;         // rowStats_ count the listing's own work
  std::atomic<bool> rendered_{false};  // result_ holds the finished render
  std::shared_ptr<std::string> dir_;
  std::shared_ptr<RenderOptions> options_;
  std::shared_ptr<DisplayOptions> display_;
  std::shared_ptr<TraceFlags> flags_;
  std::string target_, partial_;
  std::optional<Scene> scene_;
  std::optional<PrimeCamera> camera_;
  Placement at_;
  std::string mappingPalette_;
  Palette palette_;
  bool quantizing_ = false;
  std::optional<display::LiveScreen> screen_;
  std::vector<char> finished_;
  std::optional<GraphStream> stream_;
  RenderResult result_;
};

}  // namespace

TraceFactory addTraceOptions(CLI::App* cmd, const std::shared_ptr<TraceFlags>& flags) {
  auto dir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto options = std::make_shared<RenderOptions>();
  auto display = std::make_shared<DisplayOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(sceneDirectory());
  cmd->add_option("--out", *out, "Graph file to write (default: DIR/graph_scr)")
      ->check(outputName());
  addAreaOption(cmd, *display, "--png-area");
  cmd->add_option(
      "--display-palette", display->palette,
      "Palette for the window and PNG: listing, plate3, vga or a palette file (default: the one "
      "--palette implies)");
  addDacOption(cmd, *display);
  addUpscaleOptions(cmd, *display);
  auto record = std::make_shared<RecordFlags>();
  addRecordOptions(cmd, *record);
  addRenderOptions(cmd, *options);
  flags->camera = &options->camera.flags;
  flags->ownOutputs = {out.get(), &display->pngUpscaled, &record->file};
  flags->firstFrameOnly = {&options->model};
  return [dir, out, options, display, flags, record] {
    return std::make_unique<PrimeTrace>(dir, out, options, display, flags, record);
  };
}

}  // namespace prime::cli
