#include "src/prime/bench/scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "legacy_io/prime/records.h"
#include "src/math/matrix.h"
#include "src/prime/bench/plot.h"
#include "src/prime/math/listing_matrix.h"

namespace prime::bench {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

SceneTexture constantMap(double r, double g, double b) {
  SceneTexture t;
  t.uScale = 1;
  t.vScale = 1;
  t.channel = {std::vector<double>{r}, std::vector<double>{g}, std::vector<double>{b}};
  t.constant = true;
  return t;
}

}  // namespace

Scene makeScaleScene(int objects) {
  if (objects < 1) throw std::invalid_argument("a scale scene needs at least one object");
  Scene scene;
  scene.name = "scale-" + std::to_string(objects);
  scene.maps.resize(5);
  scene.maps[1] = constantMap(0.9, 0.3, 0.2);
  scene.maps[2] = constantMap(0.2, 0.8, 0.3);
  scene.maps[3] = constantMap(0.3, 0.4, 0.9);
  scene.maps[4] = constantMap(0.9, 0.9, 0.5);
  scene.ambient = {0.2, 0.2, 0.2};
  scene.lights = {{{500.0, 1500.0, -1000.0}, {0.8, 0.8, 0.8}},
                  {{-500.0, 200.0, -500.0}, {0.4, 0.4, 0.4}}};

  const int k = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(objects))));
  const double cell = 1000.0 / k, r = 0.4 * cell;
  static constexpr io::PrimType kTypes[] = {io::PrimType::Sphere, io::PrimType::Cube,
                                            io::PrimType::Cylinder, io::PrimType::Cone,
                                            io::PrimType::Pyramid};
  for (int i = 0; i < objects; ++i) {
    const int gx = i % k, gy = i / k;
    const Vec3 c{(gx + 0.5) * cell, 1000.0 - (gy + 0.5) * cell,
                 300.0 + 200.0 * ((gx * 7 + gy * 13) % 11) / 10.0};
    ScenePrim p;
    p.type = kTypes[i % 5];
    Vec3 s{r, r, r}, t{c[0], c[1], c[2]};
    switch (p.type) {
      case io::PrimType::Sphere:
        break;  // unit sphere at the origin
      case io::PrimType::Cube:
        s = {2 * r, 2 * r, 2 * r};  // [0,1]^3
        t = {c[0] - r, c[1] - r, c[2] - r};
        break;
      case io::PrimType::Cylinder:  // radius 1 about z, z in [0,1]
      case io::PrimType::Cone:
        s = {r, r, 2 * r};
        t = {c[0], c[1], c[2] - r};
        break;
      case io::PrimType::Pyramid:
        s = {2 * r, 2 * r, 2 * r};  // base y = 0, x, z in [0,1]
        t = {c[0] - r, c[1] - r, c[2] - r};
        break;
    }
    p.transform = identity4();
    transform(p.transform, s, t, {0, 0, 0}, {0, 0, 0});
    if (!inverse(p.transform, p.inverse)) throw std::logic_error("scale scene: singular matrix");
    const int map = 1 + i % 4;
    for (int surface = 0; surface < io::surfaceCount(p.type); ++surface)
      p.map[surface] = {map, map};
    scene.prims.push_back(p);

    SceneObject obj;
    obj.number = i + 1;
    obj.entries = {CsgEntry{'P', i, 0}};
    obj.boundPrim = -1;
    obj.hue.kDR = 0.7;  // kSR = 0.3: a reflected ray at every hit
    obj.hue.kDT = 1.0;  // kST = 0: opaque
    obj.hue.fDR = {0.8, 0.8, 0.8};
    obj.hue.tT = 1.0;
    obj.hue.kRH = 10.0;
    obj.hue.kTH = 1.0;
    obj.hue.indx = 1.5;
    scene.objects.push_back(obj);
  }
  return scene;
}

std::vector<ScaleRow> runScale(const ScaleOptions& options) {
  auto log = [&](const std::string& m) {
    if (options.log) options.log(m);
  };
  const long baseline = runInChild([] { return std::vector<double>{}; }).maxRssKb;
  std::vector<ScaleRow> rows;
  for (int n : options.sizes)
    for (bool skips : {true, false}) {
      if (!skips && n > options.offMaxObjects) continue;
      const int runs = std::max(1, options.runs);
      const ChildRun child = runInChild([&] {
        const Scene scene = makeScaleScene(n);
        RenderSettings s;
        s.camera = options.camera;
        s.threads = options.threads;
        s.trace.skipUnneededWork = skips;
        std::vector<double> walls, cpus, out;
        TraceStats stats;
        for (int run = 0; run < runs; ++run) {
          const double w0 = wallSeconds(), c0 = processCpuSeconds();
          const RenderResult res = render(scene, s);
          walls.push_back(wallSeconds() - w0);
          cpus.push_back(processCpuSeconds() - c0);
          stats = res.stats;
        }
        out = {median(walls),
               *std::min_element(walls.begin(), walls.end()),
               *std::max_element(walls.begin(), walls.end()),
               median(cpus),
               static_cast<double>(stats.rays()),
               static_cast<double>(stats.objectTests),
               static_cast<double>(stats.primitiveTests)};
        return out;
      });
      ScaleRow r;
      r.objects = n;
      r.skips = skips;
      r.runs = runs;
      r.wallMedian = child.values.at(0);
      r.wallMin = child.values.at(1);
      r.wallMax = child.values.at(2);
      r.cpuMedian = child.values.at(3);
      r.rays = child.values.at(4);
      r.objectTests = child.values.at(5);
      r.primitiveTests = child.values.at(6);
      r.peakRssKb = child.maxRssKb;
      r.baselineRssKb = baseline;
      rows.push_back(r);
      log("scale: " + std::to_string(n) + " objects, skips " + (skips ? "on" : "off") + ": " +
          fmt("%.4f s", r.wallMedian) + ", peak RSS " + std::to_string(r.peakRssKb) + " kB");
    }
  return rows;
}

