// prime plate1 DIR: Colour Plate 1, the beta-spline wireframe (thesis 3.4.2,
// 5.10), drawn with line() on the emulated 8514/A screen from DIR/knots.txt,
// and written like a render: DIR/graph_scr (the camera's viewport) and a PNG.
#include <cstdio>
#include <memory>

#include "legacy_io/prime/graph_file.h"
#include "palette/png_image.h"
#include "palette/prime/dac.h"
#include "palette/prime/export.h"
#include "palette/prime/palettes.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/camera_options.h"
#include "src/prime/plate1/plate1.h"

namespace prime::cli {

void addPlate1Command(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "plate1",
      "Colour Plate 1: draw the beta-spline wireframe of DIR/knots.txt on the emulated screen");
  struct Options {
    std::string dir, knots, out, png, area = "image";
    CameraOptions camera;
    spline::WireframeOptions wire;
    bool quiet = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("DIR", o->dir, "Scene directory holding knots.txt (scenes/prime/plate1)")
      ->required()
      ->check(sceneDirectory("plate1"));
  cmd->add_option("--knots", o->knots, "Knot file (default: DIR/knots.txt)");
  cmd->add_option("--out", o->out, "Graph file to write (default: DIR/graph_scr)")
      ->check(outputName());
  cmd->add_option("--png", o->png, "Also write the picture as PNG (listing palette)")
      ->check(outputName());
  cmd->add_option("--png-area", o->area, "image (the viewport, default) or screen (all 1024 x 768)")
      ->check(CLI::IsMember({"image", "screen"}));
  addCameraOptions(cmd, o->camera);
  cmd->add_option("--curves", o->wire.curvesPerPatch,
                  "Curves per patch in each direction (default 4)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--segments", o->wire.segmentsPerPatch,
                  "Line segments per patch along each curve (default 8)")
      ->check(CLI::Range(1, 256));
  cmd->add_flag("--net", o->wire.net, "Also draw the control polygon (lavender)");
  cmd->add_flag("-q,--quiet", o->quiet, "No summary");
  cmd->callback([o, &action] {
    action = [o] {
      applyCameraOptions(o->camera, o->wire.camera);
      const std::string knotPath = o->knots.empty() ? o->dir + "/knots.txt" : o->knots;
      const spline::KnotFile knots = spline::readKnotFile(knotPath, knotPath);
      const spline::Plate1Picture pic = spline::drawPlate1(knots, o->wire);
      const std::string target = o->out.empty() ? o->dir + "/graph_scr" : o->out;
      io::writeGraphFile(target, pic.graph);
      if (!o->png.empty()) {
        const spline::Projection proj(o->wire.camera);
        const ListingCamera& cam = proj.camera();
        const Rect area = o->area == "screen"
                              ? pic.screen.bounds()
                              : intersect(pic.screen.bounds(), Rect{cam.screenX(0), cam.screenY(0),
                                                                    cam.columns(), cam.rows()});
        writePng(o->png, screenImage(pic.screen, present(listingDac()), area));
      }
      if (!o->quiet)
        std::printf(
            "drew %d x %d knots (beta1 %g, beta2 %g): %d x %d patches, %d lines; graph file %d x "
            "%d: %s\n",
            knots.grid.rows(), knots.grid.cols(), knots.shape.beta1, knots.shape.beta2,
            knots.grid.patchRows(), knots.grid.patchCols(), pic.lines, pic.graph.width(),
            pic.graph.height(), target.c_str());
      // One "wrote PATH" line per file written, as every command (issue 16).
      if (!o->quiet)
        for (const std::string& f : {target, o->png})
          if (!f.empty()) std::printf("wrote %s\n", f.c_str());
      return 0;
    };
  });
}

}  // namespace prime::cli
