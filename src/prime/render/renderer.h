// RayTrace.c's main loop: one ray tree per pixel of the listing's window,
// ColorNum'ed to a palette index and collected into a graph file (PRIME's
// "film"). The rows go through the shared scheduler (src/render/render_rows.h)
// and the optional supersampling through the shared sampler
// (src/prime/render/pixel_sampling.h); what is PRIME's is here: the profile's
// tracer, the listing's camera, the primary-ray mask and ColorNum.
#pragma once
#include <atomic>
#include <functional>
#include <optional>

#include "legacy_io/prime/graph_file.h"
#include "src/prime/render/camera.h"
#include "src/prime/render/pixel_sampling.h"
#include "src/prime/render/primary_mask.h"
#include "src/prime/render/tracer_1991.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/render/tracer_thesis.h"
#include "src/render/render_rows.h"
#include "src/render/rgb_image.h"

namespace prime {

// The primary-ray mask (deviation W6) a render with `tracer` uses for
// `camera`, as `prime trace` and `prime walk` use it: the leaf primitives'
// boxes in the 1991 profile (none when it does not skip unneeded work), the
// same boxes with the hulls about them in the modern and thesis profiles.
std::optional<PrimaryRayMask> primaryMaskFor(const Tracer1991& tracer, const PrimeCamera& camera);
std::optional<PrimaryRayMask> primaryMaskFor(const TracerModern& tracer, const PrimeCamera& camera);
std::optional<PrimaryRayMask> primaryMaskFor(const TracerThesis& tracer, const PrimeCamera& camera);
// What a tracer's castRay returns for a primary ray the mask rules out (the
// background), counted as a primary ray the mask answered.
inline Rgb maskedPrimaryRay(const Scene& scene, TraceStats& stats) {
  ++stats.primaryRays;
  ++stats.maskedPrimaryRays;
  return {scene.background[0], scene.background[1], scene.background[2]};
}

enum class ColorMapping { Listing, Plate3 };  // ColorNum (K16) or the X1 16x16 red/green table

// Thesis: the renderer the thesis describes (docs/prime/thesis-profile.md).
enum class Profile { Listing1991, Modern, Thesis };

struct RenderSettings {
  Profile profile = Profile::Listing1991;
  CameraSettings camera;
  Sampling sampling;
  TraceOptions trace;
  ThesisOptions thesis;  // the thesis profile only: shadows, light radii, the texel's role
  int threads = 0;       // 0: all cores
  int graphType = 1;     // written to graph_scr and passed to ColorNum (1 = IBM8514HI)
  ColorMapping mapping = ColorMapping::Listing;
  // Keep every pixel's unquantised colour in RenderResult::rgb (true-colour
  // PNG, prime bench); false leaves rgb empty and saves its memory.
  bool keepColours = true;
  // Each row's counts (--pace 1991 and --record: the era model's cost of a
  // row), written into (*rowStats)[row] before the row's rowDone; render()
  // sizes it. Null: not kept.
  std::vector<TraceStats>* rowStats = nullptr;
};

struct RenderResult {
  io::GraphFile graph;  // header 349 x 768 etc., (across+1) x (down+1) pixels
  RgbImage rgb;         // the unquantised colour of each pixel, same order
  TraceStats stats;
  std::uint64_t samples = 0;  // rays per pixel summed (Grid, Jittered, Statistical; else 0)
  double seconds = 0;
  int threads = 1;
  bool aborted = false;  // stopped by `abort` before the last row
  int rowsDone = 0;      // rows rendered: all of the band's unless aborted
  int rows = 0;          // rows in the band (the picture's, without --rows)
};

// The shared scheduler's callbacks, with each finished row's palette
// indices (what the live 8514/A screen draws).
// Rows of palette indices, from the top of the graph file's picture.
using RenderCallbacks = PictureCallbacks<std::int16_t>;

RenderResult render(const Scene& scene, const RenderSettings& settings,
                    const RenderCallbacks& callbacks = {});

// One pixel's index from its colour, as the settings map it.
int paletteIndex(const Rgb& color, const RenderSettings& settings, TraceStats& stats);

}  // namespace prime
