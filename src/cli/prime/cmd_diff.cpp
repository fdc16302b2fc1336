// prime diff A B: how two graph files differ. Exit status 0 when they are
// identical (same graphType, same size, every pixel value equal), 1 when they
// differ, 2 when a file cannot be read or the image cannot be written.
#include <cstdio>
#include <iostream>

#include "palette/prime/graph_diff.h"
#include "src/cli/commands.h"
#include "src/cli/prime/display_options.h"

namespace prime::cli {

namespace {

std::string describeGraph(const io::GraphFile& g) {
  return std::to_string(g.width()) + " x " + std::to_string(g.height()) + " pixels, graphType " +
         std::to_string(g.graphType);
}

std::string colourText(const Rgb8& c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%d, %d, %d)", c.r, c.g, c.b);
  return buf;
}

}  // namespace

void addDiffCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "diff",
      "Compare two graph files pixel by pixel (exit 0: identical, 1: they differ, 2: trouble)");
  auto a = std::make_shared<std::string>();
  auto b = std::make_shared<std::string>();
  auto image = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto o = std::make_shared<DisplayOptions>();
  cmd->add_option("A", *a, "First graph file")->required();
  cmd->add_option("B", *b, "Second graph file")->required();
  cmd->add_option(
      "--image", *image,
      "Write a PNG of A's pixel grid: equal pixels dim grey, differing pixels magenta (cyan when "
      "the two values show the same colour)");
  addPaletteOption(cmd, *o, "from A's graphType (0: vga, else listing)");
  addDacOption(cmd, *o);
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing; only the exit status tells");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      try {
        const io::GraphFile ga = io::readGraphFile(*a);
        const io::GraphFile gb = io::readGraphFile(*b);
        const Palette palette = paletteOf(*o, paletteNameForGraphType(ga.graphType));
        const Rgb8Table colours = present(palette.dac, dacOf(*o));
        const GraphDiff d = diffGraphs(ga, gb, colours);
        if (!*quiet) {
          std::printf("A: %s: %s\nB: %s: %s\n", a->c_str(), describeGraph(ga).c_str(), b->c_str(),
                      describeGraph(gb).c_str());
          if (!d.sameGraphType)
            std::printf("graphType differs: %d and %d\n", ga.graphType, gb.graphType);
          if (!d.sameSize) {
            std::printf("sizes differ: no pixels compared\n");
          } else {
            std::printf(
                "pixels differing: %zu of %zu (%.4f%%); %zu of them look different on the screen\n",
                d.differing, d.pixels, 100.0 * d.share(), d.lookDifferent);
            if (d.differing > 0) {
              const auto at = [&](const io::GraphFile& g, int x, int y) { return g.at(x, y); };
              std::printf("first difference at (%d, %d): %d and %d\n", d.firstX, d.firstY,
                          at(ga, d.firstX, d.firstY), at(gb, d.firstX, d.firstY));
            }
            if (d.maxColourDifference > 0) {
              const std::int16_t va = ga.at(d.maxX, d.maxY), vb = gb.at(d.maxX, d.maxY);
              std::printf(
                  "largest colour difference: %d of 255 (palette %s, DAC %s) at (%d, %d): %d %s "
                  "and %d %s\n",
                  d.maxColourDifference, palette.name.c_str(), o->dac.c_str(), d.maxX, d.maxY, va,
                  colourText(colours[static_cast<std::size_t>(va & 0xFF)]).c_str(), vb,
                  colourText(colours[static_cast<std::size_t>(vb & 0xFF)]).c_str());
            } else {
              std::printf("largest colour difference: 0\n");
            }
          }
          std::printf("%s\n", d.identical() ? "identical" : "the files differ");
        }
        if (!image->empty()) {
          if (!d.sameSize) {
            std::cerr << "prime: diff: no image: the files differ in size\n";
            return 2;
          }
          writePng(*image, diffImage(ga, gb, colours));
          if (!*quiet) std::printf("wrote %s\n", image->c_str());
        }
        return d.identical() ? 0 : 1;
      } catch (const std::exception& e) {
        std::cerr << "prime: " << e.what() << "\n";
        return 2;
      }
    };
  });
}

}  // namespace prime::cli
