#include "src/cli/prime/render_options.h"

#include <iostream>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/model_builder.h"
#include "src/prime/scene/scene_loader.h"

namespace prime::cli {

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
    const io::Model built = io::buildModel(scene);
    io::writeModel(scene, built);
    for (const auto& w : built.warnings) std::cerr << "prime: warning: " << w << "\n";
  } else if (auto stale = staleDatabases(scene); !stale.empty()) {
    std::string msg = "the scene's databases are not up to date:";
    for (const auto& s : stale) msg += "\n  " + s;
    msg += "\nrun `prime model " + dir + "` first, or add --model";
    throw io::InputError({dir, std::nullopt, std::nullopt}, msg);
  }
  return loadScene(scene);
}

}  // namespace prime::cli
