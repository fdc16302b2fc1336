// prime dump FILE: print any PRIME database or graph file in readable form.
#include <iostream>

#include "legacy_io/prime/dump.h"
#include "legacy_io/prime/scene_dir.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"

namespace prime::cli {

void addDumpCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("dump", "Print a PrimFile, object file, List, map file or graph file");
  auto file = std::make_shared<std::string>();
  auto as = std::make_shared<std::string>();
  auto rows = std::make_shared<int>(8);
  cmd->add_option("FILE", *file,
                  "The binary file (its name matched without regard to case, as a scene's)")
      ->required()
      // As every reader of a scene finds its files (M40): D/PRIM/PRIMFILE is
      // D/PRIM/PrimFile on a case-sensitive disk.
      ->transform(CLI::Validator(
          [](std::string& path) {
            path = io::findIgnoringCase(path).string();
            return std::string();
          },
          "", "case"))
      ->check(CLI::ExistingFile);
  cmd->add_option("--as", *as, "Read it as this kind instead of guessing from its name")
      ->check(CLI::IsMember({"prim", "obj", "list", "map", "graph"}));
  cmd->add_option("--rows", *rows, "Rows of map/graph data to print")->check(atLeast(0));
  cmd->callback([=, &action] {
    action = [=] {
      auto kind = as->empty() ? io::kindFromFileName(*file) : io::kindFromName(*as);
      if (!kind) {
        std::cerr << "prime: " << *file
                  << ": cannot tell the kind of file from its name (PrimFile, List, O<n>, "
                     "Map<n>_R.map, graph_scr or a .scr, .graph, .gr, .partial graph file); say it "
                     "with --as prim|obj|list|map|graph\n";
        return 1;
      }
      std::cout << io::dumpDatabase(*file, *kind, *rows);
      return 0;
    };
  });
}

}  // namespace prime::cli
