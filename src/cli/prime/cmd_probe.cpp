// prime probe DIR --pixel X Y | --ray ox oy oz dx dy dz: explain one pixel
// (PRIME's part of the shared verb, src/cli/verbs.cpp).
#include <sstream>

#include "palette/prime/color_num.h"
#include "palette/prime/export.h"
#include "src/cli/option_values.h"
#include "src/cli/overlay.h"
#include "src/cli/prime/probe_pixel.h"
#include "src/cli/prime/render_options.h"
#include "src/cli/system.h"
#include "src/prime/render/tracer_modern.h"

namespace prime::cli {

namespace {

// The rays of a PRIME probe log: each "ray" event (origin, unit direction,
// kind) ends at the next "hit" or "miss" event of its depth; a "shadow"
// event (the thesis profile) runs from the last hit of its depth to the
// point of the light it aimed at.
std::vector<OverlaySegment> primeSegments(const std::vector<ProbeEvent>& events) {
  std::vector<OverlaySegment> out;
  struct Open {
    OverlaySegment seg;
    Vec3 dir{};
    int depth = 0;
  };
  std::vector<Open> open;
  std::vector<std::pair<int, Vec3>> hits;  // (depth, point), latest last
  for (const ProbeEvent& e : events) {
    if (e.kind == "ray") {
      const auto o = jsonVec3(e.json, "origin"), d = jsonVec3(e.json, "dir");
      const auto kind = overlayKind(jsonField(e.json, "kind"));
      if (!o || !d || !kind) continue;
      Open r;
      r.seg.from = *o;
      r.seg.kind = *kind;
      r.dir = *d;
      r.depth = e.depth;
      open.push_back(r);
    } else if ((e.kind == "hit" || e.kind == "miss") && !open.empty()) {
      for (auto it = open.rbegin(); it != open.rend(); ++it) {
        if (it->depth != e.depth) continue;
        const auto point = jsonVec3(e.json, "point");
        it->seg.hit = e.kind == "hit" && point.has_value();
        it->seg.to = it->seg.hit ? *point : it->seg.from + it->dir * kMissLength;
        if (it->seg.hit) hits.emplace_back(e.depth, *point);
        out.push_back(it->seg);
        open.erase(std::next(it).base());
        break;
      }
    } else if (e.kind == "shadow" && !hits.empty()) {
      if (const auto target = jsonVec3(e.json, "target"))
        out.push_back({hits.back().second, *target, OverlayKind::Shadow, false});
    }
  }
  return out;
}

}  // namespace

ProbedPixel probePixel(const Scene& scene, const RenderSettings& settings, const Ray& r,
                       const std::string& where, int column, int row) {
  // The tracer of the chosen profile; only the modern one says so (the
  // 1991 output is what it always was).
  const Profile profile = settings.profile;
  const bool modern = profile == Profile::Modern;
  const char* profileName = modern ? "modern" : profile == Profile::Thesis ? "thesis" : nullptr;
  TraceStats stats;
  Probe probe;
  Rgb color;
  if (profile == Profile::Thesis) {
    // Sample 0 of the pixel (its soft-shadow points are those of the
    // render's first sample; a --ray is pixel (0, 0)'s).
    const SampleId sample{
        PixelKey{settings.sampling.seed, static_cast<std::uint32_t>(std::max(row, 0)),
                 static_cast<std::uint32_t>(std::max(column, 0))},
        0};
    color =
        TracerThesis(scene, settings.trace, settings.thesis).castRay(r, 0, stats, sample, &probe);
  } else {
    color = modern ? TracerModern(scene, settings.trace).castRay(r, 0, stats, &probe)
                   : Tracer1991(scene, settings.trace).castRay(r, 0, stats, &probe);
  }
  const int index = paletteIndex(color, settings, stats);
  const PaletteTable table =
      settings.mapping == ColorMapping::Plate3 ? plate3Palette() : initPalette();
  const PaletteRgb shown = table[static_cast<std::size_t>(index & 0xFF)];
  ProbedPixel out;
  JsonObject doc;
  doc.add("scene", scene.name).add("where", where);
  if (profileName) doc.add("profile", profileName);
  doc.addJson("events", probe.jsonEvents())
      .add("color", color)
      .add("index", index)
      .addJson("paletteRgb", "[" + std::to_string(shown.r) + "," + std::to_string(shown.g) + "," +
                                 std::to_string(shown.b) + "]")
      .add("rays", stats.rays());
  out.json = doc.str();
  std::ostringstream text;
  text << scene.name << ": " << where
       << (profileName ? std::string(" (") + profileName + " profile)" : "") << "\n";
  for (const auto& e : probe.events)
    text << std::string(2 * e.depth + 2, ' ') << e.kind << ": " << e.text << "\n";
  text << "colour " << fmt(color) << " -> palette index " << index << " = (" << shown.r << ", "
       << shown.g << ", " << shown.b << ") of 255; " << stats.rays() << " ray(s) in the tree\n";
  out.text = text.str();
  const LinearView v = PrimeCamera(settings.camera).linearView();
  out.camera = {v.eye, v.toFirst, v.stepAcross, v.stepDown, 0.5, 0.5};
  out.segments = primeSegments(probe.events);
  out.column = column;
  out.row = row;
  return out;
}

std::string pixelWhere(const PrimeCamera& camera, int x, int y) {
  return "pixel " + std::to_string(x) + " " + std::to_string(y) + " (screen " +
         std::to_string(camera.screenX(x)) + ", " + std::to_string(camera.screenY(y)) + ")";
}

ProbeFactory addProbeOptions(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags) {
  auto dir = std::make_shared<std::string>();
  auto ray = std::make_shared<std::vector<double>>();
  auto options = std::make_shared<RenderOptions>();
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(sceneDirectory());
  auto* rx = cmd->add_option("--ray", *ray,
                             "Instead of --pixel, a world-space ray: origin x y z, direction x y z")
                 ->expected(6)
                 ->allow_extra_args(false);
  rx->excludes(cmd->get_option("--pixel"));
  addRenderOptions(cmd, *options);
  return [dir, ray, options, flags]() -> ProbeReport {
    const std::vector<int>* pixel = &flags->pixel;
    {
      if (pixel->empty() && ray->empty())
        throw CLI::ValidationError("probe", "give --pixel X Y or --ray ox oy oz dx dy dz");
      finishRenderOptions(*options);
      const Scene scene = prepareScene(*dir, options->model);
      const PrimeCamera camera(options->settings.camera);
      Ray r;
      std::string where;
      if (!pixel->empty()) {
        const int x = (*pixel)[0], y = (*pixel)[1];
        if (x < 0 || x >= camera.columns() || y < 0 || y >= camera.rows())
          throw CLI::ValidationError("--pixel", "pixel " + std::to_string(x) + " " +
                                                    std::to_string(y) + " is outside the image (" +
                                                    std::to_string(camera.columns()) + " x " +
                                                    std::to_string(camera.rows()) + ")");
        r = camera.primaryRay(y, x);
        where = pixelWhere(camera, x, y);
      } else {
        r.o = {(*ray)[0], (*ray)[1], (*ray)[2]};
        r.d = {(*ray)[3], (*ray)[4], (*ray)[5]};
        if (r.d == Vec3{0, 0, 0})  // R10: no direction, no ray
          throw CLI::ValidationError("--ray", "the direction is 0 0 0; give a non-zero direction");
        where = "ray from " + fmt(r.o) + " towards " + fmt(r.d);
      }
      const int column = pixel->empty() ? -1 : (*pixel)[0], row = pixel->empty() ? -1 : (*pixel)[1];
      const ProbedPixel probed = probePixel(scene, options->settings, r, where, column, row);
      ProbeReport report{probed.text, probed.json, ""};
      if (!flags->overlay.empty()) {
        // The picture trace writes in true colour, the tree over it.
        RenderSettings settings = options->settings;
        settings.keepColours = true;
        const RenderResult picture = render(scene, settings);
        Image8 img;
        img.width = picture.rgb.width;
        img.height = picture.rgb.height;
        for (const Rgb& c : picture.rgb.pixels) {
          const Rgb8 t = trueColour(c);
          img.rgb.insert(img.rgb.end(), {t.r, t.g, t.b});
        }
        report.written = writeOverlay(flags->overlay, img, probed);
      }
      return report;
    }
  };
}

}  // namespace prime::cli
