#include "legacy_io/malone/input.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "legacy_io/common/input_file.h"

namespace prime::malone {

namespace {

// One field of an object: a name, and 1 (scalar) or 3 (vector) numbers.
struct Field {
  const char* name;
  int size;
};

struct ObjectInfo {
  int id;
  const char* name;
  std::vector<Field> fields;
};

const std::vector<ObjectInfo>& objectTable() {
  // The original's table of object types (section 1.1: "a table of all
  // object types, with pointer to their read, normal and intersection
  // functions"), here the read part: what each ID reads, in order.
  static const std::vector<ObjectInfo> table = {
      {1, "sphere", {{"radius", 1}, {"centre", 3}}},
      {2, "plane", {{"D", 1}, {"normal", 3}}},
      {3, "disk", {{"centre", 3}, {"normal", 3}, {"radius", 1}}},
      {4, "annulus", {{"centre", 3}, {"normal", 3}, {"radius", 1}, {"r_in", 1}}},
      {5, "triangle", {{"v0", 3}, {"v1", 3}, {"v2", 3}}},
      {6, "parallelogram", {{"vertex", 3}, {"edge1", 3}, {"edge2", 3}}},
      {7, "affine", {{"O", 3}, {"X", 3}, {"Y", 3}, {"Z", 3}}},
      {8, "cone", {{"alpha", 1}, {"start", 1}, {"finish", 1}, {"apex", 3}, {"axis", 3}}},
      {9, "cylinder", {{"radius", 1}, {"start", 1}, {"finish", 1}, {"point", 3}, {"axis", 3}}},
      {10, "torus", {{"R", 1}, {"r", 1}, {"centre", 3}, {"axis", 3}}},
      {11, "polygon", {{"N", 1}}},
      {100,
       "surface",
       {{"colour", 3}, {"k_s", 1}, {"k_e", 1}, {"k_d", 1}, {"k_t", 1}, {"index", 1}}},
      {101, "point light", {{"position", 3}, {"rgb", 3}}},
      {102, "viewer", {{"eye", 3}, {"look-at", 3}, {"x", 3}, {"y", 3}, {"X_RES", 1}, {"Y_RES", 1}}},
      {103, "ambient light", {{"rgb", 3}}},
      {104, "point light without r^-2", {{"position", 3}, {"rgb", 3}}},
      {105, "sampled light", {{"samples", 1}, {"centre", 3}, {"radius", 1}, {"rgb", 3}}},
      {106, "set default surface", {}},
      {107, "use default surface", {}},
  };
  return table;
}

const ObjectInfo* findObject(int id) {
  for (const auto& o : objectTable())
    if (o.id == id) return &o;
  return nullptr;
}

// A field being read, named only when a message needs it.
struct FieldRef {
  const char* object;
  const Field* field = nullptr;
  int component = 0;
  const char* plain = nullptr;  // a name of its own (ID slots, polygon vertices)
  int vertex = -1;              // polygon: 1-based vertex number
  std::string name() const;
};

std::string fieldName(const Field& f, int component) {
  if (f.size == 1) return f.name;
  static const char* xyz[] = {" x", " y", " z"};
  return std::string(f.name) + ((std::string(f.name) == "rgb" || std::string(f.name) == "colour")
                                    ? std::string(component == 0   ? " red"
                                                  : component == 1 ? " green"
                                                                   : " blue")
                                    : std::string(xyz[component]));
}

// Escapes control bytes so that a message shows what the file holds. (legacy_io/common/error.h)
std::string shown(std::string_view word) {
  return io::quotedWord(word, 40);
}

std::string FieldRef::name() const {
  std::string n = object;
  if (plain) return n + ", " + plain;
  if (vertex >= 0)
    return n + ", field vertex " + std::to_string(vertex) +
           (component == 0   ? " x"
            : component == 1 ? " y"
                             : " z");
  return n + ", field " + fieldName(*field, component);
}

class Tokens {
 public:
  Tokens(const std::string& text, std::string display, bool comments)
      : text_(text), display_(std::move(display)), comments_(comments) {
    if (text_.size() >= 3 && static_cast<unsigned char>(text_[0]) == 0xEF &&
        static_cast<unsigned char>(text_[1]) == 0xBB &&
        static_cast<unsigned char>(text_[2]) == 0xBF)
      advance(3);  // a UTF-8 byte order mark is not part of the stream
  }

