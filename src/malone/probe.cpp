#include "src/malone/probe.h"

#include <cstdio>

namespace prime::malone {

namespace {
std::string num(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}
std::string vec(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v[0], v[1], v[2]);
  return buf;
}
std::string depthText(int depth) {
  return "depth " + std::to_string(depth);
}
}  // namespace

void Probe::pixel(int X, int Y, const MRay& ray) {
  add(0, "pixel",
      "pixel (" + std::to_string(X) + ", " + std::to_string(Y) + "): primary ray from " +
          vec(ray.o) + " along " + vec(ray.d),
      JsonObject().add("x", X).add("y", Y).add("origin", ray.o).add("direction", ray.d));
}

void Probe::miss(int depth) {
  add(depth, "miss", depthText(depth) + ": no hit (black)",
      JsonObject().add("colour", Vec3{0, 0, 0}));
}

void Probe::hit(int depth, int object, const std::string& kind, const io::InputLocation& at,
                double t, const Vec3& point, const Vec3& normal) {
  const std::string where = io::describe(at);
  add(depth, "hit",
      depthText(depth) + ": hit object " + std::to_string(object) + " (" + kind + ", " + where +
          ") at t = " + num("%.9g", t) + ", point " + vec(point) + ", normal " + vec(normal),
      JsonObject()
          .add("object", object)
          .add("primitive", kind)
          .add("where", where)
          .add("t", t)
          .add("point", point)
          .add("normal", normal));
}

void Probe::shadowed(int depth, int light, const Vec3& position) {
  add(depth, "light", "light " + std::to_string(light + 1) + " at " + vec(position) + ": shadowed",
      JsonObject().add("light", light + 1).add("position", position).add("shadowed", true));
}

void Probe::light(int depth, int light, const Vec3& position, double ds, double rs, double l,
                  const Rgb& adds) {
  add(depth, "light",
      "light " + std::to_string(light + 1) + " at " + vec(position) + ": d.s = " + num("%.6g", ds) +
          ", r.s = " + num("%.6g", rs) + ", l = " + num("%.6g", l) + ", adds " + vec(adds),
      JsonObject()
          .add("light", light + 1)
          .add("position", position)
          .add("shadowed", false)
          .add("ds", ds)
          .add("rs", rs)
          .add("distance", l)
          .add("adds", adds));
}

void Probe::tir(int depth, double ks) {
  add(depth, "tir", "total internal reflection: k_s' = " + num("%.6g", ks),
      JsonObject().add("ks", ks));
}

void Probe::transmitted(int depth, bool leaving, double eta, const Vec3& direction) {
  add(depth, "transmitted",
      std::string("transmitted (") + (leaving ? "leaving" : "entering") +
          ", eta = " + num("%.6g", eta) + ") along " + vec(direction),
      JsonObject().add("leaving", leaving).add("eta", eta).add("direction", direction));
}

void Probe::reflected(int depth, double ks, const Vec3& direction) {
  add(depth, "reflected", "reflected (k_s' = " + num("%.6g", ks) + ") along " + vec(direction),
      JsonObject().add("ks", ks).add("direction", direction));
}

void Probe::returns(int depth, const Rgb& colour) {
  add(depth, "returns", depthText(depth) + " returns " + vec(colour),
      JsonObject().add("colour", colour));
}

}  // namespace prime::malone
