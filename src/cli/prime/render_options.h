// Options shared by `prime trace` and `prime probe`: the camera and window of
// RayTrace.c (each listing constant overridable), the tracing limits, and the
// staleness check of the scene's databases.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "src/cli/prime/camera_options.h"
#include "src/prime/render/renderer.h"

namespace prime::cli {

struct RenderOptions {
  RenderSettings settings;
  CameraOptions camera;
  bool model = false;  // --model: run `prime model` first
  std::string palette = "listing";
  std::string profile = "1991";
  int samples = 1;
  double adaptiveTolerance = -1.0;  // < 0: off
  int jitter = 0;                   // --jitter N (0: off)
  double statisticalBound = -1.0;   // --statistical BOUND (< 0: off)
  std::vector<double> lightRadius;  // --light-radius R [R ...] (thesis profile)
  bool noShadows = false;           // --no-shadows (thesis profile)
  std::string texel = "both";       // --texel fresnel|both (thesis profile, T8)
  bool fixGiven = false;            // --fix (1991 profile only)
};

// `sampling`: also the options of a pixel's several rays (--samples, --adaptive,
// --jitter, --statistical and theirs); `walk` takes one ray per pixel.
void addRenderOptions(CLI::App* cmd, RenderOptions& o, bool sampling = true);
// Copies the parsed vectors into o.settings; a free camera's default size is
// `freeSide` x `freeSide` (applyCameraOptions).
void finishRenderOptions(RenderOptions& o, int freeSide = 769);
// Loads the scene, after modelling it (`model`: --model) or checking that its
// databases are up to date (else an InputError saying what to run).
Scene prepareScene(const std::string& dir, bool model);

}  // namespace prime::cli