  // The next token, or false at end of file. `word` points into the text.
  bool next(std::string_view& word, io::InputLocation& where) {
    skipBlanks();
    if (pos_ >= text_.size()) return false;
    where.file = display_;
    where.line = line_;
    where.column = column_;
    const std::size_t start = pos_;
    // A token has no line break: only the column moves.
    while (pos_ < text_.size() && !blank(text_[pos_]) && !(comments_ && text_[pos_] == '#')) {
      ++pos_;
      ++column_;
    }
    word = std::string_view(text_).substr(start, pos_ - start);
    where.token = ++tokens_;
    return true;
  }
  io::InputLocation here() const { return {display_, line_, std::nullopt, column_, std::nullopt}; }
  // Where the stream ended (line and column just past the last byte).
  io::InputLocation endOfFile() const { return here(); }

 private:
  static bool blank(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  }
  void advance(std::size_t n) {
    for (std::size_t k = 0; k < n && pos_ < text_.size(); ++k, ++pos_) {
      const char c = text_[pos_];
      // LF, CR LF and a lone CR all end a line.
      if (c == '\n' || (c == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n'))) {
        ++line_;
        column_ = 1;
      } else if (c != '\r') {
        ++column_;
      }
    }
  }
  void skipBlanks() {
    for (;;) {
      while (pos_ < text_.size() && blank(text_[pos_])) advance(1);
      if (comments_ && pos_ < text_.size() && text_[pos_] == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') advance(1);
        continue;
      }
      return;
    }
  }
  const std::string& text_;
  std::string display_;
  bool comments_;
  std::size_t pos_ = 0;
  int line_ = 1, column_ = 1;
  int tokens_ = 0;
};

class Reader {
 public:
  Reader(const std::string& text, const std::string& display, const ReadOptions& options)
      : tokens_(text, display, options.comments), options_(options) {}

  SceneFile read() {
    std::string_view word;
    io::InputLocation where;
    while (tokens_.next(word, where)) {
      const int id = objectId(word, where, "object ID (a primitive, light, viewer or 106)");
      ++objects_;
      const ObjectInfo* info = findObject(id);
      switch (static_cast<ObjectId>(id)) {
        case ObjectId::Surface:
          throw io::InputError(where, "object ID",
                               "a primitive, light, viewer or 106 (a surface is read only after a "
                               "primitive, or after 106)",
                               "100 (a surface on its own)");
        case ObjectId::UseDefaultSurface:
          throw io::InputError(where, "object ID",
                               "a primitive, light, viewer or 106 (107 stands only where a "
                               "primitive's surface goes)",
                               "107");
        case ObjectId::SetDefaultSurface:
          defaultSurface_ = surface(where, "106 (set default surface)", /*allowDefault=*/false);
          break;
        case ObjectId::PointLight:
        case ObjectId::PointLightNoFalloff:
        case ObjectId::SampledLight:
          light(static_cast<ObjectId>(id), *info, where);
          break;
        case ObjectId::Viewer:
          viewer(*info, where);
          break;
        case ObjectId::Ambient: {
          const auto v = numbers(*info, where);
          scene_.ambients.push_back({v[0], v[1], v[2]});
          break;
        }
        default: {
          PrimitiveRecord p = primitive(id, where);
          p.surface = surface(where, std::string(objectName(id)) + " (its surface)", true);
          p.objectNumber = objects_;
          scene_.primitives.push_back(std::move(p));
          break;
        }
      }
    }
    if (scene_.viewers == 0)
      throw io::InputError(tokens_.endOfFile(), "viewer",
                           "a viewer (102 eye look-at x y X_RES Y_RES) somewhere in the scene",
                           "end of file without one");
    return std::move(scene_);
  }

 private:
  int objectId(std::string_view word, const io::InputLocation& where, const std::string& what) {
    const double v = parse(word, where, [&] { return what; });
    if (v != std::floor(v) || std::fabs(v) > 1e9)
      throw io::InputError(where, what, "an integral ID", shown(word));
    const int id = static_cast<int>(v);
    if (findObject(id) == nullptr)
      throw io::InputError(where, what,
                           "a known ID: 1-11 (primitives), 100 (surface), 101-105 (lights, "
                           "viewer, ambient), 106, 107",
                           "unknown ID " + shown(word));
    return id;
  }

