// What `prime probe` records while one pixel's ray tree is traced, for every
// system: typed events, each a human-readable line and the same as a JSON
// object. A tracer emits events only when a log is attached, so a normal
// render pays one pointer test per event site; text and JSON are built here
// and in each system's probe printer, never by a shading function's strings.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/math/vec.h"

namespace prime {

// A JSON object built field by field: keys and strings quoted and escaped,
// numbers as json(double) prints them (17 digits; NaN and Inf as strings).
class JsonObject {
 public:
  JsonObject& add(std::string_view key, int v);
  JsonObject& add(std::string_view key, std::uint64_t v);
  JsonObject& add(std::string_view key, double v);
  JsonObject& add(std::string_view key, bool v);
  JsonObject& add(std::string_view key, const Vec3& v);
  JsonObject& add(std::string_view key, std::string_view v);
  JsonObject& add(std::string_view key, const char* v) { return add(key, std::string_view(v)); }
  JsonObject& add(std::string_view key, char v) { return add(key, std::string_view(&v, 1)); }
  // A value that is JSON already (an array or object built elsewhere).
  JsonObject& addJson(std::string_view key, std::string_view json);
  std::string str() const { return text_ + "}"; }

 private:
  JsonObject& key(std::string_view k);
  std::string text_ = "{";
};

std::string jsonString(std::string_view s);  // "s", escaped
std::string json(double v);                  // %.17g; NaN and Inf as strings
std::string json(const Vec3& v);             // [x,y,z]
// Reading back what JsonObject wrote (flat objects of this file's own
// making): the text of `key`'s value (a string without its quotes, a
// number, an array with its brackets), or "" when absent; an array of three
// numbers as a Vec3, or nullopt.
std::string jsonField(std::string_view json, std::string_view key);
std::optional<Vec3> jsonVec3(std::string_view json, std::string_view key);
std::string fmt(double v);       // %.6g
std::string fmt(const Vec3& v);  // (x, y, z) at %.6g

struct ProbeEvent {
  int depth = 0;
  std::string kind;  // the system's event name: "ray", "hit", "light", "shade", ...
  std::string text;  // human-readable one-liner
  std::string json;  // the same as a JSON object
};

// The events of one pixel's ray tree, in the order they happened.
class ProbeLog {
 public:
  void add(int depth, std::string kind, std::string text, const JsonObject& data) {
    events.push_back({depth, std::move(kind), std::move(text), data.str()});
  }
  // The events as a JSON array of {"depth", "event", "data"}.
  std::string jsonEvents() const;

  std::vector<ProbeEvent> events;
};

}  // namespace prime
