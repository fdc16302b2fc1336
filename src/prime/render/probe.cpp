#include "src/prime/render/probe.h"

#include <cmath>
#include <cstdio>

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

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string fmt(const Vec3& v) {
  return "(" + fmt(v[0]) + ", " + fmt(v[1]) + ", " + fmt(v[2]) + ")";
}

std::string json(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "\"NaN\"" : (v > 0 ? "\"Inf\"" : "\"-Inf\"");
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string json(const Vec3& v) {
  return "[" + json(v[0]) + "," + json(v[1]) + "," + json(v[2]) + "]";
}

std::string describe(const TList& list) {
  if (list.empty()) return "empty";
  std::string s;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TNode& n = list[i];
    s += (i % 2 == 0 ? "[" : "") + fmt(n.t) + " p" + std::to_string(n.prim) +
         (n.surfType ? " In" : " Out");
    s += (i % 2 == 0 ? ", " : "] ");
  }
  return s;
}

std::string jsonList(const TList& list) {
  std::string s = "[";
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TNode& n = list[i];
    if (i) s += ",";
    s += "{\"t\":" + json(n.t) + ",\"prim\":" + std::to_string(n.prim) + ",\"surfType\":\"" +
         (n.surfType ? "In" : "Out") + "\",\"norm\":" + json(n.norm) + "}";
  }
  return s + "]";
}

}  // namespace prime