void writeScaleCsv(const std::string& path, const std::vector<ScaleRow>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  out << kScaleCsvHeader << "\n";
  for (const auto& r : rows)
    out << r.objects << "," << (r.skips ? "on" : "off") << "," << r.runs << ","
        << fmt("%.6f", r.wallMedian) << "," << fmt("%.6f", r.wallMin) << ","
        << fmt("%.6f", r.wallMax) << "," << fmt("%.6f", r.cpuMedian) << "," << fmt("%.0f", r.rays)
        << "," << fmt("%.0f", r.objectTests) << "," << fmt("%.0f", r.primitiveTests) << ","
        << r.peakRssKb << "," << r.baselineRssKb << "\n";
  if (!out) throw std::runtime_error(path + ": write failed");
}

std::string scaleMarkdown(const std::vector<ScaleRow>& rows, const CameraSettings& camera) {
  std::ostringstream md;
  const ListingCamera cam(camera);
  md << "Generated scenes at " << cam.columns() << " x " << cam.rows() << " pixels (screen "
     << camera.screenWidth << " x " << camera.screenHeight
     << "), one ray per pixel, MaxDepth 5, one thread; median of "
     << (rows.empty() ? 0 : rows.front().runs)
     << " renders. Peak memory is the child process's ru_maxrss "
     << "minus that of an empty child (" << (rows.empty() ? 0 : rows.front().baselineRssKb)
     << " kB).\n\n";
  md << "| objects | skips + BVH | wall ms | spread | CPU ms | rays | object tests | primitive "
        "tests | peak RSS "
        "over baseline (MB) | CPU / CPU(1 object) "
        "|\n|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& r : rows) {
    double t1 = 0;
    for (const auto& q : rows)
      if (q.objects == 1 && q.skips == r.skips) t1 = q.cpuMedian;
    md << "| " << r.objects << " | " << (r.skips ? "on" : "off") << " | "
       << fmt("%.1f", r.wallMedian * 1e3) << " | "
       << fmt("%.0f%%", r.wallMedian > 0 ? 100 * (r.wallMax - r.wallMin) / r.wallMedian : 0.0)
       << " | " << fmt("%.1f", r.cpuMedian * 1e3) << " | " << fmt("%.0f", r.rays) << " | "
       << fmt("%.0f", r.objectTests) << " | " << fmt("%.0f", r.primitiveTests) << " | "
       << fmt("%.1f", (r.peakRssKb - r.baselineRssKb) / 1024.0) << " | "
       << (t1 > 0 ? fmt("%.1f", r.cpuMedian / t1) : std::string("-")) << " |\n";
  }
  return md.str();
}

namespace {
Image8 scalePlot(const std::vector<ScaleRow>& rows, bool memory) {
  std::vector<Series> series(2);
  series[0].name = "SKIPS + BVH ON";
  series[0].colour = seriesColour(0);
  series[1].name = "SKIPS + BVH OFF";
  series[1].colour = seriesColour(1);
  double firstOn = 0;
  for (const auto& r : rows) {
    const double y =
        memory ? std::max(0.01, (r.peakRssKb - r.baselineRssKb) / 1024.0) : r.cpuMedian;
    Series& s = series[r.skips ? 0 : 1];
    s.dots.push_back({static_cast<double>(r.objects), y});
    s.line.push_back({static_cast<double>(r.objects), y});
    if (r.skips && r.objects == 1) firstOn = y;
  }
  if (firstOn > 0 && !memory) {
    Series lin;
    lin.name = "PROPORTIONAL TO OBJECTS";
    lin.colour = {150, 150, 150};
    lin.dashed = true;
    for (const auto& r : rows)
      if (r.skips) lin.line.push_back({static_cast<double>(r.objects), firstOn * r.objects});
    // Keep the chart readable: stop the guide line a decade above the data.
    double top = 0;
    for (const auto& r : rows) top = std::max(top, r.cpuMedian);
    std::erase_if(lin.line, [&](const PlotPoint& p) { return p.y > 10 * top && p.x > 1; });
    series.push_back(lin);
  }
  PlotSpec spec;
  spec.title = memory ? "SCALE: PEAK MEMORY" : "SCALE: RENDER TIME";
  spec.xLabel = "OBJECTS IN THE SCENE";
  spec.logY = !memory;  // memory: linear MB from 0
  spec.yFromZero = memory;
  spec.yLabel =
      memory ? "PEAK RSS OVER BASELINE (MB)" : "CPU SECONDS PER PICTURE (MEDIAN, 1 THREAD)";
  return drawPlot(spec, series);
}
}  // namespace

Image8 scaleTimePlot(const std::vector<ScaleRow>& rows) {
  return scalePlot(rows, false);
}
Image8 scaleMemoryPlot(const std::vector<ScaleRow>& rows) {
  return scalePlot(rows, true);
}

}  // namespace prime::bench
