// prime palette [NAME|FILE]: print a palette in the palette-file format
// (docs/prime/palette.md), ready to copy and edit; --list names the built-in ones.
#include <iostream>

#include "palette/prime/palette_file.h"
#include "src/cli/commands.h"
#include "src/cli/prime/display_options.h"

namespace prime::cli {

void addPaletteCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("palette", "Print a palette's 256 DAC entries in the palette-file format");
  auto name = std::make_shared<std::string>("listing");
  auto list = std::make_shared<bool>(false);
  auto o = std::make_shared<DisplayOptions>();
  cmd->add_option("NAME", *name,
                  "listing (default), plate3, vga, or a palette file to check and print");
  cmd->add_flag("--list", *list, "List the built-in palettes");
  addDacOption(cmd, *o);
  cmd->callback([=, &action] {
    action = [=] {
      if (*list) {
        for (const auto& n : builtinPaletteNames())
          std::cout << n << "\t" << findBuiltinPalette(n)->description << "\n";
        return 0;
      }
      // On another monitor, the palette as it shows there (its greys).
      std::cout << formatPaletteText(onMonitorOf(*o, resolvePalette(*name)), dacOf(*o));
      return 0;
    };
  });
}

}  // namespace prime::cli
