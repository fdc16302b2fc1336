// The Waterloo CGL package's Table 5 (Sweeney 1985, section 11: milliseconds
// per operation on a VAX 11/780), measured on this port: intersect sphere,
// cylinder, rectangle and super box through the renderer's public routines
// (src/cgl/primitives.h), each for a ray that hits, a ray that misses, and
// a mix alternating the two (Table 5 does not say which rays it timed: a
// render's rays mostly miss any one object); and "shade ray" for Lambert
// and Phong through the tracer's public entry point: Tracer::trace of a
// primary ray that hits a one-sphere scene (one light at infinity, no
// shadows, depth 0), and Tracer::intersect of the same ray alone, so that
// shade = trace - intersect (Tracer::shade is private; docs/cgl/benchmarks.md
// subtracts). Objects are made by Preprocess from scene records, as a scene
// file makes them.
//   build/release/bench/micro/prime_micro --benchmark_filter=^cgl/
#include <benchmark/benchmark.h>

#include <string>

#include "src/cgl/primitives.h"
#include "src/cgl/scene.h"
#include "src/cgl/tracer.h"

namespace {

using namespace prime;
using namespace prime::cgl;

Spectrum flat(double v) {
  Spectrum s{};
  s.fill(v);
  return s;
}

NodeRecord nodeOf(NodeKind kind, int down = 0, int right = 0) {
  NodeRecord n;
  n.number = 1;
  n.kind = kind;
  n.down = down;
  n.right = right;
  n.surface = 1;
  return n;
}

// One surface (Lambert, Phong or Cook-Torrance, k_d 0.7, colour 0.5; Phong
// k_s 0.5, e 20; Cook k_s 1, m 0.3, a flat Fresnel table),
// the ambience of Figure 59 (k_a 0.0005, here flat 100) and one light at
// infinity towards (1, 1, 1) with dw 0.0006, and the nodes given.
SceneFile sceneOf(ShadingModel model, std::vector<NodeRecord> nodes, std::vector<Vec3> vertices) {
  SceneFile f;
  f.path = "micro.cgl";
  SurfaceRecord s;
  s.model = model;
  s.diffuse = 0.7;
  s.specular = model == ShadingModel::Phong ? 0.5 : 0.0;
  s.exponent = 20.0;
  s.colour = flat(0.5);
  if (model == ShadingModel::Cook) {  // the copper's k_s 1.0 and m 0.3; F 0.5 at every angle
    s.specular = 1.0;
    s.m = 0.3;
    s.fresnel.assign(kFresnelAngles, flat(0.5));
  }
  f.surfaces.push_back(s);
  f.ambience.ka = 0.0005;
  f.ambience.colour = flat(100.0);
  LightRecord l;
  l.xyz = {1, 1, 1};
  l.dw = 0.0006;
  l.colour = flat(100.0);
  f.lights.push_back(l);
  f.vertices = std::move(vertices);
  for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i].number = static_cast<int>(i + 1);
  f.nodes = std::move(nodes);
  f.numbers.root = 1;
  return f;
}

Scene sphereScene(ShadingModel model = ShadingModel::Lambert) {
  NodeRecord n = nodeOf(NodeKind::Sphere);
  n.radius = 1.0;  // at the origin
  return buildScene(sceneOf(model, {n}, {}));
}

Scene cylinderScene() {
  NodeRecord n = nodeOf(NodeKind::Cylinder);
  n.radius = 1.0;
  n.vertices = {1, 2};  // along y from -1 to 1
  return buildScene(sceneOf(ShadingModel::Lambert, {n}, {{0, -1, 0}, {0, 1, 0}}));
}

Scene rectangleScene() {
  NodeRecord n = nodeOf(NodeKind::Polygon);
  n.vertices = {1, 2, 3, 4};  // the square |x|, |y| <= 1 in z = 0
  return buildScene(
      sceneOf(ShadingModel::Lambert, {n}, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}));
}

Scene boxScene() {
  // A super box around the unit sphere: the box node's down pointer.
  NodeRecord box = nodeOf(NodeKind::Box, 2, 0);
  NodeRecord n = nodeOf(NodeKind::Sphere);
  n.radius = 1.0;
  return buildScene(sceneOf(ShadingModel::Lambert, {box, n}, {}));
}

// Every hit ray runs from z = 5 towards -z, a little off the axis (for the
// cylinder, from x = 5 towards -x); every miss ray passes 3 units beside.
const Ray kHitZ{{0.1, 0.2, 5.0}, normalized(Vec3{0.01, 0.02, -1.0})};
const Ray kMissZ{{3.1, 0.2, 5.0}, normalized(Vec3{0.01, 0.02, -1.0})};
const Ray kHitX{{5.0, 0.2, 0.1}, normalized(Vec3{-1.0, 0.02, 0.01})};
const Ray kMissX{{5.0, 0.2, 3.1}, normalized(Vec3{-1.0, 0.02, 0.01})};

enum class Mix { Hit, Miss, Alternate };

