// prime probe SCENE.mal --pixel X Y: why is this pixel that colour? The ray
// tree of one pixel of a Malone scene: every hit, light, shadow ray,
// reflected and transmitted ray, with the colour each returns; as text or
// as JSON (the schema every system's probe shares, docs/user-guide.md).
#include <cstdio>

#include "legacy_io/malone/ppm.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"
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

}  // namespace

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
    const prime::malone::Tracer tracer(scene, o->trace);
    prime::malone::TraceStats stats;
    prime::malone::Probe log;
    const Rgb c = tracer.pixel(x, y, stats, &log);
    const int r = prime::malone::toByte(c[0]), g = prime::malone::toByte(c[1]),
              b = prime::malone::toByte(c[2]);
    ProbeReport report;
    report.text = o->file + ": Malone (1995)\n";
    for (const ProbeEvent& e : log.events)
      report.text += std::string(indentOf(e), ' ') + e.text + "\n";
    char last[200];
    std::snprintf(last, sizeof last,
                  "pixel (%d, %d) = (%.6g, %.6g, %.6g) -> bytes %d %d %d; %llu rays\n", x, y, c[0],
                  c[1], c[2], r, g, b, static_cast<unsigned long long>(stats.rays()));
    report.text += last;
    report.json = JsonObject()
                      .add("scene", o->file)
                      .add("where", "pixel " + std::to_string(x) + " " + std::to_string(y))
                      .addJson("events", log.jsonEvents())
                      .add("color", c)
                      .add("rays", stats.rays())
                      .addJson("malone", JsonObject()
                                             .add("system", "Malone (1995)")
                                             .addJson("bytes", "[" + std::to_string(r) + "," +
                                                                   std::to_string(g) + "," +
                                                                   std::to_string(b) + "]")
                                             .str())
                      .str();
    return report;
  };
}

}  // namespace prime::cli::malone
