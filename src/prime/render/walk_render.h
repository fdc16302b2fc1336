// One pass of `prime walk`'s progressive picture (src/render/progressive.h)
// for a PRIME scene: every block x block block of the free camera's picture
// gets the colour of the ray through its top-left pixel's centre, traced by
// the chosen profile's tracer (the 1991 one with the listing's quirks: the
// listing's camera is replaced by the free one, T31). The last pass
// (block 1) gives exactly the pixels `prime trace` gives with the same free
// camera and one ray per pixel. Rows of blocks go through renderRows.
#pragma once
#include <atomic>
#include <functional>
#include <optional>

#include "src/prime/render/renderer.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/render/tracer_thesis.h"
#include "src/render/render_rows.h"

namespace prime {

class WalkRenderer {
 public:
  // Keeps a reference to `scene` (with the lights where the user put them).
  // Throws std::invalid_argument for a profile it cannot trace.
  // The thesis profile traces one ray per block with one fixed soft-shadow
  // sample (SampleId{}): shadows from one point of each light, no noise.
  WalkRenderer(const Scene& scene, Profile profile, const TraceOptions& options,
               const ThesisOptions& thesis = {});

  // Renders pass `block` (firstBlock: the coarsest of this frame, sampling
  // everything) into `out` (camera-sized; it keeps the previous pass's
  // colours, which this pass reuses on its grid). rowsDone(row0, rows) runs
  // on the calling thread when picture rows row0 .. row0+rows-1 are final
  // for this pass. Returns false when `abandon` stopped it.
  bool pass(const FreeCamera& camera, int block, int firstBlock, RgbImage& out, int threads,
            const std::atomic<bool>* abandon, const std::function<void(int, int)>& rowsDone,
            TraceStats& stats, ThreadReport* report = nullptr) const;

 private:
  template <class Tracer>
  bool passWith(const Tracer& tracer, const FreeCamera& camera, int block, int firstBlock,
                RgbImage& out, int threads, const std::atomic<bool>* abandon,
                const std::function<void(int, int)>& rowsDone, TraceStats& stats,
                ThreadReport* report) const;
  std::optional<Tracer1991> t1991_;
  std::optional<TracerModern> modern_;
  std::optional<TracerThesis> thesis_;
};

}  // namespace prime
