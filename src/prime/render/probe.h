// What `prime probe` records while one pixel's ray tree is traced: every ray,
// every bound, object and primitive test, the chosen hit, the texture and the
// shading. The tracer calls these hooks only when a probe is attached, so a
// normal render pays one pointer test per event site.
#pragma once
#include <string>
#include <vector>

#include "src/prime/geom/interval_list.h"
#include "src/geom/ray.h"
#include "src/prime/render/hall_1991.h"
#include "src/prime/render/trace_stats.h"

namespace prime {

const char* rayKindName(RayKind k);

struct ProbeEvent {
  int depth = 0;
  std::string kind;  // "ray", "bound", "primitive", "csg", "object", "hit", "texture", "transmit",
                     // "shade", "miss"
  std::string text;  // human-readable one-liner
  std::string json;  // the same as a JSON object
};

class Probe {
 public:
  void add(int depth, std::string kind, std::string text, std::string json) {
    events.push_back({depth, std::move(kind), std::move(text), std::move(json)});
  }
  std::vector<ProbeEvent> events;
};

// Formatting helpers shared by the tracer's probe hooks.
std::string fmt(double v);
std::string fmt(const Vec3& v);
std::string json(const Vec3& v);
std::string json(double v);
std::string describe(const TList& list);
std::string jsonList(const TList& list);

}  // namespace prime
