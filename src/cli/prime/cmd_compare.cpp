// prime compare DIR [--a "SETTINGS"] [--b "SETTINGS"]: render a scene twice
// (by default the 1991 profile and the thesis renderer, or the modern profile
// where there is no thesis profile: T35), write one PNG with A, B and their
// difference side by side (T36), and report how many pixels differ and, for
// a sample of them, the first ray where the two ray trees part (the probe's
// records of both, T37).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>

#include "palette/png_image.h"
#include "palette/prime/export.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/render_options.h"
#include "src/prime/bench/plot.h"
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

// CIE L*a*b* of an 8-bit sRGB colour (D65), for the difference panel's
// perceptual distance (CIE76 delta E).
std::array<double, 3> lab(Rgb8 c) {
  auto linear = [](std::uint8_t v) {
    const double x = v / 255.0;
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
  };
  const double r = linear(c.r), g = linear(c.g), b = linear(c.b);
  const double X = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double Y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double Z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
  };
  return {116.0 * f(Y) - 16.0, 500.0 * (f(X) - f(Y)), 200.0 * (f(Y) - f(Z))};
}

double deltaE(Rgb8 p, Rgb8 q) {
  const auto a = lab(p), b = lab(q);
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// A perceptually ordered heat scale (matplotlib's inferno, eight stops),
// s in [0, 1]: black through purple, red and orange to pale yellow.
Rgb8 heat(double s) {
  static constexpr std::array<std::array<double, 3>, 8> kStops{{{0, 0, 4},
                                                                {40, 11, 84},
                                                                {101, 21, 110},
                                                                {159, 42, 99},
                                                                {212, 72, 66},
                                                                {245, 125, 21},
                                                                {250, 193, 39},
                                                                {252, 255, 164}}};
  const double x = std::clamp(s, 0.0, 1.0) * (kStops.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(x), kStops.size() - 2);
  const double t = x - static_cast<double>(i);
  auto ch = [&](int k) {
    return static_cast<std::uint8_t>(std::lround(kStops[i][static_cast<std::size_t>(k)] * (1 - t) +
                                                 kStops[i + 1][static_cast<std::size_t>(k)] * t));
  };
  return {ch(0), ch(1), ch(2)};
}

// 1, 2 or 5 times a power of ten, at least v.
double niceCeiling(double v) {
  double p = std::pow(10.0, std::floor(std::log10(std::max(v, 1e-9))));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= v) return m * p;
  return 10.0 * p;
}

// What a panel's caption says of its settings: profile, --fix set, camera.
std::string settingsCaption(const RenderSettings& s) {
  std::string text = std::string("PRIME, ") +
                     (s.profile == Profile::Modern   ? "MODERN"
                      : s.profile == Profile::Thesis ? "THESIS"
                                                     : "1991") +
                     " PROFILE";
  if (const std::string ids = fixIds(s.trace.fixes); !ids.empty()) text += ", --FIX " + ids;
  if (s.camera.free) {
    const FreeCameraSettings& c = *s.camera.free;
    char cam[96];
    std::snprintf(cam, sizeof cam, ", FREE CAMERA %dX%d FOV %.4g", c.width, c.height, c.fovY);
    text += cam;
  } else {
    text += ", LISTING CAMERA";
  }
  return text;
}

constexpr bench::Colour kInk{235, 235, 235};

// `text` at (x, y) at `scale`, cut with "..." where it does not fit `width`.
void caption(Image8& img, int x, int y, int width, std::string text, int scale) {
  while (bench::textWidth(text, scale) > width && text.size() > 4)
    text = text.substr(0, text.size() - 4) + "...";
  bench::drawText(img, x, y, text, kInk, scale);
}

struct Captions {
  std::string a1, a2, b1, b2, d1;
};

