// prime export-pov DIR OUT.pov: the scene as POV-Ray 3.7 scene language, with
// its texture maps as PNG files next to OUT.pov (src/prime/pov/pov_export.h).
#include <filesystem>
#include <iostream>

#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/camera_options.h"
#include "src/cli/prime/render_options.h"
#include "src/prime/pov/pov_export.h"

namespace prime::cli {

namespace {

struct ExportPovOptions {
  CameraOptions camera;
  int maxDepth = 5;
  bool model = false;
  bool shadows = false;
  double lightRadius = 0.0;
};

}  // namespace

void addExportPovOptions(CLI::App* cmd, Action& action) {
  auto dir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto o = std::make_shared<ExportPovOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(sceneDirectory());
  cmd->add_option("OUT", *out, "POV-Ray scene file to write (e.g. scene.pov)")
      ->required()
      ->check(outputName());
  addCameraOptions(cmd, o->camera);
  cmd->add_option(
         "--max-depth", o->maxDepth,
         "Recursion depth limit (listing MaxDepth: 5; written as max_trace_level MaxDepth + 1)")
      ->check(CLI::Range(0, 255));
  cmd->add_flag("--model", o->model,
                "Build the databases from the text inputs first (prime model)");
  cmd->add_flag(
      "--shadows", o->shadows,
      "Lights cast shadows, as in --profile thesis (default: shadowless, as the listing)");
  cmd->add_option("--light-radius", o->lightRadius,
                  "With --shadows: lights are circular area lights of this radius, facing the "
                  "point lit (prime trace --profile thesis --light-radius)")
      ->check(atLeast(0));
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      const Scene scene = prepareScene(*dir, o->model);  // as prime trace
      const std::filesystem::path target(*out);
      PovExportOptions po;
      applyCameraOptions(o->camera, po.camera);
      po.maxDepth = o->maxDepth;
      if (o->lightRadius > 0.0 && !o->shadows)
        throw CLI::ValidationError("--light-radius", "needs --shadows");
      po.shadows = o->shadows;
      po.lightRadius = o->lightRadius;
      po.imageStem = target.stem().string();
      const PovExport exported = exportPov(scene, po);
      writePovExport(exported, target);
      if (!*quiet) {
        std::cout << "wrote " << *out << " (" << scene.objects.size() << " objects, "
                  << scene.lights.size() << " lights";
        if (!exported.images.empty())
          std::cout << ", " << exported.images.size() << " texture images beside it";
        std::cout << ")\nrender: povray +I" << target.filename().string() << " +W" << exported.width
                  << " +H" << exported.height << " -A File_Gamma=1.0 (from "
                  << (target.has_parent_path() ? target.parent_path().string() : std::string("."))
                  << ")\n";
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
