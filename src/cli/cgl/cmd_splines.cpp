// prime cgl-splines SCENE.cgl: the B-spline surfaces of a CGL scene measured
// as Sweeney 1985 measures them in Tables 3 and 6 (section 11.2): per
// surface the original (extended) and refined vertices, tree nodes and bytes,
// then for the picture (rendered on one thread) boxes checked and Newton
// calls per ray, iterations per call, and the share of time in refinement,
// tree building, box tests, Newton and shading with the rest. Box and Newton
// times come from a second pass over the primary rays: the intersection
// alone, then Newton alone replayed from the same starts. With --holes N,
// every N-th pixel's primary ray is also traced by the dense reference
// (src/cgl/spline.h): the rays it hits and the Newton path misses. With
// --distances FILE, every pixel's primary ray is traced by both and the
// distances to the nearest spline hit are written as CSV (the holes against
// POV-Ray: bench/cgl/spline_holes.sh, CGL-D171).
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

#include "legacy_io/common/output_file.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"

namespace prime::cli::cgl {

namespace {

const char* endName(prime::cgl::EndCondition e) {
  switch (e) {
    case prime::cgl::EndCondition::Single:
      return "single";
    case prime::cgl::EndCondition::Double:
      return "double";
    case prime::cgl::EndCondition::Triple:
      return "triple";
    case prime::cgl::EndCondition::Closed:
      return "closed";
  }
  return "?";
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void addSplinesCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("cgl-splines", "Tables 3 and 6 for the B-spline surfaces of a CGL scene");
  auto o = std::make_shared<CglOptions>();
  auto holes = std::make_shared<int>(0);
  addCglOptions(cmd, *o);
  cmd->add_option("--holes", *holes,
                  "Count holes on every N-th pixel's primary ray (0: do not; slow)")
      ->check(CLI::Range(0, 512));
  auto distances = std::make_shared<std::string>();
  cmd->add_option("--distances", *distances,
                  "Write every pixel's distance to the nearest spline hit, by the dense "
                  "reference and by the Newton path, as CSV (x,y,reference,path; empty: none)");
  cmd->callback([o, holes, distances, &action] {
    if (!distances->empty()) io::checkOutputPath(*distances);
    action = [o, holes, distances] {
      const double t0 = now();
      const prime::cgl::SceneFile file = readCgl(*o, true);
      const double t1 = now();
      const prime::cgl::Scene scene = buildCgl(*o, file);
      const double t2 = now();
      prime::cgl::RenderSettings settings = renderSettings(*o, file);
      settings.threads = 1;
      const double r0 = now();
      const auto result = prime::cgl::render(scene, settings);
      const double render = now() - r0;
      const auto& st = result.stats;
      const double rays = static_cast<double>(st.rays.rays());
      std::printf("# %s: %llu rays (%llu primary), render %.3f s on one thread\n", o->file.c_str(),
                  static_cast<unsigned long long>(st.rays.rays()),
                  static_cast<unsigned long long>(st.rays.primaryRays), render);
      double refine = 0, tree = 0;
      for (const auto& s : scene.splines) {
        refine += s.refineSeconds;
        tree += s.treeSeconds;
        std::printf(
            "surface (node %d): %d+4 x %d+4 = %d original vertices, %s x %s, divisions %d, "
            "overlap %g; %d refined vertices, %d leaves, %zu tree nodes, %zu bytes (+ %zu "
            "bytes of packets and leaf records, CGL-D170); refinement %.2f ms, tree %.2f ms\n",
            s.node, s.mu - 4, s.mv - 4, s.mu * s.mv, endName(s.uEnd), endName(s.vEnd), s.divisions,
            s.overlap, s.pu * s.pv, s.leaves, s.nodes.size(), s.bytes(), s.traversalBytes(),
            1e3 * s.refineSeconds, 1e3 * s.treeSeconds);
      }
      // The primary rays again: intersection alone, recording Newton's starts.
      const auto& p = file.program;
      std::vector<prime::cgl::NewtonStart> starts;
      std::vector<Ray> primary;
      for (int y = p.yhigh; y >= p.ylow; --y)
        for (int x = p.xleft; x <= p.xright; ++x) primary.push_back(scene.camera.primaryRay(x, y));
      prime::cgl::SplineCounters c;
      double boxesAndNewton = 0, newtonOnly = 0;
      for (const auto& s : scene.splines) {
        starts.clear();
        std::vector<std::size_t> firstStart;
        firstStart.reserve(primary.size() + 1);
        const double a0 = now();
        for (const Ray& ray : primary) {
          firstStart.push_back(starts.size());
          prime::cgl::SplineHit h;
          prime::cgl::intersectSpline(s, ray, settings.epsilon, 1e10, h, c, &starts);
        }
        boxesAndNewton += now() - a0;
        firstStart.push_back(starts.size());
        prime::cgl::NewtonOptions no;
        no.tolerance = s.tolerance;
        int sink = 0;
        const double n0 = now();
        for (std::size_t r = 0; r < primary.size(); ++r) {
          const prime::cgl::RayPlanes planes = prime::cgl::rayPlanes(primary[r]);
          for (std::size_t k = firstStart[r]; k < firstStart[r + 1]; ++k)
            sink += prime::cgl::newton(s, planes, primary[r], starts[k].u0, starts[k].v0, no).hit;
        }
        newtonOnly += now() - n0;
        if (sink < 0) std::printf("\n");
      }
      // CGL-D170: the document's heap walk against the packet walk on the
      // same primary rays (intersection alone, CPU of this thread, the two
      // interleaved, median of 5 runs each).
      {
        auto cpuNow = [] {
          timespec ts{};
          clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
          return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
        };
        std::vector<double> doc, packets;
        int sink = 0;
        for (int run = 0; run < 5; ++run)
          for (int walk = 0; walk < 2; ++walk) {
            const bool document = (walk + run) % 2 == 0;
            prime::cgl::SplineCounters wc;
            const double w0 = cpuNow();
            for (const auto& s : scene.splines)
              for (const Ray& ray : primary) {
                prime::cgl::SplineHit h;
                sink +=
                    document
                        ? prime::cgl::intersectSplineDocument(s, ray, settings.epsilon, 1e10, h, wc)
                        : prime::cgl::intersectSpline(s, ray, settings.epsilon, 1e10, h, wc);
              }
            (document ? doc : packets).push_back(cpuNow() - w0);
          }
        std::sort(doc.begin(), doc.end());
        std::sort(packets.begin(), packets.end());
        std::printf(
            "primary rays' spline intersection alone (CPU, median of 5): document's heap walk "
            "%.4f s, packet walk %.4f s (CGL-D170), ratio %.2f; %d hits each\n",
            doc[2], packets[2], packets[2] / doc[2], sink / 10);
      }
      const double build = t2 - t1;
      const double total = build + render;
      const double boxes = std::max(0.0, boxesAndNewton - newtonOnly);
      const double shading = std::max(0.0, render - boxesAndNewton);
      std::printf(
          "average boxes checked/ray %.2f, Newton calls/ray %.2f, iterations/call %.2f, "
          "hits/ray %.3f (all rays of the render)\n",
          rays > 0 ? static_cast<double>(st.spline.boxes) / rays : 0.0,
          rays > 0 ? static_cast<double>(st.spline.newtonCalls) / rays : 0.0,
          st.spline.newtonCalls ? static_cast<double>(st.spline.iterations) /
                                      static_cast<double>(st.spline.newtonCalls)
                                : 0.0,
          rays > 0 ? static_cast<double>(st.spline.hits) / rays : 0.0);
      std::printf(
          "time: total %.3f s (read %.3f s apart) = refinement %.1f%%, tree building %.1f%%, "
          "bounding box intersect %.1f%%, Newton %.1f%%, shading and overhead %.1f%%\n",
          total, t1 - t0, 100 * refine / total, 100 * tree / total, 100 * boxes / total,
          100 * newtonOnly / total, 100 * (shading + build - refine - tree) / total);
      if (*holes > 0) {
        for (const auto& s : scene.splines) {
          prime::cgl::HoleCount h;
          for (int y = p.yhigh; y >= p.ylow; y -= *holes)
            for (int x = p.xleft; x <= p.xright; x += *holes)
              prime::cgl::countHoles(s, scene.camera.primaryRay(x, y), settings.epsilon, h);
          std::printf(
              "holes (node %d, overlap %g): %llu rays, reference hits %llu, Newton path "
              "hits %llu, holes %llu (%.2f%% of the reference's hits), path-only hits "
              "%llu, farther hits %llu\n",
              s.node, s.overlap, static_cast<unsigned long long>(h.rays),
              static_cast<unsigned long long>(h.referenceHits),
              static_cast<unsigned long long>(h.pathHits), static_cast<unsigned long long>(h.holes),
              h.referenceHits
                  ? 100.0 * static_cast<double>(h.holes) / static_cast<double>(h.referenceHits)
                  : 0.0,
              static_cast<unsigned long long>(h.extra), static_cast<unsigned long long>(h.farther));
        }
      }
      if (!distances->empty()) {
        // CGL-D171: the distance |I - O| along each primary ray, nearest over
        // the scene's spline surfaces, by the reference and by the path.
        io::OutputFile out(*distances);
        out.write("x,y,reference,path\n");
        constexpr double kInf = std::numeric_limits<double>::infinity();
        std::string line;
        for (int y = p.yhigh; y >= p.ylow; --y)
          for (int x = p.xleft; x <= p.xright; ++x) {
            const Ray ray = scene.camera.primaryRay(x, y);
            double ref = kInf, path = kInf;
            for (const auto& s : scene.splines) {
              prime::cgl::SplineHit h;
              prime::cgl::SplineCounters c;
              if (prime::cgl::intersectSplineReference(s, ray, settings.epsilon, ref, h)) ref = h.t;
              if (prime::cgl::intersectSpline(s, ray, settings.epsilon, path, h, c)) path = h.t;
            }
            const double len = length(ray.d);
            char buf[96];
            line = std::to_string(x) + "," + std::to_string(y) + ",";
            if (ref < kInf) {
              std::snprintf(buf, sizeof buf, "%.9g", ref * len);
              line += buf;
            }
            line += ",";
            if (path < kInf) {
              std::snprintf(buf, sizeof buf, "%.9g", path * len);
              line += buf;
            }
            line += "\n";
            out.write(line);
          }
        out.commit();
      }
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
