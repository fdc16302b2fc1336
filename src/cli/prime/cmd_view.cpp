// prime view FILE: replay a graph file onto the emulated 8514/A screen in a
// window, through a palette (default: the one its graphType implies), and
// wait for Esc as WaitForEsc did.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <sstream>
#include <vector>

#include "palette/prime/live_screen.h"
#include "palette/window/screen_window.h"
#include "src/cli/camera_flags.h"
#include "src/cli/commands.h"
#include "src/cli/live_render.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/display_options.h"

namespace prime::cli {

void addViewOptions(CLI::App* cmd, Action& action) {
  auto file = std::make_shared<std::string>();
  auto rate = std::make_shared<double>(0.0);
  auto o = std::make_shared<DisplayOptions>();
  cmd->add_option("FILE", *file, "Graph file (graph_scr, or the .partial of an aborted trace)")
      ->required()
      ->check(CLI::ExistingFile);
  addPaletteOption(cmd, *o, "from the file's graphType (0: vga, else listing)");
  addDacOption(cmd, *o);
  addGeometryOptions(cmd, *o);
  addInfoOption(cmd, *o);
  addWindowOptions(cmd, *o);
  cmd->add_option("--rows-per-second", *rate,
                  "Replay row by row at this rate (default 0: all at once)")
      ->check(atLeast(0))
      ->group("");  // the older name of --pace N
  auto pace1991 = std::make_shared<bool>(false);
  cmd->add_option_function<std::string>(
         "--pace",
         [rate, pace1991](const std::string& text) {
           LiveOptions parsed;
           parsePace(text, parsed);
           *rate = parsed.pace;
           *pace1991 = parsed.pace1991;
         },
         "Replay row by row: N rows a second, or 1991 (a graph file holds no counts of the "
         "work: one ray a pixel at 300 rays a second; trace --pace 1991 has the era model). "
         "Space pauses, ] and [ double and halve it")
      ->type_name("N|1991");
  auto record = std::make_shared<RecordFlags>();
  addRecordOptions(cmd, *record);
  cmd->callback([=, &action] {
    action = [=] {
      const std::optional<GraphInfo> info = graphInfoFor(*o, *file);
      const Geometry g = geometryOf(*o, info);
      const io::GraphFilePrefix f = readGraphForDisplay(*file, g, false);
      const Palette palette = paletteOf(*o, info, paletteNameForGraphType(f.graph.graphType));
      const int columns = f.graph.width();
      // Each row's time: --pace N, or 1991's flat rate of one ray a pixel;
      // the rows a .partial lacks are not drawn: no time, and they leave the
      // screen as cleared.
      const bool paced = *rate > 0 || *pace1991;
      std::vector<double> rowSeconds(static_cast<std::size_t>(f.graph.height()),
                                     *rate > 0 ? 1.0 / *rate : columns / kRaysPerSecond1991);
      if (!f.complete())
        for (std::size_t r = (f.pixelsPresent + columns - 1) / columns; r < rowSeconds.size(); ++r)
          rowSeconds[r] = 0.0;
      io::GraphFile shownGraph = f.graph;
      for (std::size_t i = f.pixelsPresent; i < shownGraph.pixels.size(); ++i)
        shownGraph.pixels[i] = 0;
      const std::string timeSource =
          *rate > 0 ? "--pace rows a second" : "one ray a pixel at 300 a second";
      if (!record->file.empty())
        recordGraphDrawing(*record, shownGraph, g.at, g.width, g.height,
                           present(palette.dac, dacOf(*o)), rowSeconds, timeSource, false);
      auto headless = display::headlessReason(o->noWindow);
      display::LiveScreen live(g.width, g.height, windowPalettes(palette, *o), dacOf(*o));
      std::unique_ptr<display::ScreenWindow> window;
      if (!headless) {
        try {
          window = std::make_unique<display::ScreenWindow>(
              live, display::WindowConfig{*file, o->zoom, ".", o->fullscreen, scaleOf(*o), false,
                                          companionMeta(info)});
        } catch (const display::WindowError& e) {
          headless = e.what();
        }
      }
      if (!window) {
        if (record->file.empty())
          std::cerr << "prime: running headless (" << *headless
                    << "): nothing to show; `prime export " << *file
                    << " OUT.png` writes the picture\n";
        return 0;
      }
      // The pace's keys: Space pauses, ] and [ double and halve it.
      display::PaceClock paceClock;
      window->setInputHandler([&](const display::module::Event& e) {
        if (e.type == display::module::Event::Type::Key && e.letter == 'r') {
          // R: the drawing kept, timed as --record would time it.
          recordOnKey(*record, shownGraph, g.at, g.width, g.height, present(palette.dac, dacOf(*o)),
                      rowSeconds, timeSource);
          return true;
        }
        if (!paced || e.type != display::module::Event::Type::Key || !paceClock.onKey(e.key))
          return false;
        std::cerr << (paceClock.paused() ? "prime: paused (Space resumes)\n"
                                         : "prime: pace x" + numberText(paceClock.speed()) + "\n");
        return true;
      });
      const int rowsPresent =
          columns > 0 ? static_cast<int>((f.pixelsPresent + columns - 1) / columns) : 0;
      const auto rowSpan = [&](int row) {
        const std::size_t start = static_cast<std::size_t>(row) * columns;
        return std::span(f.graph.pixels)
            .subspan(start, std::min<std::size_t>(columns, f.pixelsPresent - start));
      };
      auto last = std::chrono::steady_clock::now();
      double clock = 0.0, rowEnds = 0.0;  // the pace's time; the drawn rows' times summed
      int drawn = 0;
      bool announced = false;
      for (;;) {
        const auto now = std::chrono::steady_clock::now();
        clock = paceClock.advance(std::chrono::duration<double>(now - last).count());
        last = now;
        // A row shows once the pace's clock has reached its start (the first at once).
        for (; drawn < rowsPresent && (!paced || rowEnds <= clock); ++drawn) {
          live.drawRow(g.at, drawn, rowSpan(drawn));
          rowEnds += rowSeconds[static_cast<std::size_t>(drawn)];
        }
        window->setStatus((drawn < rowsPresent
                               ? "row " + std::to_string(drawn) + "/" + std::to_string(rowsPresent)
                               : std::to_string(rowsPresent) + " rows") +
                          (f.complete() ? "" : " (partial file)") + " - Esc to close");
        if (window->poll(drawn < rowsPresent ? 10 : 100)) break;
        if (!announced && drawn == rowsPresent && window->upToDate()) {
          announced = true;
          std::ostringstream line;  // one write, so a reader never sees half of it
          line << "prime: view: " << *file << " shown (window 0x" << std::hex << window->nativeId()
               << std::dec << ", palette " << live.palette().name
               << "); Esc or close the window to quit\n";
          std::cerr << line.str() << std::flush;
        }
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
