#include "src/prime/render/probe.h"

#include <cmath>
#include <cstdio>

#include "legacy_io/prime/records.h"

namespace prime {

const char* rayKindName(RayKind k) {
  switch (k) {
    case RayKind::Primary:
      return "primary";
    case RayKind::Reflected:
      return "reflected";
    case RayKind::Transmitted:
      return "transmitted";
    case RayKind::Shadow:
      return "shadow";
  }
  return "?";
}

namespace {
const char* inOut(int surfType) {
  return surfType ? "In" : "Out";
}
}  // namespace

std::string describe(const TList& list) {
  if (list.empty()) return "empty";
  std::string s;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TNode& n = list[i];
    s += (i % 2 == 0 ? "[" : "") + fmt(n.t) + " p" + std::to_string(n.prim) + " " +
         inOut(n.surfType);
    s += (i % 2 == 0 ? ", " : "] ");
  }
  return s;
}

std::string jsonList(const TList& list) {
  std::string s = "[";
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TNode& n = list[i];
    if (i) s += ",";
    s += JsonObject()
             .add("t", n.t)
             .add("prim", n.prim)
             .add("surfType", inOut(n.surfType))
             .add("norm", n.norm)
             .str();
  }
  return s + "]";
}

void Probe::ray(int depth, RayKind kind, const Ray& r) {
  add(depth, "ray",
      std::string(rayKindName(kind)) + " ray, depth " + std::to_string(depth) + ": from " +
          fmt(r.o) + " dir " + fmt(r.d),
      JsonObject()
          .add("kind", rayKindName(kind))
          .add("depth", depth)
          .add("origin", r.o)
          .add("dir", r.d));
}

void Probe::boundTest(int depth, int object, io::PrimType boundType, int boundPrim, bool hit) {
  add(depth, "bound",
      "object " + std::to_string(object) + ": bounding " + io::primTypeName(boundType) + " (prim " +
          std::to_string(boundPrim) + ") " + (hit ? "hit" : "missed: object skipped"),
      JsonObject().add("object", object).add("boundPrim", boundPrim).add("hit", hit));
}

void Probe::primitive(int depth, int object, int prim, io::PrimType type,
                      const std::optional<PrimHit>& in) {
  std::string text = "object " + std::to_string(object) + " prim " + std::to_string(prim) + " (" +
                     io::primTypeName(type) + "): ";
  JsonObject json;
  json.add("object", object)
      .add("prim", prim)
      .add("type", static_cast<char>(type))
      .add("hit", in.has_value());
  if (in) {
    text += "in " + fmt(in->tIn) + " n " + fmt(in->nIn) + ", out " + fmt(in->tOut) + " n " +
            fmt(in->nOut);
    json.add("tIn", in->tIn).add("tOut", in->tOut).add("nIn", in->nIn).add("nOut", in->nOut);
  } else {
    text += "miss";
  }
  add(depth, "primitive", std::move(text), json);
}

void Probe::csgList(int depth, int object, const TList& list) {
  add(depth, "csg", "object " + std::to_string(object) + " Roth list: " + describe(list),
      JsonObject().add("object", object).addJson("list", jsonList(list)));
}

void Probe::hit(int depth, int object, int prim, io::PrimType type, double t, const Vec3& point,
                const Vec3& local, const Vec3& normal, bool inside) {
  add(depth, "hit",
      "nearest: object " + std::to_string(object) + " prim " + std::to_string(prim) + " (" +
          io::primTypeName(type) + ") at t " + fmt(t) + ", point " + fmt(point) + ", local " +
          fmt(local) + ", normal " + fmt(normal) + " (" + (inside ? "inside" : "outside") +
          " surface)",
      JsonObject()
          .add("object", object)
          .add("prim", prim)
          .add("t", t)
          .add("point", point)
          .add("local", local)
          .add("normal", normal)
          .add("surfType", inOut(inside)));
}

void Probe::texture(int depth, double u, double v, int surface, bool noFaceMatched, int map,
                    int uScale, int vScale, const Rgb& colour) {
  add(depth, "texture",
      "u " + fmt(u) + " v " + fmt(v) + " surface " + std::to_string(surface) +
          (noFaceMatched ? " (no face matched: E44)" : "") + " -> map " + std::to_string(map) +
          " (" + std::to_string(uScale) + "x" + std::to_string(vScale) + ") colour " + fmt(colour),
      JsonObject()
          .add("u", u)
          .add("v", v)
          .add("surface", surface)
          .add("map", map)
          .add("color", colour));
}

void Probe::transmit(int depth, int object, int steps, double distance, bool exited,
                     const Ray& leaving, std::string_view whyNoExit) {
  add(depth, "transmit",
      "through object " + std::to_string(object) + ": " + std::to_string(steps) +
          " internal step(s), distance " + fmt(distance) +
          (exited ? "" : " (" + std::string(whyNoExit) + ")") + ", leaves at " + fmt(leaving.o) +
          " dir " + fmt(leaving.d),
      JsonObject()
          .add("object", object)
          .add("steps", steps)
          .add("distance", distance)
          .add("exited", exited)
          .add("origin", leaving.o)
          .add("dir", leaving.d));
}

void Probe::shadow(int depth, int light, const Vec3& target, const Rgb& visibility) {
  const bool lit = visibility[0] == 1.0 && visibility[1] == 1.0 && visibility[2] == 1.0;
  const bool dark = visibility[0] == 0.0 && visibility[1] == 0.0 && visibility[2] == 0.0;
  add(depth, "shadow",
      "light " + std::to_string(light) + " at " + fmt(target) + ": " +
          (lit    ? std::string("lit")
           : dark ? std::string("in shadow")
                  : "attenuated to " + fmt(visibility)),
      JsonObject().add("light", light).add("target", target).add("visibility", visibility));
}

void Probe::miss(int depth, const Vec3& background) {
  add(depth, "miss", "no object hit: background " + fmt(background), JsonObject());
}

void Probe::hallTerms(int depth, const std::array<HallTerms, 3>& terms) {
  static const char* kChannel[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    const HallTerms& t = terms[static_cast<std::size_t>(c)];
    add(depth, "hall",
        std::string(kChannel[c]) + ": specular refl " + fmt(t.specularReflection) +
            " + specular trans " + fmt(t.specularTransmission) + " + diffuse refl " +
            fmt(t.diffuseReflection) + " + diffuse trans " + fmt(t.diffuseTransmission) +
            " + reflected " + fmt(t.reflected) + " + transmitted " + fmt(t.transmitted) + " = " +
            fmt(t.sum()),
        JsonObject()
            .add("channel", kChannel[c])
            .add("specularReflection", t.specularReflection)
            .add("specularTransmission", t.specularTransmission)
            .add("diffuseReflection", t.diffuseReflection)
            .add("diffuseTransmission", t.diffuseTransmission)
            .add("reflected", t.reflected)
            .add("transmitted", t.transmitted)
            .add("sum", t.sum()));
  }
}

void Probe::shade(int depth, const Rgb& reflected, const Rgb& transmitted, double sT,
                  const Rgb& colour) {
  add(depth, "shade",
      "Hall: reflected " + fmt(reflected) + ", transmitted " + fmt(transmitted) + ", sT " +
          fmt(sT) + " -> colour " + fmt(colour),
      JsonObject()
          .add("reflected", reflected)
          .add("transmitted", transmitted)
          .add("sT", sT)
          .add("color", colour));
}

}  // namespace prime
