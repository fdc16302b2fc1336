// prime view FILE: replay a graph file onto the emulated 8514/A screen in a
// window, through a palette (default: the one its graphType implies), and
// wait for Esc as WaitForEsc did.
#include <chrono>
#include <iostream>
#include <sstream>

#include "palette/prime/live_screen.h"
#include "palette/window/screen_window.h"
#include "src/cli/commands.h"
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
      ->check(atLeast(0));
  cmd->callback([=, &action] {
    action = [=] {
      const std::optional<GraphInfo> info = graphInfoFor(*o, *file);
      const Geometry g = geometryOf(*o, info);
      const io::GraphFilePrefix f = readGraphForDisplay(*file, g, false);
      const Palette palette = paletteOf(*o, info, paletteNameForGraphType(f.graph.graphType));
      auto headless = display::headlessReason(o->noWindow);
      display::LiveScreen live(g.width, g.height, windowPalettes(palette, *o), dacOf(*o));
      std::unique_ptr<display::ScreenWindow> window;
      if (!headless) {
        try {
          window = std::make_unique<display::ScreenWindow>(
              live, display::WindowConfig{
                        *file, o->zoom, ".", o->fullscreen, scaleOf(*o), false,
                        PngMeta{{{"Software", std::string("prime ") + PRIME_VERSION}}, 1, 1}});
        } catch (const display::WindowError& e) {
          headless = e.what();
        }
      }
      if (!window) {
        std::cerr << "prime: running headless (" << *headless
                  << "): nothing to show; `prime export " << *file
                  << " OUT.png` writes the picture\n";
        return 0;
      }
      const int columns = f.graph.width();
      const int rowsPresent =
          columns > 0 ? static_cast<int>((f.pixelsPresent + columns - 1) / columns) : 0;
      const auto rowSpan = [&](int row) {
        const std::size_t start = static_cast<std::size_t>(row) * columns;
        return std::span(f.graph.pixels)
            .subspan(start, std::min<std::size_t>(columns, f.pixelsPresent - start));
      };
      const auto start = std::chrono::steady_clock::now();
      int drawn = 0;
      bool announced = false;
      for (;;) {
        int due = rowsPresent;
        if (*rate > 0) {
          const double s =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          due = std::min(rowsPresent, static_cast<int>(s * *rate) + 1);
        }
        for (; drawn < due; ++drawn) live.drawRow(g.at, drawn, rowSpan(drawn));
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
