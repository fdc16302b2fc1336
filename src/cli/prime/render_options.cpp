#include "src/cli/prime/render_options.h"

#include <filesystem>
#include <iostream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/run_inputs.h"
#include "legacy_io/prime/model_builder.h"
#include "src/prime/render/probe.h"
#include "legacy_io/prime/model_commit.h"
#include "src/prime/scene/scene_loader.h"

namespace prime::cli {

namespace fs = std::filesystem;

void addRenderOptions(CLI::App* cmd, RenderOptions& o) {
  addCameraOptions(cmd, o.camera);
  addFreeCameraOptions(cmd, o.camera);
  cmd->add_option("--max-depth", o.settings.trace.maxDepth,
                  "Recursion depth limit (listing MaxDepth: 5)")
      ->check(CLI::Range(0, 64));
  cmd->add_option(
         "--tir-cap", o.settings.trace.tirCap,
         "1991 profile: total-internal-reflection steps before giving up (errata E59: 1000; 0 = "
         "never, may hang); the modern profile stops at 64")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--skip-empty-right", o.settings.trace.csg.skipRightWhenLeftEmpty,
                "Errata Q4 alternative: skip the right subtree when the left list is empty");
  cmd->add_flag(
      "--no-skip", [&o](std::int64_t) { o.settings.trace.skipUnneededWork = false; },
      "Do all the work the listing did: reflected/transmitted rays even where kSR/kST = 0, "
      "and every right CSG subtree (same pixels, more rays)");
  cmd->add_option("--samples", o.samples, "Regular N x N supersampling (listing: 1 ray per pixel)")
      ->check(CLI::Range(1, 16));
  cmd->add_option(
         "--adaptive", o.adaptiveTolerance,
         "Whitted's adaptive supersampling: subdivide where the 5 rays differ by more than this")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--adaptive-levels", o.settings.sampling.maxLevel,
                  "Subdivision levels for --adaptive (2)")
      ->check(CLI::Range(0, 6));
  cmd->add_option(
         "--min-weight", o.settings.trace.minWeight,
         "Adaptive tree-depth control: do not cast rays weighing less than this (listing: 0, off)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--palette", o.palette,
                  "Colour mapping: listing (ColorNum, 3-3-2) or plate3 (16x16 red/green, X1)")
      ->check(CLI::IsMember({"listing", "plate3"}));
  cmd->add_option(
         "--profile", o.profile,
         "1991: the listing, quirks and all (default); modern: the same scenes with robust "
         "arithmetic and correct geometry (docs/prime/deviations.md)")
      ->check(CLI::IsMember({"1991", "modern"}));
  cmd->add_flag("--model", o.model, "Build the databases from the text inputs first (prime model)");
}

void finishRenderOptions(RenderOptions& o) {
  applyCameraOptions(o.camera, o.settings.camera);
  // R10: a window of no size casts every primary ray in one direction (or
  // none); the listing would have drawn one flat colour and exited 0. The
  // window runs across from --window-left to --window-right, and down from
  // --window-left to the origin (K23).
  const CameraSettings& c = o.settings.camera;
  if (c.windowLeft == c.windowRight)
    throw CLI::ValidationError("--window-left/--window-right",
                               "the window has zero width: both corners are " + fmt(c.windowLeft));
  if (c.windowLeft == Vec3{0, 0, 0})
    throw CLI::ValidationError(
        "--window-left",
        "the window has zero height: its top-left corner is the origin (the window runs down "
        "from it to the origin, errata K23)");
  o.settings.mapping = o.palette == "plate3" ? ColorMapping::Plate3 : ColorMapping::Listing;
  o.settings.profile = o.profile == "modern" ? Profile::Modern : Profile::Listing1991;
  if (o.samples > 1) {
    o.settings.sampling.mode = Sampling::Mode::Grid;
    o.settings.sampling.gridN = o.samples;
  }
  if (o.adaptiveTolerance >= 0.0) {
    o.settings.sampling.mode = Sampling::Mode::Adaptive;
    o.settings.sampling.tolerance = o.adaptiveTolerance;
  }
}

Scene prepareScene(const std::string& dir, bool model) {
  const io::SceneDir scene(dir);
  if (model) {
    const auto lock = io::lockForModel(scene, /*wait=*/false);
    const io::Model built = io::buildModel(scene);
    io::writeModel(scene, built, lock.get());
    for (const auto& w : built.warnings) std::cerr << "prime: warning: " << w << "\n";
  }
  // Held while the databases are read: no prime model switches them meanwhile.
  const auto reading = io::openModelForReading(scene);  // M19
  // No output of this run may overwrite a text input or database of the scene.
  for (const auto& f : scene.inputFiles()) io::protectInput(f.string(), scene.display(f));
  if (auto stale = model ? std::vector<std::string>{} : staleDatabases(scene); !stale.empty()) {
    std::string msg = "the scene's databases are not up to date:";
    for (const auto& s : stale) msg += "\n  " + s;
    // A directory of databases only (a DOS disk's) has nothing to model from.
    if (fs::exists(scene.find(".", "Model.txt")))
      msg += "\nrun `prime model " + dir + "` first, or add --model";
    else
      msg +=
          "\nthe scene has no Model.txt to build them from: copy its databases (prim/PrimFile, "
          "obj/List, obj/O<n>, map/) with it";
    throw io::InputError({dir, std::nullopt, std::nullopt}, msg);
  }
  Scene loaded = loadScene(scene);
  for (const auto& w : sharedSubtreeWarnings(loaded)) std::cerr << "prime: warning: " << w << "\n";
  return loaded;
}

}  // namespace prime::cli
