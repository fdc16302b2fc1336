// prime compare DIR [--a "SETTINGS"] [--b "SETTINGS"]: render a scene twice
// (by default the 1991 profile and the thesis renderer, or the modern profile
// where there is no thesis profile: T35), write one PNG with A, B and their
// difference side by side (T36), and report how many pixels differ and, for
// a sample of them, the first ray where the two ray trees part (the probe's
// records of both, T37).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "palette/png_image.h"
#include "palette/prime/export.h"
#include "src/cli/commands.h"
#include "src/cli/prime/render_options.h"
#include "src/prime/render/compare.h"
#include "src/prime/render/tracer_modern.h"

namespace prime::cli {

namespace {

constexpr int kGap = 4;  // grey columns between the three pictures

// Any of trace's render options, from one string ("--profile modern --samples 2").
RenderSettings parseSettings(const std::string& text, const std::string& which) {
  CLI::App sub{"settings " + which, "prime compare " + which};
  RenderOptions o;
  addRenderOptions(&sub, o);
  try {
    sub.parse(text, false);
  } catch (const CLI::ParseError& e) {
    throw CLI::ValidationError(which, "\"" + text + "\": " + e.what());
  }
  finishRenderOptions(o);
  o.settings.keepColours = true;
  return o.settings;
}

// The default B: the thesis renderer when this build has it (T35).
std::string defaultB() {
  try {
    parseSettings("--profile thesis", "--b");
    return "--profile thesis";
  } catch (const CLI::ValidationError&) {
    return "--profile modern";
  }
}

// The probe's record of one ray tree in the settings' profile (nothing for a
// profile the probe does not trace), with the profile's tracer (and its BVH)
// built once for all the sampled pixels.
class ProbeTracer {
 public:
  ProbeTracer(const Scene& scene, const RenderSettings& s) : s_(s) {
    if (s.profile == Profile::Thesis)
      thesis_.emplace(scene, s.trace, s.thesis);
    else if (s.profile == Profile::Modern)
      modern_.emplace(scene, s.trace);
    else if (s.profile == Profile::Listing1991)
      t1991_.emplace(scene, s.trace);
  }
  std::optional<std::vector<ProbeEvent>> tree(int row, int column, const Ray& ray,
                                              Rgb& colour) const {
    TraceStats stats;
    Probe probe;
    if (thesis_) {
      // The pixel's sample 0, as `prime probe` traces it (T16).
      const SampleId sample{PixelKey{s_.sampling.seed, static_cast<std::uint32_t>(row),
                                     static_cast<std::uint32_t>(column)},
                            0};
      colour = thesis_->castRay(ray, 0, stats, sample, &probe);
    } else if (modern_) {
      colour = modern_->castRay(ray, 0, stats, &probe);
    } else if (t1991_) {
      colour = t1991_->castRay(ray, 0, stats, &probe);
    } else {
      return std::nullopt;
    }
    return std::move(probe.events);
  }

 private:
  const RenderSettings& s_;
  std::optional<TracerThesis> thesis_;
  std::optional<TracerModern> modern_;
  std::optional<Tracer1991> t1991_;
};

void put(Image8& img, int x, int y, Rgb8 c) {
  const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 3;
  img.rgb[i] = c.r;
  img.rgb[i + 1] = c.g;
  img.rgb[i + 2] = c.b;
}

// A | B | difference: equal pixels as A's grey at a quarter, differing ones
// magenta, brighter the larger the difference (a difference of 1/4 or more
// is full magenta).
Image8 sideBySide(const RenderResult& a, const RenderResult& b) {
  const int w = a.rgb.width, h = a.rgb.height;
  Image8 img;
  img.width = 3 * w + 2 * kGap;
  img.height = h;
  img.rgb.assign(static_cast<std::size_t>(img.width) * h * 3, 96);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgb& ca = a.rgb.at(y, x);
      const Rgb& cb = b.rgb.at(y, x);
      const Rgb8 ta = trueColour(ca), tb = trueColour(cb);
      put(img, x, y, ta);
      put(img, w + kGap + x, y, tb);
      Rgb8 d;
      if (std::memcmp(ca.data(), cb.data(), sizeof ca) == 0) {
        const auto grey = static_cast<std::uint8_t>((ta.r * 3 + ta.g * 6 + ta.b) / 40);
        d = {grey, grey, grey};
      } else {
        const double s = std::min(1.0, 4.0 * colourDifference(ca, cb));
        const auto v = static_cast<std::uint8_t>(std::lround(96.0 + 159.0 * s));
        d = {v, 0, v};
      }
      put(img, 2 * (w + kGap) + x, y, d);
    }
  return img;
}

}  // namespace

void addCompareCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "compare",
      "Render a scene with two settings (1991 profile and thesis renderer by default) and show "
      "both and their difference side by side, with where the rays diverge");
  auto dir = std::make_shared<std::string>();
  auto a = std::make_shared<std::string>("--profile 1991");
  auto b = std::make_shared<std::string>();
  auto png = std::make_shared<std::string>();
  auto samples = std::make_shared<int>(5);
  auto model = std::make_shared<bool>(false);
  auto threads = std::make_shared<int>(0);
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--a", *a, "Settings of A, any of trace's render options (\"--profile 1991\")");
  cmd->add_option("--b", *b,
                  "Settings of B (\"--profile thesis\"; \"--profile modern\" in a build without "
                  "the thesis profile)");
  cmd->add_option("--png", *png, "The side-by-side PNG: A | B | difference (DIR/compare.png)");
  cmd->add_option("--divergence-samples", *samples,
                  "Differing pixels whose ray trees are probed for where they part (5)")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--threads", *threads, "Render threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--model", *model, "Build the databases from the text inputs first (prime model)");
  cmd->callback([=, &action] {
    action = [=] {
      const std::string textB = b->empty() ? defaultB() : *b;
      RenderSettings sa = parseSettings(*a, "--a");
      RenderSettings sb = parseSettings(textB, "--b");
      if (*threads > 0) sa.threads = sb.threads = *threads;
      const Scene scene = prepareScene(*dir, *model);
      const RenderResult ra = render(scene, sa);
      const RenderResult rb = render(scene, sb);
      if (ra.rgb.width != rb.rgb.width || ra.rgb.height != rb.rgb.height)
        throw CLI::ValidationError(
            "--b", "A is " + std::to_string(ra.rgb.width) + " x " + std::to_string(ra.rgb.height) +
                       " pixels and B " + std::to_string(rb.rgb.width) + " x " +
                       std::to_string(rb.rgb.height) + ": give both the same camera size");
      const RenderComparison c = compareRenders(ra, rb, *samples);
      std::printf("%s: %d x %d pixels\n", scene.name.c_str(), ra.rgb.width, ra.rgb.height);
      std::printf("A: %s (%.2f s, %llu rays)\n", a->c_str(), ra.seconds,
                  static_cast<unsigned long long>(ra.stats.rays()));
      std::printf("B: %s (%.2f s, %llu rays)\n", textB.c_str(), rb.seconds,
                  static_cast<unsigned long long>(rb.stats.rays()));
      std::printf("pixels differing: %zu of %zu (%.2f%%); palette indices differing: %zu\n",
                  c.differing, c.pixels, 100.0 * c.share(), c.indexDiffering);
      if (c.differing > 0)
        std::printf(
            "largest channel difference %.4f (of 1) at pixel %d %d; mean over all pixels %.5f\n",
            c.maxDifference, c.maxColumn, c.maxRow, c.meanDifference);
      if (!c.sample.empty()) {
        std::printf(
            "where the rays diverge (%zu differing pixels; ray 0 is the primary ray; "
            "prime probe DIR --pixel X Y with the same settings shows a whole tree):\n",
            c.sample.size());
        const PrimeCamera ca(sa.camera), cb(sb.camera);
        const ProbeTracer pa(scene, sa), pb(scene, sb);
        for (const auto& [row, column] : c.sample) {
          Rgb colA{}, colB{};
          const auto ea = pa.tree(row, column, ca.primaryRay(row, column), colA);
          const auto eb = pb.tree(row, column, cb.primaryRay(row, column), colB);
          std::printf("  pixel %d %d: ", column, row);
          if (!ea || !eb) {
            std::printf("the probe does not trace this profile\n");
            continue;
          }
          const RayDivergence d = firstDivergence(*ea, *eb);
          if (d.firstDiffering < 0) {
            std::printf("the %d rays agree; the shading differs: A %s, B %s\n", d.raysA,
                        fmt(colA).c_str(), fmt(colB).c_str());
          } else {
            std::printf(
                "rays 0..%d agree, ray %d differs (A has %d rays, B %d)\n    A: %s\n    "
                "B: %s\n",
                d.firstDiffering - 1, d.firstDiffering, d.raysA, d.raysB,
                d.rayA.empty() ? "(no such ray)" : d.rayA.c_str(),
                d.rayB.empty() ? "(no such ray)" : d.rayB.c_str());
          }
        }
      }
      const std::string out = png->empty() ? *dir + "/compare.png" : *png;
      writePng(out, sideBySide(ra, rb));
      std::printf(
          "wrote %s: A | B | difference (equal: A's grey, dimmed; differing: magenta, "
          "full at a channel difference of 0.25)\n",
          out.c_str());
      return 0;
    };
  });
}

}  // namespace prime::cli
