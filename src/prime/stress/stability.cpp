// Whole-image stability: each shipped scene rendered after a world transform
// T (scale 1e-3 and 1e3, translation by 1e4, a quarter turn), with the camera
// moved to match; the share of pixels whose palette index changes.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "legacy_io/prime/scene_dir.h"
#include "src/prime/math/listing_matrix.h"
#include "src/prime/render/renderer.h"
#include "src/prime/render/tracer_modern.h"
#include "src/prime/scene/scene_loader.h"
#include "src/prime/stress/stress.h"
#include "src/render/render_rows.h"

namespace prime::stress {

namespace {

// The scene as if modelled in a world moved by T (row vectors: p' = p T).
Scene transformScene(const Scene& in, const Matrix4& t) {
  Scene s = in;
  for (ScenePrim& p : s.prims) {
    matrixMul(p.transform, t);
    if (!inverse(p.transform, p.inverse))
      throw std::runtime_error("transformed primitive is singular");
  }
  for (auto& l : s.lights) l.pt = pointMatrixMul(l.pt, t);
  return s;
}

struct Image {
  std::vector<int> index;
  std::vector<Rgb> colour;
};

template <class Tracer>
Image renderIndices(const Tracer& tracer, const ListingCamera& cam, const Matrix4& t,
                    const RenderSettings& settings, int threads, std::uint64_t& nan) {
  const int rows = cam.rows(), cols = cam.columns();
  Image out;
  out.index.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
  out.colour.resize(out.index.size());
  std::atomic<int> next{0};
  std::atomic<std::uint64_t> nanCount{0};
  auto work = [&] {
    TraceStats stats;
    for (int r; (r = next.fetch_add(1)) < rows;)
      for (int c = 0; c < cols; ++c) {
        const Ray p = cam.primaryRay(r, c);
        const Ray ray{pointMatrixMul(p.o, t), vectorMatrixMul(p.d, t)};
        const Rgb color = tracer.castRay(ray, 0, stats);
        const std::size_t at = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
                               static_cast<std::size_t>(c);
        out.index[at] = paletteIndex(color, settings, stats);
        out.colour[at] = color;
      }
    nanCount += stats.nanColours;
  };
  std::vector<std::thread> pool;
  startThreads(pool, threads - 1, [&](int) { work(); });
  work();
  for (auto& th : pool) th.join();
  nan = nanCount;
  return out;
}

}  // namespace

std::vector<StabilityRow> runStability(const StabilityOptions& o) {
  namespace fs = std::filesystem;
  std::vector<fs::path> dirs;
  for (const auto& e : fs::directory_iterator(o.scenesDir))
    if (e.is_directory() && fs::exists(e.path() / "Model.txt") &&
        (o.scenes.empty() || std::find(o.scenes.begin(), o.scenes.end(),
                                       e.path().filename().string()) != o.scenes.end()))
      dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());

  struct Named {
    std::string name;
    Matrix4 m;
  };
  std::vector<Named> transforms;
  auto scaled = [](double s) {
    Matrix4 m = identity4();
    for (int i = 0; i < 3; ++i) m[i][i] = s;
    return m;
  };
  transforms.push_back({"scale 1e-3", scaled(1e-3)});
  transforms.push_back({"scale 1e3", scaled(1e3)});
  Matrix4 tr = identity4();
  tr[3] = {1e4, 1e4, 1e4, 1};
  transforms.push_back({"translate 1e4", tr});
  Matrix4 rot{};  // exactly a quarter turn about y: (x, y, z) -> (z, y, -x)
  rot[0] = {0, 0, -1, 0};
  rot[1] = {0, 1, 0, 0};
  rot[2] = {1, 0, 0, 0};
  rot[3] = {0, 0, 0, 1};
  transforms.push_back({"rotate 90 (y)", rot});

  const int threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<StabilityRow> rows;
  for (const fs::path& d : dirs) {
    const io::SceneDir dir(d);
    if (!staleDatabases(dir).empty()) {
      if (o.log) o.log("scene " + d.filename().string() + ": databases missing or stale, skipped");
      continue;
    }
    const Scene scene = loadScene(dir);
    RenderSettings settings;
    settings.camera.screenWidth /= o.screenDivisor;
    settings.camera.screenHeight /= o.screenDivisor;
    const ListingCamera cam(settings.camera);
    std::uint64_t nan = 0;
    Image base91, baseModern;
    if (o.run1991)
      base91 = renderIndices(Tracer1991(scene), cam, identity4(), settings, threads, nan);
    if (o.runModern)
      baseModern = renderIndices(TracerModern(scene), cam, identity4(), settings, threads, nan);
    for (const Named& t : transforms) {
      const Scene moved = transformScene(scene, t.m);
      StabilityRow row{d.filename().string(), t.name,
                       static_cast<std::uint64_t>(cam.rows()) * cam.columns()};
      // Changed palette indices, and those whose colour moved by more than
      // 0.01 in a channel (not just across a ColorNum step by rounding).
      auto changed = [](const Image& a, const Image& b, std::uint64_t& big) {
        std::uint64_t n = 0;
        for (std::size_t i = 0; i < a.index.size(); ++i) {
          if (a.index[i] == b.index[i]) continue;
          ++n;
          double d = 0;
          for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(a.colour[i][k] - b.colour[i][k]));
          if (!(d <= 0.01)) ++big;
        }
        return n;
      };
      if (o.run1991)
        row.changed1991 = changed(
            base91, renderIndices(Tracer1991(moved), cam, t.m, settings, threads, row.nan1991),
            row.big1991);
      if (o.runModern)
        row.changedModern =
            changed(baseModern,
                    renderIndices(TracerModern(moved), cam, t.m, settings, threads, row.nanModern),
                    row.bigModern);
      if (o.log)
        o.log("scene " + row.scene + ", " + row.transform + ": " + std::to_string(row.changed1991) +
              " / " + std::to_string(row.changedModern) + " of " + std::to_string(row.pixels) +
              " pixels changed");
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace prime::stress