// Captions over A | B | difference. Equal pixels in the difference panel
// are A's grey at a quarter; differing ones carry a heat colour for their
// CIE76 delta E (0 .. the scale, the 95th percentile of the differing
// pixels' delta E rounded up to 1, 2 or 5 x 10^k) over that grey, more
// opaque the larger the difference; a legend bar gives the scale.
Image8 sideBySide(const RenderResult& a, const RenderResult& b, Captions cap, double& scaleOut) {
  const int w = a.rgb.width, h = a.rgb.height;
  constexpr int kLine = 14, kTop = 3 * kLine + 6;
  Image8 img;
  img.width = 3 * w + 2 * kGap;
  img.height = h + kTop;
  img.rgb.assign(static_cast<std::size_t>(img.width) * img.height * 3, 48);
  std::vector<double> de(static_cast<std::size_t>(w) * h, 0.0);
  std::vector<double> differing;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgb& ca = a.rgb.at(y, x);
      const Rgb& cb = b.rgb.at(y, x);
      if (std::memcmp(ca.data(), cb.data(), sizeof ca) == 0) continue;
      const double d = deltaE(trueColour(ca), trueColour(cb));
      de[static_cast<std::size_t>(y) * w + x] = d;
      differing.push_back(d);
    }
  double scale = 1.0;
  if (!differing.empty()) {
    const auto k = differing.begin() + static_cast<std::ptrdiff_t>(differing.size() * 95 / 100);
    std::nth_element(differing.begin(), k, differing.end());
    scale = niceCeiling(std::max(*k, 1.0));
  }
  scaleOut = scale;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgb& ca = a.rgb.at(y, x);
      const Rgb& cb = b.rgb.at(y, x);
      const Rgb8 ta = trueColour(ca), tb = trueColour(cb);
      put(img, x, kTop + y, ta);
      put(img, w + kGap + x, kTop + y, tb);
      const double grey = (ta.r * 3 + ta.g * 6 + ta.b) / 40.0;
      Rgb8 d{static_cast<std::uint8_t>(grey), static_cast<std::uint8_t>(grey),
             static_cast<std::uint8_t>(grey)};
      if (std::memcmp(ca.data(), cb.data(), sizeof ca) != 0) {
        const double s = std::min(1.0, de[static_cast<std::size_t>(y) * w + x] / scale);
        const Rgb8 hc = heat(0.15 + 0.85 * s);  // the smallest difference still shows
        const double alpha = 0.45 + 0.55 * s;
        auto mix = [&](std::uint8_t c) {
          return static_cast<std::uint8_t>(std::lround(grey * (1 - alpha) + c * alpha));
        };
        d = {mix(hc.r), mix(hc.g), mix(hc.b)};
      }
      put(img, 2 * (w + kGap) + x, kTop + y, d);
    }
  // One size for every caption: 2 when all fit, else 1.
  int fs = 2;
  for (const std::string* t : {&cap.a1, &cap.a2, &cap.b1, &cap.b2, &cap.d1})
    if (bench::textWidth(*t, 2) > w - 4) fs = 1;
  caption(img, 2, 3, w - 4, cap.a1, fs);
  caption(img, 2, 3 + kLine, w - 4, cap.a2, fs);
  caption(img, w + kGap + 2, 3, w - 4, cap.b1, fs);
  caption(img, w + kGap + 2, 3 + kLine, w - 4, cap.b2, fs);
  const int dx = 2 * (w + kGap);
  caption(img, dx + 2, 3, w - 4, cap.d1, fs);
  // The legend: the heat scale from 0 to `scale`, as the panel blends it at full opacity.
  char right[32];
  std::snprintf(right, sizeof right, "DE %g", scale);
  const int labelW = bench::textWidth("0", 1) + bench::textWidth(right, 1) + 8;
  const int bar = std::max(8, std::min(w - 4 - labelW, 160));
  const int by = 3 + kLine + 2;
  bench::drawText(img, dx + 2, by + 1, "0", kInk, 1);
  const int bx = dx + 2 + bench::textWidth("0", 1) + 3;
  for (int i = 0; i < bar && bx + i < img.width; ++i)
    for (int yy = by; yy < by + 7; ++yy)
      put(img, bx + i, yy, heat(0.15 + 0.85 * i / std::max(bar - 1, 1)));
  if (bx + bar + 3 < img.width) bench::drawText(img, bx + bar + 3, by + 1, right, kInk, 1);
  caption(img, dx + 2, 3 + 2 * kLine + 2, w - 4, "EQUAL: A, DIMMED", fs);
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
  auto only = std::make_shared<std::string>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(sceneDirectory("compare"));
  cmd->add_option("--a", *a, "Settings of A, any of trace's render options (\"--profile 1991\")");
  cmd->add_option("--b", *b,
                  "Settings of B (\"--profile thesis\"; \"--profile modern\" in a build without "
                  "the thesis profile)");
  cmd->add_option("--png", *png, "The side-by-side PNG: A | B | difference (DIR/compare.png)")
      ->check(outputName());
  cmd->add_option("--divergence-samples", *samples,
                  "Differing pixels whose ray trees are probed for where they part (5)")
      ->check(CLI::Range(0, 1000));
  std::vector<std::string> classes(std::begin(kDivergenceClasses), std::end(kDivergenceClasses));
  cmd->add_option("--divergence-class", *only,
                  "Sample only differing pixels whose trees part at this kind of ray: primary, "
                  "reflected, transmitted, tir (a transmitted ray after other total internal "
                  "reflections), shadow, shading (the same rays, other colours)")
      ->check(CLI::IsMember(classes));
  cmd->add_option("--threads", *threads, "Render threads (default: all cores)")
      ->check(CLI::Range(0, 1024));
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
        // With --divergence-class, more differing pixels are probed (evenly
        // spread, at most 40 per sample asked) until enough of that class.
        const RenderComparison pool =
            only->empty() ? c : compareRenders(ra, rb, std::min<int>(40 * *samples, 4000));
        std::printf(
            "where the rays diverge (%s%zu differing pixels probed; ray 0 is the primary ray; "
            "prime probe DIR --pixel X Y with the same settings shows a whole tree):\n",
            only->empty() ? "" : ("pixels of class " + *only + " among ").c_str(),
            pool.sample.size());
        const PrimeCamera ca(sa.camera), cb(sb.camera);
        const ProbeTracer pa(scene, sa), pb(scene, sb);
        std::map<std::string, int> byClass;
        int shown = 0;
        for (const auto& [row, column] : pool.sample) {
          Rgb colA{}, colB{};
          const auto ea = pa.tree(row, column, ca.primaryRay(row, column), colA);
          const auto eb = pb.tree(row, column, cb.primaryRay(row, column), colB);
          if (!ea || !eb) {
            std::printf("  pixel %d %d: the probe does not trace this profile\n", column, row);
            continue;
          }
          const RayDivergence d = firstDivergence(*ea, *eb);
          std::string kinds;
          for (const std::string& k : d.kinds) {
            ++byClass[k];
            kinds += (kinds.empty() ? "" : ", ") + k;
          }
          const bool wanted =
              only->empty() || std::find(d.kinds.begin(), d.kinds.end(), *only) != d.kinds.end();
          if (!wanted || shown >= *samples) continue;
          ++shown;
          std::printf("  pixel %d %d [%s]: ", column, row, kinds.c_str());
          if (d.firstDiffering < 0) {
            std::printf(
                "the %d rays agree; %s: A %s, B %s\n", d.raysA,
                d.kind == "shadow" ? "the shadow rays' verdicts differ" : "the shading differs",
                fmt(colA).c_str(), fmt(colB).c_str());
          } else {
            // The class asked for, else the first ray that differs.
            const auto& [lineA, lineB] =
                only->empty() ? std::pair{d.rayA, d.rayB} : d.rays.at(*only);
            std::printf(
                "rays 0..%d agree, ray %d differs (A has %d rays, B %d)%s\n    A: %s\n    "
                "B: %s\n",
                d.firstDiffering - 1, d.firstDiffering, d.raysA, d.raysB,
                only->empty() ? "" : ("; its first differing " + *only + " ray").c_str(),
                lineA.empty() ? "(no such ray)" : lineA.c_str(),
                lineB.empty() ? "(no such ray)" : lineB.c_str());
          }
        }
        std::string tally;
        for (const char* k : kDivergenceClasses)
          if (byClass.count(k))
            tally +=
                (tally.empty() ? "" : ", ") + std::string(k) + " " + std::to_string(byClass[k]);
        std::printf(
            "  pixels by where their trees part (a pixel may count in two), of the %zu "
            "probed: %s\n",
            pool.sample.size(), tally.c_str());
        if (!only->empty() && shown == 0)
          std::printf("  no probed pixel's trees part at a %s ray\n", only->c_str());
      }
      const std::string out = png->empty() ? *dir + "/compare.png" : *png;
      Captions cap;
      cap.a1 = "A: " + settingsCaption(sa);
      cap.a2 = *a;
      cap.b1 = "B: " + settingsCaption(sb);
      cap.b2 = textB;
      char d1[96];
      std::snprintf(d1, sizeof d1, "DIFFERENCE: %.2f%% OF PIXELS", 100.0 * c.share());
      cap.d1 = d1;
      double scale = 0;
      writePng(out, sideBySide(ra, rb, cap, scale));
      std::printf(
          "wrote %s: A | B | difference, captioned (equal: A's grey, dimmed; differing: a heat "
          "colour for the CIE76 delta E of the two true colours, 0 .. %g, over it)\n",
          out.c_str(), scale);
      return 0;
    };
  });
}

}  // namespace prime::cli
