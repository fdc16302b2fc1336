// prime export-pov DIR OUT.pov: the scene as POV-Ray 3.7 scene language, with
// its texture maps as PNG files next to OUT.pov (src/export/pov_export.h).
#include <filesystem>
#include <iostream>

#include "legacy_io/error.h"
#include "legacy_io/model_builder.h"
#include "src/cli/commands.h"
#include "src/export/pov_export.h"
#include "src/scene/scene_loader.h"

namespace prime::cli {

namespace {

struct ExportPovOptions {
  std::vector<double> eye, windowLeft, windowRight, viewport;
  std::vector<int> screen;
  int maxDepth = 5;
  bool model = false;
};

CameraSettings cameraOf(const ExportPovOptions& o) {
  CameraSettings c;
  if (o.eye.size() == 3) c.eye = {o.eye[0], o.eye[1], o.eye[2]};
  if (o.windowLeft.size() == 3) c.windowLeft = {o.windowLeft[0], o.windowLeft[1], o.windowLeft[2]};
  if (o.windowRight.size() == 3)
    c.windowRight = {o.windowRight[0], o.windowRight[1], o.windowRight[2]};
  if (o.viewport.size() == 4) {
    c.xMin = o.viewport[0];
    c.yMin = o.viewport[1];
    c.xMax = o.viewport[2];
    c.yMax = o.viewport[3];
  }
  if (o.screen.size() == 2) {
    c.screenWidth = o.screen[0];
    c.screenHeight = o.screen[1];
  }
  return c;
}

// As prime trace: model first with --model, else refuse stale databases.
Scene loadForExport(const std::string& dir, bool model) {
  const io::SceneDir scene(dir);
  if (model) {
    const io::Model m = io::buildModel(scene);
    io::writeModel(scene, m);
    for (const auto& w : m.warnings) std::cerr << "prime: warning: " << w << "\n";
  } else if (auto stale = staleDatabases(scene); !stale.empty()) {
    std::string msg = "the scene's databases are not up to date:";
    for (const auto& s : stale) msg += "\n  " + s;
    msg += "\nrun `prime model " + dir + "` first, or add --model";
    throw io::InputError({dir, std::nullopt, std::nullopt}, msg);
  }
  return loadScene(scene);
}

}  // namespace

void addExportPovCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "export-pov",
      "Write a modelled scene as a POV-Ray 3.7 scene (OUT.pov, texture maps as PNG beside it)");
  auto dir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto o = std::make_shared<ExportPovOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("OUT", *out, "POV-Ray scene file to write (e.g. scene.pov)")->required();
  cmd->add_option("--eye", o->eye, "Eye position x y z (listing: 500 500 -1500)")->expected(3)->allow_extra_args(false);
  cmd->add_option("--window-left", o->windowLeft,
                  "World window top-left corner (listing: 0 1000 0)")
      ->expected(3)->allow_extra_args(false);
  cmd->add_option("--window-right", o->windowRight,
                  "World window top-right corner (listing: 1000 1000 0)")
      ->expected(3)->allow_extra_args(false);
  cmd->add_option("--viewport", o->viewport,
                  "Screen viewport xMin yMin xMax yMax, normalised (listing: 0.66 0 1 1)")
      ->expected(4)->allow_extra_args(false);
  cmd->add_option("--screen", o->screen, "Screen size in pixels W H (8514/A: 1024 768)")
      ->expected(2)->allow_extra_args(false);
  cmd->add_option(
         "--max-depth", o->maxDepth,
         "Recursion depth limit (listing MaxDepth: 5; written as max_trace_level MaxDepth + 1)")
      ->check(CLI::Range(0, 255));
  cmd->add_flag("--model", o->model,
                "Build the databases from the text inputs first (prime model)");
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      const Scene scene = loadForExport(*dir, o->model);
      const std::filesystem::path target(*out);
      PovExportOptions po;
      po.camera = cameraOf(*o);
      po.maxDepth = o->maxDepth;
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
