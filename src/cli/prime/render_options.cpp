#include "src/cli/prime/render_options.h"

#include <filesystem>
#include <iostream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/run_inputs.h"
#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/model_commit.h"
#include "src/cli/option_values.h"
#include "src/prime/render/probe.h"
#include "src/prime/scene/scene_loader.h"

namespace prime::cli {

namespace fs = std::filesystem;

namespace {
// A pixel's several rays: --samples, --adaptive, --jitter, --statistical and theirs.
void addSamplingOptions(CLI::App* cmd, RenderOptions& o) {
  cmd->add_option("--samples", o.samples, "Regular N x N supersampling (listing: 1 ray per pixel)")
      ->check(CLI::Range(1, 16));
  cmd->add_option(
         "--adaptive", o.adaptiveTolerance,
         "Whitted's adaptive supersampling: subdivide where the 5 rays differ by more than this")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--adaptive-levels", o.settings.sampling.maxLevel,
                  "Subdivision levels for --adaptive (2)")
      ->check(CLI::Range(0, 6));
  cmd->add_option("--jitter", o.jitter,
                  "Stochastic supersampling (thesis 2.6.2): N x N strata, one random ray in each")
      ->check(CLI::Range(1, 16));
  cmd->add_option("--statistical", o.statisticalBound,
                  "Statistical supersampling (thesis 2.6.3): random rays four at a time until the "
                  "confidence interval of the pixel's mean is within +-BOUND in every channel")
      ->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--confidence", o.settings.sampling.confidence,
                  "Confidence of --statistical's interval (0.95)")
      ->check(CLI::Range(0.5, 0.9999));
  cmd->add_option("--min-samples", o.settings.sampling.minSamples,
                  "Rays per pixel before --statistical may stop (4, the thesis' first four)")
      ->check(CLI::Range(4, 4096));
  cmd->add_option("--max-samples", o.settings.sampling.maxSamples,
                  "Rays per pixel at most for --statistical (64)")
      ->check(CLI::Range(4, 4096));
}
}  // namespace

void addRenderOptions(CLI::App* cmd, RenderOptions& o, bool sampling) {
  addCameraOptions(cmd, o.camera);
  addFreeCameraOptions(cmd, o.camera);
  cmd->add_option("--max-depth", o.settings.trace.maxDepth,
                  "Recursion depth limit (listing MaxDepth: 5)")
      ->check(CLI::Range(0, 64));
  cmd->add_option(
         "--tir-cap", o.settings.trace.tirCap,
         "1991 profile: total-internal-reflection steps before giving up (errata E59: 1000; 0 = "
         "never, may hang); the modern profile stops at 64")
      ->check(atLeast(0));
  cmd->add_flag("--skip-empty-right", o.settings.trace.csg.skipRightWhenLeftEmpty,
                "Errata Q4 alternative: skip the right subtree when the left list is empty");
  cmd->add_flag(
      "--no-skip", [&o](std::int64_t) { o.settings.trace.skipUnneededWork = false; },
      "Do all the work the listing did: reflected/transmitted rays even where kSR/kST = 0, "
      "and every right CSG subtree (same pixels, more rays)");
  if (sampling) addSamplingOptions(cmd, o);
  cmd->add_option("--seed", o.settings.sampling.seed,
                  "Seed of --jitter's, --statistical's and the soft shadows' random numbers (1)");
  cmd->add_option("--light-radius", o.lightRadius,
                  "Thesis profile: lights are discs of this radius (soft shadows); one value for "
                  "every light, or one per light in the light file's order")
      ->expected(1, 10)
      ->check(atLeast(0));
  cmd->add_flag("--no-shadows", o.noShadows,
                "Thesis profile: cast no shadow rays (every light reaches every point)");
  cmd->add_option("--texel", o.texel,
                  "Thesis profile: the texel is F(0) of the Fresnel terms and colours the diffuse "
                  "terms (both, default), or only F(0) as the listing uses it (fresnel)")
      ->check(CLI::IsMember({"both", "fresnel"}));
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
         "arithmetic and correct geometry (docs/prime/deviations.md); thesis: the modern one plus "
         "what the thesis describes: shadow rays, Hall's model as written, soft shadows "
         "(docs/prime/thesis-profile.md)")
      ->check(CLI::IsMember({"1991", "modern", "thesis"}));
  cmd->add_option_function<std::string>(
         "--fix",
         [&o](const std::string& ids) {
           try {
             o.settings.trace.fixes = parseListingFixes(ids);
           } catch (const std::invalid_argument& e) {
             throw CLI::ValidationError("--fix", e.what());
           }
           o.fixGiven = true;
         },
         "1991 profile: correct these listing quirks and no other (K4, K5, K10, K15, K18 or all; "
         "prime errata lists every K id)")
      ->type_name("ID[,ID...]");
  cmd->add_flag("--model", o.model, "Build the databases from the text inputs first (prime model)");
  // Combinations no single option can check: usage errors (exit 2) at parse time.
  cmd->parse_complete_callback([&o] {
    const int modes = (o.samples > 1) + (o.adaptiveTolerance >= 0.0) + (o.jitter > 0) +
                      (o.statisticalBound >= 0.0);
    if (modes > 1)
      throw CLI::ValidationError("sampling",
                                 "choose one of --samples, --adaptive, --jitter, --statistical");
    if (o.fixGiven && o.profile != "1991")
      throw CLI::ValidationError("--fix", "corrects quirks of the 1991 profile; the " + o.profile +
                                              " profile has its own corrections");
    if (o.profile != "thesis" && (!o.lightRadius.empty() || o.noShadows || o.texel != "both"))
      throw CLI::ValidationError("--light-radius/--no-shadows/--texel",
                                 "only the thesis profile has them (add --profile thesis)");
    if (o.settings.sampling.maxSamples < o.settings.sampling.minSamples)
      throw CLI::ValidationError("--max-samples", "must be at least --min-samples");
  });
}

void finishRenderOptions(RenderOptions& o, int freeSide) {
  applyCameraOptions(o.camera, o.settings.camera, freeSide);
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
  o.settings.profile = o.profile == "modern"   ? Profile::Modern
                       : o.profile == "thesis" ? Profile::Thesis
                                               : Profile::Listing1991;
  if (o.lightRadius.size() == 1)
    o.settings.thesis.lightRadius = o.lightRadius[0];
  else
    o.settings.thesis.lightRadii = o.lightRadius;
  o.settings.thesis.shadows = !o.noShadows;
  o.settings.thesis.texelInDiffuse = o.texel == "both";
  if (o.jitter > 0) {
    o.settings.sampling.mode = Sampling::Mode::Jittered;
    o.settings.sampling.gridN = o.jitter;
  }
  if (o.statisticalBound >= 0.0) {
    o.settings.sampling.mode = Sampling::Mode::Statistical;
    o.settings.sampling.bound = o.statisticalBound;
  }
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
    io::forgetInputsContent();  // the render's digest: of the databases it reads
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