  // strtod on the token; `what` names the field, called only for a message.
  template <class What>
  double parse(std::string_view word, const io::InputLocation& where, What&& what) {
    char small[64];
    std::string large;
    const char* begin = small;
    if (word.size() < sizeof small) {
      std::memcpy(small, word.data(), word.size());
      small[word.size()] = '\0';
    } else {
      large.assign(word);
      begin = large.c_str();
    }
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    if (end == begin || static_cast<std::size_t>(end - begin) != word.size())
      throw io::InputError(where, what(), "a number", shown(word));
    // Overflow first: strtod returns HUGE_VAL for 1e309, which is not finite
    // either, and the message should say why.
    if (errno == ERANGE && std::fabs(v) > 1.0)
      throw io::InputError(where, what(), "a number within the range of a double",
                           shown(word) + " (out of range)");
    if (!std::isfinite(v)) throw io::InputError(where, what(), "a finite number", shown(word));
    return v;
  }

  // The next number of an object's field; end of file is an error that says
  // which object and which field was next.
  double number(const FieldRef& field, const io::InputLocation& objectWhere) {
    std::string_view word;
    io::InputLocation where;
    if (!tokens_.next(word, where))
      throw io::InputError(tokens_.endOfFile(), field.name(),
                           std::string("a number (the ") + field.object + " that starts at " +
                               io::describe(objectWhere) + " is not complete)",
                           "end of file");
    return parse(word, where, [&] { return field.name(); });
  }

  int integer(const FieldRef& field, const io::InputLocation& objectWhere, int lo, int hi) {
    std::string_view word;
    io::InputLocation where;
    if (!tokens_.next(word, where))
      throw io::InputError(tokens_.endOfFile(), field.name(),
                           std::string("an integer (the ") + field.object + " that starts at " +
                               io::describe(objectWhere) + " is not complete)",
                           "end of file");
    const double v = parse(word, where, [&] { return field.name(); });
    if (v != std::floor(v) || v < lo || v > hi)
      throw io::InputError(where, field.name(),
                           "an integer from " + std::to_string(lo) + " to " + std::to_string(hi),
                           shown(word));
    return static_cast<int>(v);
  }

  std::vector<double> numbers(const ObjectInfo& info, const io::InputLocation& where) {
    std::vector<double> v;
    v.reserve(12);
    for (const Field& f : info.fields)
      for (int k = 0; k < f.size; ++k) v.push_back(number({info.name, &f, k}, where));
    return v;
  }
  // One named field of `info` (by its index in the table).
  double field(const ObjectInfo& info, int index, int component, const io::InputLocation& where) {
    return number({info.name, &info.fields[static_cast<std::size_t>(index)], component}, where);
  }

  PrimitiveRecord primitive(int id, const io::InputLocation& where) {
    const ObjectInfo& info = *findObject(id);
    PrimitiveRecord p;
    p.id = static_cast<ObjectId>(id);
    p.where = where;
    if (p.id == ObjectId::Polygon) {
      const int n = integer({info.name, &info.fields[0], 0}, where, 3, 1000000);
      p.numbers.reserve(1 + 3 * static_cast<std::size_t>(n));
      p.numbers.push_back(n);
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
          FieldRef f{info.name};
          f.component = k;
          f.vertex = i + 1;
          p.numbers.push_back(number(f, where));
        }
      return p;
    }
    p.numbers = numbers(info, where);
    if (p.id == ObjectId::Affine) {
      std::string_view word;
      io::InputLocation innerWhere;
      if (!tokens_.next(word, innerWhere))
        throw io::InputError(tokens_.endOfFile(), "affine, embedded primitive",
                             "the ID of the primitive it transforms (the affine that starts at " +
                                 io::describe(where) + " is not complete)",
                             "end of file");
      const int inner = objectId(word, innerWhere, "affine, embedded primitive ID");
      if (!isPrimitive(static_cast<ObjectId>(inner)))
        throw io::InputError(innerWhere, "affine, embedded primitive ID", "a primitive ID (1-11)",
                             std::to_string(inner) + " (" + objectName(inner) + ")");
      if (++affineDepth_ > 64)
        throw io::InputError(innerWhere, "affine, embedded primitive ID",
                             "at most 64 affine primitives nested in one another", "more");
      p.inner = std::make_shared<const PrimitiveRecord>(primitive(inner, innerWhere));
      --affineDepth_;
    }
    return p;
  }

