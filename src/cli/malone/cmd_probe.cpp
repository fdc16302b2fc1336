// prime probe SCENE.mal --pixel X Y: why is this pixel that colour? The ray
// tree of one pixel of a Malone scene: every hit, light, shadow ray,
// reflected and transmitted ray, with the colour each returns; as text or
// as JSON (the schema every system's probe shares, docs/user-guide.md).
#include <cstdio>
#include <map>
#include <vector>

#include "legacy_io/malone/ppm.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"
#include "src/cli/malone/probe_pixel.h"
#include "src/cli/overlay.h"
#include "src/cli/system.h"

namespace prime::cli::malone {

namespace {

// The text's indent: a ray's own lines (hit, miss, returns) two spaces a
// level; what happens at its hit (lights, spawned rays) two more.
std::size_t indentOf(const ProbeEvent& e) {
  if (e.kind == "pixel") return 0;
  const bool own = e.kind == "hit" || e.kind == "miss" || e.kind == "returns";
  return static_cast<std::size_t>(2 * e.depth + (own ? 0 : 2));
}

// The rays of a Malone probe log: the pixel's primary ray (depth 1), and
// each transmitted or reflected ray spawned at a hit of depth d, ending at
// the next hit or miss of depth d + 1; a light sample's shadow ray runs
// from its hit to the sample.
std::vector<OverlaySegment> maloneSegments(const std::vector<ProbeEvent>& events) {
  std::vector<OverlaySegment> out;
  std::map<int, std::vector<std::pair<OverlaySegment, Vec3>>> open;  // by depth: segment, direction
  std::map<int, Vec3> hitAt;                                         // the latest hit of a depth
  for (const ProbeEvent& e : events) {
    if (e.kind == "pixel") {
      const auto o = jsonVec3(e.json, "origin"), d = jsonVec3(e.json, "direction");
      if (o && d) open[1].push_back({{*o, {}, OverlayKind::Primary, false}, *d});
    } else if ((e.kind == "transmitted" || e.kind == "reflected") && hitAt.count(e.depth)) {
      if (const auto d = jsonVec3(e.json, "direction"))
        open[e.depth + 1].push_back({{hitAt[e.depth], {}, *overlayKind(e.kind), false}, *d});
    } else if ((e.kind == "hit" || e.kind == "miss") && !open[e.depth].empty()) {
      auto [seg, dir] = open[e.depth].back();
      open[e.depth].pop_back();
      const auto point = jsonVec3(e.json, "point");
      seg.hit = e.kind == "hit" && point.has_value();
      seg.to = seg.hit ? *point : seg.from + dir * kMissLength;
      if (seg.hit) hitAt[e.depth] = *point;
      out.push_back(seg);
    } else if (e.kind == "light" && hitAt.count(e.depth)) {
      if (const auto p = jsonVec3(e.json, "position"))
        out.push_back({hitAt[e.depth], *p, OverlayKind::Shadow, false});
    }
  }
  return out;
}

}  // namespace

ProbedPixel probePixel(const prime::malone::Scene& scene, const prime::malone::TraceSettings& trace,
                       const std::string& file, int x, int y) {
  const prime::malone::Tracer tracer(scene, trace);
  prime::malone::TraceStats stats;
  prime::malone::Probe log;
  const Rgb c = tracer.pixel(x, y, stats, &log);
  const int r = prime::malone::toByte(c[0]), g = prime::malone::toByte(c[1]),
            b = prime::malone::toByte(c[2]);
  ProbedPixel out;
  out.text = file + ": Malone (1995)\n";
  for (const ProbeEvent& e : log.events) out.text += std::string(indentOf(e), ' ') + e.text + "\n";
  char last[200];
  std::snprintf(last, sizeof last,
                "pixel (%d, %d) = (%.6g, %.6g, %.6g) -> bytes %d %d %d; %llu rays\n", x, y, c[0],
                c[1], c[2], r, g, b, static_cast<unsigned long long>(stats.rays()));
  out.text += last;
  out.json = JsonObject()
                 .add("scene", file)
                 .add("where", "pixel " + std::to_string(x) + " " + std::to_string(y))
                 .addJson("events", log.jsonEvents())
                 .add("color", c)
                 .add("rays", stats.rays())
                 .addJson("malone",
                          JsonObject()
                              .add("system", "Malone (1995)")
                              .addJson("bytes", "[" + std::to_string(r) + "," + std::to_string(g) +
                                                    "," + std::to_string(b) + "]")
                              .str())
                 .str();
  // The ray of pixel (X, Y) goes through its corner (MAL-Q23):
  // forward + x (2X - W)/W - y (2Y - H)/H.
  const prime::malone::Viewer& v = scene.viewer;
  const Vec3 forward = normalized(v.lookAt - v.eye);
  out.camera = {v.eye, forward - v.x + v.y, v.x * (2.0 / v.xRes), v.y * (-2.0 / v.yRes), 0.0, 0.0};
  out.segments = maloneSegments(log.events);
  out.column = x;
  out.row = y;
  return out;
}

ProbeFactory addProbeOptions(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags) {
  auto o = std::make_shared<MaloneOptions>();
  addMaloneOptions(cmd, *o);
  return [o, flags]() -> ProbeReport {
    if (flags->pixel.size() != 2) throw CLI::ValidationError("probe", "give --pixel X Y");
    const prime::malone::Scene scene = loadMalone(*o);
    const int x = flags->pixel[0], y = flags->pixel[1];
    if (x < 0 || y < 0 || x >= scene.viewer.xRes || y >= scene.viewer.yRes)
      throw CLI::ValidationError("--pixel", "--pixel " + std::to_string(x) + " " +
                                                std::to_string(y) + " is outside the " +
                                                std::to_string(scene.viewer.xRes) + " x " +
                                                std::to_string(scene.viewer.yRes) + " picture");
    const ProbedPixel probed = probePixel(scene, o->trace, o->file, x, y);
    ProbeReport report{probed.text, probed.json, ""};
    if (!flags->overlay.empty()) {
      // The picture trace writes (its PPM's bytes), the tree over it.
      prime::malone::RenderSettings settings;
      settings.trace = o->trace;
      const prime::malone::RenderResult picture = prime::malone::render(scene, settings);
      Image8 img;
      img.width = picture.raster.width;
      img.height = picture.raster.height;
      for (const Rgb& p : picture.raster.pixels)
        for (int k = 0; k < 3; ++k) img.rgb.push_back(prime::malone::toByte(p[k]));
      report.written = writeOverlay(flags->overlay, img, probed);
    }
    return report;
  };
}

}  // namespace prime::cli::malone
