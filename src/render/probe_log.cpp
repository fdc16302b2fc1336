#include "src/render/probe_log.h"

#include <cmath>
#include <cstdio>

namespace prime {

std::string jsonString(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

JsonObject& JsonObject::key(std::string_view k) {
  if (text_.size() > 1) text_ += ",";
  text_ += jsonString(k) + ":";
  return *this;
}
JsonObject& JsonObject::add(std::string_view k, int v) {
  key(k).text_ += std::to_string(v);
  return *this;
}
JsonObject& JsonObject::add(std::string_view k, std::uint64_t v) {
  key(k).text_ += std::to_string(v);
  return *this;
}
JsonObject& JsonObject::add(std::string_view k, double v) {
  key(k).text_ += json(v);
  return *this;
}
JsonObject& JsonObject::add(std::string_view k, bool v) {
  key(k).text_ += v ? "true" : "false";
  return *this;
}
JsonObject& JsonObject::add(std::string_view k, const Vec3& v) {
  key(k).text_ += json(v);
  return *this;
}
JsonObject& JsonObject::add(std::string_view k, std::string_view v) {
  key(k).text_ += jsonString(v);
  return *this;
}
JsonObject& JsonObject::addJson(std::string_view k, std::string_view v) {
  key(k).text_ += v;
  return *this;
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

std::string ProbeLog::jsonEvents() const {
  std::string s = "[";
  for (std::size_t i = 0; i < events.size(); ++i)
    s += (i ? "," : "") + JsonObject()
                              .add("depth", events[i].depth)
                              .add("event", events[i].kind)
                              .addJson("data", events[i].json)
                              .str();
  return s + "]";
}

std::string jsonField(std::string_view json, std::string_view key) {
  const std::string k = "\"" + std::string(key) + "\":";
  const auto at = json.find(k);
  if (at == std::string_view::npos) return "";
  std::size_t b = at + k.size(), end = b;
  if (b < json.size() && json[b] == '"') {
    end = json.find('"', ++b);
  } else if (b < json.size() && json[b] == '[') {
    end = json.find(']', b);
    if (end != std::string_view::npos) ++end;
  } else {
    while (end < json.size() && json[end] != ',' && json[end] != '}') ++end;
  }
  if (end == std::string_view::npos) return "";
  return std::string(json.substr(b, end - b));
}

std::optional<Vec3> jsonVec3(std::string_view json, std::string_view key) {
  const std::string v = jsonField(json, key);
  Vec3 out{};
  if (v.size() < 2 || v.front() != '[' ||
      std::sscanf(v.c_str(), "[%lf,%lf,%lf]", &out[0], &out[1], &out[2]) != 3)
    return std::nullopt;
  return out;
}

}  // namespace prime