  // A surface slot: 100 and its numbers, or 107 (the current default).
  int surface(const io::InputLocation& objectWhere, const std::string& object, bool allowDefault) {
    std::string_view word;
    io::InputLocation where;
    if (!tokens_.next(word, where))
      throw io::InputError(tokens_.endOfFile(), object,
                           std::string("a surface: 100 and its 8 numbers") +
                               (allowDefault ? ", or 107" : "") + " (the object that starts at " +
                               io::describe(objectWhere) + " is not complete)",
                           "end of file");
    const double v = parse(word, where, [&] { return object; });
    if (v == 107 && allowDefault) {
      if (defaultSurface_ < 0)
        throw io::InputError(where, object,
                             "a surface (100 and 8 numbers); 107 uses the default surface, and "
                             "none has been set yet (106 sets it)",
                             "107");
      return defaultSurface_;
    }
    if (v != 100)
      throw io::InputError(where, object,
                           std::string("a surface: 100 and its 8 numbers") +
                               (allowDefault ? ", or 107 (the current default surface)" : ""),
                           shown(word));
    const auto n = numbers(*findObject(100), where);
    SurfaceRecord s;
    s.colour = {n[0], n[1], n[2]};
    s.ks = n[3];
    s.ke = n[4];
    s.kd = n[5];
    s.kt = n[6];
    s.index = n[7];
    s.where = where;
    scene_.surfaces.push_back(s);
    return static_cast<int>(scene_.surfaces.size()) - 1;
  }

  void light(ObjectId id, const ObjectInfo& info, const io::InputLocation& where) {
    LightRecord l;
    l.id = id;
    l.where = where;
    if (id == ObjectId::SampledLight) {
      l.samples = integer({info.name, &info.fields[0], 0}, where, 1, 100000);
      for (int k = 0; k < 3; ++k) l.position[k] = field(info, 1, k, where);
      l.radius = field(info, 2, 0, where);
      for (int k = 0; k < 3; ++k) l.rgb[k] = field(info, 3, k, where);
    } else {
      const auto v = numbers(info, where);
      l.position = {v[0], v[1], v[2]};
      l.rgb = {v[3], v[4], v[5]};
    }
    scene_.lights.push_back(l);
  }

  void viewer(const ObjectInfo& info, const io::InputLocation& where) {
    ViewerRecord v;
    v.where = where;
    double* fields[] = {&v.eye[0], &v.eye[1], &v.eye[2], &v.lookAt[0], &v.lookAt[1], &v.lookAt[2],
                        &v.x[0],   &v.x[1],   &v.x[2],   &v.y[0],      &v.y[1],      &v.y[2]};
    int k = 0;
    for (int f = 0; f < 4; ++f)
      for (int c = 0; c < 3; ++c) *fields[k++] = field(info, f, c, where);
    v.xRes = integer({info.name, &info.fields[4], 0}, where, 1, options_.maxResolution);
    v.yRes = integer({info.name, &info.fields[5], 0}, where, 1, options_.maxResolution);
    scene_.viewer = v;
    ++scene_.viewers;
  }

  Tokens tokens_;
  ReadOptions options_;
  SceneFile scene_;
  int defaultSurface_ = -1;
  int objects_ = 0;
  int affineDepth_ = 0;
};

}  // namespace

const char* objectName(int id) {
  const ObjectInfo* o = findObject(id);
  return o ? o->name : nullptr;
}

bool isPrimitive(ObjectId id) {
  const int v = static_cast<int>(id);
  return v >= 1 && v <= 11;
}

SceneFile readScene(const std::string& text, const std::string& display,
                    const ReadOptions& options) {
  // A ^Z ends the text (M41, every system's rule; readInputText has cut a
  // file's already).
  if (text.find(io::kDosEof) != std::string::npos) {
    std::string cut = text;
    io::endAtDosEof(cut);
    return Reader(cut, display, options).read();
  }
  return Reader(text, display, options).read();
}

SceneFile readSceneFile(const std::string& path, const ReadOptions& options) {
  io::InputFileOptions input;
  input.maxBytes = 256u << 20;
  input.what = "a Malone scene file";
  return readScene(io::readInputText(path, input), path, options);
}

bool looksLikeMalone(const std::string& text) {
  std::size_t i = 0;
  for (;;) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i < text.size() && text[i] == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    break;
  }
  std::size_t j = i;
  while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
  const std::string first = text.substr(i, j - i);
  if (first.empty()) return false;
  // The whole word a number (a binary file's first "word" may hold a NUL,
  // where strtod would stop at once and take "" for a whole number).
  char* end = nullptr;
  const double v = std::strtod(first.c_str(), &end);
  return end != first.c_str() && end == first.c_str() + first.size() && std::isfinite(v) &&
         v == std::floor(v);
}

}  // namespace prime::malone
