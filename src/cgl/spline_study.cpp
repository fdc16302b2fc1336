#include "src/cgl/spline_study.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

#include "legacy_io/common/output_file.h"

namespace prime::cgl {

namespace {

const char* endName(EndCondition e) {
  switch (e) {
    case EndCondition::Single:
      return "single";
    case EndCondition::Double:
      return "double";
    case EndCondition::Triple:
      return "triple";
    case EndCondition::Closed:
      return "closed";
  }
  return "?";
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double threadCpuNow() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

SplineStudy::SplineStudy(const SceneFile& file, const Scene& scene, RenderSettings settings,
                         double readSeconds, double buildSeconds)
    : file_(file),
      scene_(scene),
      settings_(std::move(settings)),
      readSeconds_(readSeconds),
      buildSeconds_(buildSeconds) {
  settings_.threads = 1;
  const auto& p = file_.program;
  for (int y = p.yhigh; y >= p.ylow; --y)
    for (int x = p.xleft; x <= p.xright; ++x) primary_.push_back(scene_.camera.primaryRay(x, y));
}

void SplineStudy::renderAndSurfaces() {
  const double r0 = now();
  stats_ = render(scene_, settings_).stats;
  render_ = now() - r0;
  std::printf("# %s: %llu rays (%llu primary), render %.3f s on one thread\n", file_.path.c_str(),
              static_cast<unsigned long long>(stats_.rays.rays()),
              static_cast<unsigned long long>(stats_.rays.primaryRays), render_);
  for (const auto& s : scene_.splines) {
    refine_ += s.refineSeconds;
    tree_ += s.treeSeconds;
    std::printf(
        "surface (node %d): %d+4 x %d+4 = %d original vertices, %s x %s, divisions %d, "
        "overlap %g; %d refined vertices, %d leaves, %zu tree nodes, %zu bytes (+ %zu "
        "bytes of packets and leaf records, CGL-D170); refinement %.2f ms, tree %.2f ms\n",
        s.node, s.mu - 4, s.mv - 4, s.mu * s.mv, endName(s.uEnd), endName(s.vEnd), s.divisions,
        s.overlap, s.pu * s.pv, s.leaves, s.nodes.size(), s.bytes(), s.traversalBytes(),
        1e3 * s.refineSeconds, 1e3 * s.treeSeconds);
  }
}

void SplineStudy::timeIntersections() {
  std::vector<NewtonStart> starts;
  SplineCounters c;
  for (const auto& s : scene_.splines) {
    starts.clear();
    std::vector<std::size_t> firstStart;
    firstStart.reserve(primary_.size() + 1);
    const double a0 = now();
    for (const Ray& ray : primary_) {
      firstStart.push_back(starts.size());
      SplineHit h;
      intersectSpline(s, ray, settings_.epsilon, 1e10, h, c, &starts);
    }
    boxesAndNewton_ += now() - a0;
    firstStart.push_back(starts.size());
    NewtonOptions no;
    no.tolerance = s.tolerance;
    int sink = 0;
    const double n0 = now();
    for (std::size_t r = 0; r < primary_.size(); ++r) {
      const RayPlanes planes = rayPlanes(primary_[r]);
      for (std::size_t k = firstStart[r]; k < firstStart[r + 1]; ++k)
        sink += newton(s, planes, primary_[r], starts[k].u0, starts[k].v0, no).hit;
    }
    newtonOnly_ += now() - n0;
    if (sink < 0) std::printf("\n");
  }
}

void SplineStudy::compareWalks() const {
  std::vector<double> doc, packets;
  int sink = 0;
  for (int run = 0; run < 5; ++run)
    for (int walk = 0; walk < 2; ++walk) {
      const bool document = (walk + run) % 2 == 0;
      SplineCounters wc;
      const double w0 = threadCpuNow();
      for (const auto& s : scene_.splines)
        for (const Ray& ray : primary_) {
          SplineHit h;
          sink += document ? intersectSplineDocument(s, ray, settings_.epsilon, 1e10, h, wc)
                           : intersectSpline(s, ray, settings_.epsilon, 1e10, h, wc);
        }
      (document ? doc : packets).push_back(threadCpuNow() - w0);
    }
  std::sort(doc.begin(), doc.end());
  std::sort(packets.begin(), packets.end());
  std::printf(
      "primary rays' spline intersection alone (CPU, median of 5): document's heap walk "
      "%.4f s, packet walk %.4f s (CGL-D170), ratio %.2f; %d hits each\n",
      doc[2], packets[2], packets[2] / doc[2], sink / 10);
}

void SplineStudy::averagesAndShares() const {
  const auto& st = stats_;
  const double rays = static_cast<double>(st.rays.rays());
  const double total = buildSeconds_ + render_;
  const double boxes = std::max(0.0, boxesAndNewton_ - newtonOnly_);
  const double shading = std::max(0.0, render_ - boxesAndNewton_);
  std::printf(
      "average boxes checked/ray %.2f, Newton calls/ray %.2f, iterations/call %.2f, "
      "hits/ray %.3f (all rays of the render)\n",
      rays > 0 ? static_cast<double>(st.spline.boxes) / rays : 0.0,
      rays > 0 ? static_cast<double>(st.spline.newtonCalls) / rays : 0.0,
      st.spline.newtonCalls
          ? static_cast<double>(st.spline.iterations) / static_cast<double>(st.spline.newtonCalls)
          : 0.0,
      rays > 0 ? static_cast<double>(st.spline.hits) / rays : 0.0);
  std::printf(
      "time: total %.3f s (read %.3f s apart) = refinement %.1f%%, tree building %.1f%%, "
      "bounding box intersect %.1f%%, Newton %.1f%%, shading and overhead %.1f%%\n",
      total, readSeconds_, 100 * refine_ / total, 100 * tree_ / total, 100 * boxes / total,
      100 * newtonOnly_ / total, 100 * (shading + buildSeconds_ - refine_ - tree_) / total);
}

void SplineStudy::holes(int step) const {
  const auto& p = file_.program;
  for (const auto& s : scene_.splines) {
    HoleCount h;
    for (int y = p.yhigh; y >= p.ylow; y -= step)
      for (int x = p.xleft; x <= p.xright; x += step)
        countHoles(s, scene_.camera.primaryRay(x, y), settings_.epsilon, h);
    std::printf(
        "holes (node %d, overlap %g): %llu rays, reference hits %llu, %s path "
        "hits %llu, holes %llu (%.2f%% of the reference's hits), path-only hits "
        "%llu, farther hits %llu\n",
        s.node, s.overlap, static_cast<unsigned long long>(h.rays),
        static_cast<unsigned long long>(h.referenceHits), s.cells.empty() ? "Newton" : "modern",
        static_cast<unsigned long long>(h.pathHits), static_cast<unsigned long long>(h.holes),
        h.referenceHits
            ? 100.0 * static_cast<double>(h.holes) / static_cast<double>(h.referenceHits)
            : 0.0,
        static_cast<unsigned long long>(h.extra), static_cast<unsigned long long>(h.farther));
  }
}

void SplineStudy::distances(const std::string& path) const {
  const auto& p = file_.program;
  io::OutputFile out(path);
  out.write("x,y,reference,path\n");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::string line;
  for (int y = p.yhigh; y >= p.ylow; --y)
    for (int x = p.xleft; x <= p.xright; ++x) {
      const Ray ray = scene_.camera.primaryRay(x, y);
      double ref = kInf, along = kInf;
      for (const auto& s : scene_.splines) {
        SplineHit h;
        SplineCounters c;
        if (intersectSplineReference(s, ray, settings_.epsilon, ref, h)) ref = h.t;
        if (intersectSplineAsBuilt(s, BoxRay(ray), settings_.epsilon, along, h, c)) along = h.t;
      }
      const double len = length(ray.d);
      char buf[96];
      line = std::to_string(x) + "," + std::to_string(y) + ",";
      if (ref < kInf) {
        std::snprintf(buf, sizeof buf, "%.9g", ref * len);
        line += buf;
      }
      line += ",";
      if (along < kInf) {
        std::snprintf(buf, sizeof buf, "%.9g", along * len);
        line += buf;
      }
      line += "\n";
      out.write(line);
    }
  out.commit();
}

}  // namespace prime::cgl
