// prime export GRAPHFILE OUT.png: the picture a graph file makes on the
// emulated 8514/A screen, as a PNG.
#include <iostream>

#include "legacy_io/common/output_file.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/display_options.h"

namespace prime::cli {

void addExportOptions(CLI::App* cmd, Action& action) {
  auto file = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto o = std::make_shared<DisplayOptions>();
  cmd->add_option("GRAPHFILE", *file, "Graph file (graph_scr, or the .partial of an aborted trace)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("OUT", *out, "PNG file to write")->required()->check(outputName());
  addPaletteOption(cmd, *o, "from the file's graphType (0: vga, else listing)");
  addDacOption(cmd, *o);
  addAreaOption(cmd, *o, "--area");
  addGeometryOptions(cmd, *o);
  addInfoOption(cmd, *o);
  addUpscaleOptions(cmd, *o);
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      const std::optional<GraphInfo> info = graphInfoFor(*o, *file);
      const Geometry g = geometryOf(*o, info);
      const io::GraphFilePrefix f = readGraphForDisplay(*file, g, *quiet);
      // After the read (the graph file is then an input of the run): no
      // output is an input, and no two outputs are one file.
      io::checkOutputs({{"OUT", *out}, {"--png-upscaled", o->pngUpscaled}});
      // A PNG is all export writes: a name that says another format is
      // refused, not given a PNG under it.
      for (const std::string& name : {*out, o->pngUpscaled}) {
        const std::string ext = lowerExtension(name);
        for (const char* other :
             {".bmp", ".pcx", ".gif", ".jpg", ".jpeg", ".tif", ".tiff", ".ppm", ".tga", ".webp"})
          if (ext == other)
            throw io::InputError(
                {name, std::nullopt, std::nullopt},
                "export writes PNG only, and this name says " + ext.substr(1) + ": name it .png");
      }
      const Palette palette = paletteOf(*o, info, paletteNameForGraphType(f.graph.graphType));
      Screen screen(g.width, g.height);
      drawGraph(screen, f.graph, g.at, f.pixelsPresent);
      const IndexedImage8 img = exportIndexed(screen, f.graph, f.pixelsPresent, g.at,
                                              present(palette.dac, dacOf(*o)), areaOf(*o));
      // What made the picture, as its companion says (the render's
      // provenance), then the palette's lines.
      write8514Pngs(*out, img, companionMeta(info), *o, paletteLabel(palette));
      if (*quiet) return 0;
      std::cout << "wrote " << *out << ": " << img.width << " x " << img.height << " (" << o->area
                << " area; the file's " << f.graph.width() << " x " << f.graph.height()
                << " pixels at (" << g.at.left << ", " << g.at.top << ") on a " << g.width << " x "
                << g.height << " screen), palette " << paletteLabel(palette) << ", DAC " << o->dac
                << "\n";
      if (!o->pngUpscaled.empty()) {
        const int k = fitFactor(img.width, img.height, o->upscaleFit[0], o->upscaleFit[1]);
        std::cout << "wrote " << o->pngUpscaled << ": " << img.width * k << " x " << img.height * k
                  << " (" << *out << " upscaled " << k << " x " << k << ", nearest neighbour)\n";
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
