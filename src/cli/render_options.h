// Options shared by `prime trace` and `prime probe`: the camera and window of
// RayTrace.c (each listing constant overridable), the tracing limits, and the
// staleness check of the scene's databases.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "src/render/renderer.h"

namespace prime::cli {

struct RenderOptions {
  RenderSettings settings;
  std::vector<double> eye, windowLeft, windowRight, viewport;
  std::vector<int> screen;
  bool model = false;  // --model: run `prime model` first
  std::string palette = "listing";
  std::string profile = "1991";
  int samples = 1;
  double adaptiveTolerance = -1.0;  // < 0: off
};

void addRenderOptions(CLI::App* cmd, RenderOptions& o);
// Copies the parsed vectors into o.settings.
void finishRenderOptions(RenderOptions& o);
// Loads the scene, after modelling it (--model) or checking it is up to date.
Scene prepareScene(const std::string& dir, const RenderOptions& o);

}  // namespace prime::cli