template <typename F>
void intersectLoop(benchmark::State& state, const Ray& hit, const Ray& miss, Mix mix, F test) {
  if (!test(hit) || test(miss)) {
    state.SkipWithError("the rays do not do what the benchmark expects");
    return;
  }
  const Ray rays[2] = {hit, miss};
  unsigned k = mix == Mix::Miss ? 1u : 0u;
  for (auto _ : state) {
    const Ray& r = rays[k & 1u];
    benchmark::DoNotOptimize(r);
    bool h = test(r);
    benchmark::DoNotOptimize(h);
    if (mix == Mix::Alternate) ++k;
  }
}

void intersectSphere(benchmark::State& state, Mix mix) {
  const Scene s = sphereScene();
  const Object& o = s.objects.at(0);
  intersectLoop(state, kHitZ, kMissZ, mix, [&](const Ray& r) {
    double t = 0;
    return hitSphere(o, r, 1e-9, 1e10, t);
  });
}

void intersectCylinder(benchmark::State& state, Mix mix) {
  const Scene s = cylinderScene();
  const Object& o = s.objects.at(0);
  intersectLoop(state, kHitX, kMissX, mix, [&](const Ray& r) {
    double t = 0, axial = 0;
    return hitCylinder(o, r, 1e-9, 1e10, t, axial);
  });
}

void intersectRectangle(benchmark::State& state, Mix mix) {
  const Scene s = rectangleScene();
  const Object& o = s.objects.at(0);
  // The miss ray meets the plane outside the square: the plane test and
  // edge tests up to the first failing one.
  intersectLoop(state, kHitZ, kMissZ, mix, [&](const Ray& r) {
    double t = 0;
    return hitPolygon(o, r, 1e-9, 1e10, t);
  });
}

void intersectSuperBox(benchmark::State& state, Mix mix) {
  const Scene s = boxScene();
  const Object& box = s.objects.at(0);
  if (box.kind != ObjectKind::Box) {
    state.SkipWithError("no super box");
    return;
  }
  // The tracer makes a ray's BoxRay (the reciprocal direction) once per ray,
  // before its walk of the object list: not counted here.
  const BoxRay rays[2] = {BoxRay(kHitZ), BoxRay(kMissZ)};
  if (!(boxEntry(box, rays[0]) < 1e10) || boxEntry(box, rays[1]) < 1e10) {
    state.SkipWithError("the rays do not do what the benchmark expects");
    return;
  }
  unsigned k = mix == Mix::Miss ? 1u : 0u;
  for (auto _ : state) {
    const BoxRay& r = rays[k & 1u];
    benchmark::DoNotOptimize(r);
    double t = boxEntry(box, r);
    benchmark::DoNotOptimize(t);
    if (mix == Mix::Alternate) ++k;
  }
}

// Tracer::trace of a primary ray that hits the sphere: intersect + the hit
// point and normal + Shade (ambience, one light, Lambert, Phong or Cook) in 33
// samples. ToRGB is not included (Table 5's "shade ray" is the shading).
void traceHit(benchmark::State& state, ShadingModel model) {
  const Scene s = sphereScene(model);
  TraceSettings settings;  // depth 0, no shadows
  const Tracer tracer(s, settings);
  TraceStats stats;
  for (auto _ : state) {
    benchmark::DoNotOptimize(kHitZ);
    Spectrum z = tracer.trace(kHitZ, 0, RayKind::Primary, stats, nullptr);
    benchmark::DoNotOptimize(z);
  }
  if (stats.shadeCalls[static_cast<std::size_t>(model)] == 0)
    state.SkipWithError("the ray was not shaded");
}

// Tracer::intersect of the same ray alone: what trace spends before Shade.
void traceIntersectOnly(benchmark::State& state) {
  const Scene s = sphereScene();
  TraceSettings settings;
  const Tracer tracer(s, settings);
  TraceStats stats;
  for (auto _ : state) {
    benchmark::DoNotOptimize(kHitZ);
    Tracer::Hit hit;
    bool h = tracer.intersect(kHitZ, 1e10, hit, stats);
    benchmark::DoNotOptimize(h);
    benchmark::DoNotOptimize(hit);
  }
}

const struct Registrar {
  Registrar() {
    const std::pair<const char*, Mix> mixes[] = {
        {"hit", Mix::Hit}, {"miss", Mix::Miss}, {"alternate", Mix::Alternate}};
    for (const auto& [name, mix] : mixes) {
      const std::string m = name;
      benchmark::RegisterBenchmark(("cgl/intersect_sphere/" + m).c_str(), intersectSphere, mix);
      benchmark::RegisterBenchmark(("cgl/intersect_cylinder/" + m).c_str(), intersectCylinder, mix);
      benchmark::RegisterBenchmark(("cgl/intersect_rectangle/" + m).c_str(), intersectRectangle,
                                   mix);
      benchmark::RegisterBenchmark(("cgl/intersect_super_box/" + m).c_str(), intersectSuperBox,
                                   mix);
    }
    benchmark::RegisterBenchmark("cgl/trace_intersect_only", traceIntersectOnly);
    benchmark::RegisterBenchmark("cgl/trace_shade/lambert", traceHit, ShadingModel::Lambert);
    benchmark::RegisterBenchmark("cgl/trace_shade/phong", traceHit, ShadingModel::Phong);
    benchmark::RegisterBenchmark("cgl/trace_shade/cook", traceHit, ShadingModel::Cook);
  }
} registrar;

}  // namespace
