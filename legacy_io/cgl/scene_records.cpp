// The CGL scene file's records (Sweeney 1985, Appendix 1 sections 5 to 8):
// program and display parameters, vertices, colour-vectors (strict, and the
// lenient reader's padding), surfaces, the ambience and lights. The choices
// and repairs are in docs/cgl/deviations.md.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "legacy_io/cgl/scene_reader.h"

namespace prime::cgl::detail {

void Reader::programParameter(int k) {
  const std::size_t j = header("program parameter " + std::to_string(k + 1));
  const std::string name = "program parameter " + std::to_string(k + 1) + " of " +
                           std::to_string(scene_.numbers.programParameters);
  const Line& l = lines_[j];
  if (l.tokens.size() < 2 || !isCount(l.tokens[0].text))
    notARecord(j, name, "count keyword value (e.g. '1 depth 3')");
  Record r(*this, j, name, Section::Program);
  r.count("an integer", std::nullopt);  // "these restrictions are relaxed" (section 4)
  std::string hint;
  if (j < lines_.size() && l.tokens.size() >= 2 && anyKeyword(l.tokens[1].text))
    hint = " (a record of another section: the first record counts " +
           std::to_string(scene_.numbers.programParameters) + " program parameters)";
  const std::string kw = r.keyword("keyword", programKeywords(), hint);
  auto& p = scene_.program;
  auto& g = p.given;
  auto once = [&](bool& given) {
    if (given)
      warn(lineAt(j),
           "program parameter '" + kw + "' given again: the later value is used (CGL-Q4)");
    given = true;
  };
  const std::string pixel = "an integer 0-511 (Table 8)";
  if (kw == "output") {
    once(g.output);
    p.output = r.take("pathname", "a pathname").text;
  } else if (kw == "yhigh") {
    once(g.yhigh);
    p.yhigh = static_cast<int>(r.integer("yhigh", 0, 511, pixel));
  } else if (kw == "ylow") {
    once(g.ylow);
    p.ylow = static_cast<int>(r.integer("ylow", 0, 511, pixel));
  } else if (kw == "xleft") {
    once(g.xleft);
    p.xleft = static_cast<int>(r.integer("xleft", 0, 511, pixel));
  } else if (kw == "xright") {
    once(g.xright);
    p.xright = static_cast<int>(r.integer("xright", 0, 511, pixel));
  } else if (kw == "depth") {
    once(g.depth);
    p.depth = static_cast<int>(r.integer("depth", 0, 10, "an integer 0-10 (Table 8)"));
  } else if (kw == "shadows") {
    once(g.shadows);
    p.shadows = true;
  } else if (kw == "memory") {
    once(g.memory);
    p.memory = static_cast<int>(r.integer("memory", 1, 4096, "an integer, Mbytes, 1 or more"));
    if (p.memory > 24)
      warn(r.at(r.last()),
           "memory " + std::to_string(p.memory) +
               " Mbytes is above Table 8's 1-24 (the VAX's address space); a figure only "
               "in this port (CGL-Q3)");
  } else if (kw == "brightness") {
    once(g.brightness);
    p.brightness = r.realIn("brightness", 0.0, 1.0, "a real number 0.0-1.0 (Table 8)");
  } else if (kw == "background") {
    once(g.background);
    const std::string e = "an integer 0-255 (Table 8)";
    p.background[0] = static_cast<int>(r.integer("red", 0, 255, e));
    p.background[1] = static_cast<int>(r.integer("green", 0, 255, e));
    p.background[2] = static_cast<int>(r.integer("blue", 0, 255, e));
  } else if (kw == "quiet") {
    once(g.quiet);
    p.quiet = true;
  } else if (kw == "aathreshold") {
    once(g.aathreshold);
    const std::string e = "a real number above 0.0 (Table 8 advises 5.0-100.0)";
    const double v = r.realIn("aathreshold", std::numeric_limits<double>::min(),
                              std::numeric_limits<double>::max(), e);
    if (v < 5.0 || v > 100.0)
      warn(lineAt(j),
           "aathreshold " + std::to_string(v) + " is outside Table 8's 5.0-100.0 (CGL-Q2)");
    p.aathreshold = v;
  } else if (kw == "aalevel") {
    once(g.aalevel);
    const std::string e = "one of 0, 1, 2, 4 or 8 (section 5; 0 = no anti-aliasing, CGL-Q1)";
    const int v = static_cast<int>(r.integer("aalevel", 0, 8, e));
    if (v != 0 && v != 1 && v != 2 && v != 4 && v != 8)
      r.fail(r.last(), "aalevel", e, shown(r.last().text));
    p.aalevel = v;
  }
  done(r);
}

void Reader::displayParameter(int k) {
  const std::size_t j = header("display parameter " + std::to_string(k + 1));
  const std::string name = "display parameter " + std::to_string(k + 1) + " of " +
                           std::to_string(scene_.numbers.displayParameters);
  const Line& l = lines_[j];
  if (l.tokens.size() < 2 || !isCount(l.tokens[0].text))
    notARecord(j, name, "count keyword values (e.g. '1 eye 0.0 0.0 3.5')");
  Record r(*this, j, name, Section::Display);
  r.count("an integer", std::nullopt);
  std::string hint;
  if (anyKeyword(l.tokens[1].text))
    hint = " (a record of another section: the first record counts " +
           std::to_string(scene_.numbers.displayParameters) + " display parameters)";
  const std::string kw = r.keyword("keyword", displayKeywords(), hint);
  auto& d = scene_.display;
  auto xyz = [&](const std::string& what) {
    Vec3 v{};
    v[0] = r.real(what + " x");
    v[1] = r.real(what + " y");
    v[2] = r.real(what + " z");
    return v;
  };
  if (kw == "eye") {
    d.eye = xyz("eye");
    if (sightTowardsLine_)
      warn(lineAt(j), "the eye is set after 'sight towards' (line " +
                          std::to_string(lines_[*sightTowardsLine_].number) +
                          "), whose direction was taken from the eye as it was then; the manual: "
                          "\"the eye point should be set before the sight direction\" (CGL-Q5)");
  } else if (kw == "sight") {
    const std::string how = r.keyword("direction|towards", {"direction", "towards"});
    const Vec3 v = xyz(how == "towards" ? "point" : "direction");
    d.sight = how == "towards" ? v - d.eye : v;
    if (d.sight == Vec3{0, 0, 0})
      throw io::InputError(lineAt(j), name + ", field sight", "a direction other than (0, 0, 0)",
                           how == "towards" ? "the eye point itself" : "(0, 0, 0)");
    if (how == "towards") sightTowardsLine_ = j;
  } else if (kw == "up") {
    d.up = xyz("up");
    if (d.up == Vec3{0, 0, 0})
      throw io::InputError(lineAt(j), name + ", field up", "a direction other than (0, 0, 0)",
                           "(0, 0, 0)");
  } else if (kw == "dist") {
    d.dist = r.realIn("dist", std::numeric_limits<double>::min(),
                      std::numeric_limits<double>::max(), "a real number above 0.0");
  } else if (kw == "viewport") {
    const double lo = std::numeric_limits<double>::min(), hi = std::numeric_limits<double>::max();
    d.viewportHeight = r.realIn("height", lo, hi, "a real number above 0.0");
    d.viewportWidth = r.realIn("width", lo, hi, "a real number above 0.0");
  }
  done(r);
}

void Reader::vertex(int n) {
  const std::string name = "vertex " + std::to_string(n);
  const std::size_t j = header(name);
  Record r(*this, j, name, Section::Vertices);
  const std::string e = "the vertex number " + std::to_string(n) +
                        " (vertices are numbered consecutively from 1; the first record counts " +
                        std::to_string(scene_.numbers.vertices) + ")";
  if (!isCount(lines_[j].tokens[0].text)) notARecord(j, name + ", field count", e);
  r.count(e, n);
  Vec3 v{};
  v[0] = r.real("x");
  v[1] = r.real("y");
  v[2] = r.real("z");
  scene_.vertices.push_back(v);
  done(r);
}

// Lenient only (CGL-E10): the ambience descriptor is not introduced by a
// keyword, so a short colour-vector in the last surface could run on into it.
// It is found by counting back from the first light (or, with no lights, the
// first scene node): its 33 numbers come last and the one before them is k_a.
// Returns the k_a line (colour-vectors of surfaces stop before it).
std::size_t Reader::findAmbienceBoundary() const {
  std::size_t stop = lines_.size();
  for (std::size_t j = next_; j < lines_.size(); ++j) {
    const Line& l = lines_[j];
    if (l.comment || l.tokens.size() < 2 || !isCount(l.tokens[0].text)) continue;
    const std::string& kw = l.tokens[1].text;
    if ((scene_.numbers.lights > 0 && among(lightKeywords(), kw)) ||
        (scene_.numbers.lights == 0 && among(nodeKeywords(), kw))) {
      stop = j;
      break;
    }
  }
  // The nearest line before `stop` holding one number with at least 33
  // numbers after it is k_a (parameter lines of scene nodes printed before
  // their header may stand between the ambience and `stop`); failing that,
  // the line of the 34th number counted back.
  int numbers = 0;
  std::size_t fallback = std::numeric_limits<std::size_t>::max();
  for (std::size_t j = stop; j-- > next_;) {
    const Line& l = lines_[j];
    if (l.comment) continue;
    int here = 0;
    for (const auto& t : l.tokens) {
      if (!isReal(t.text)) break;
      ++here;
    }
    if (here == 1 && numbers >= kSpectrumSamples) return j;
    numbers += here;
    if (numbers >= kSpectrumSamples + 1 && fallback == std::numeric_limits<std::size_t>::max())
      fallback = j;
  }
  return fallback;
}

namespace {
// A colour-vector is written 10, 10, 10 and 3 numbers to a line.
constexpr int kColourRows[4] = {10, 10, 10, 3};
}  // namespace

void Reader::checkReflectance(double v, const io::InputLocation& where, const std::string& what,
                              const std::string& field, const std::string& text) const {
  if (v < 0.0)
    throw io::InputError(where, what + ", field " + field,
                         "a reflectance or intensity 0.0 or more (CGL-Q11)", shown(text));
}

Spectrum Reader::colourVector(const std::string& what, Section section) {
  return lenient_ ? lenientColourVector(what, section) : strictColourVector(what);
}

// As printed: four lines of 10, 10, 10 and 3 numbers.
Spectrum Reader::strictColourVector(const std::string& what) {
  Spectrum s{};
  int k = 0;
  for (int row = 0; row < 4; ++row) {
    const std::string rowName = "colour-vector row " + std::to_string(row + 1) + " of 4";
    const std::size_t j = header(what + ", " + rowName);
    const Line& l = lines_[j];
    for (int c = 0; c < kColourRows[row]; ++c, ++k) {
      const std::string field = "colour-vector sample " + std::to_string(k + 1) + " (" +
                                std::to_string(380 + 10 * k) + " nm)";
      const std::string e =
          "a real number (a colour-vector is 33 numbers, written 10, 10, 10 "
          "and 3 to a line)";
      if (c >= static_cast<int>(l.tokens.size()))
        throw io::InputError(
            lineAt(j), what + ", field " + field, e,
            "end of line after " + std::to_string(c) + " numbers" +
                (l.tokens.empty() ? "" : " (--lenient pads a short colour-vector)"));
      const Token& t = l.tokens[static_cast<std::size_t>(c)];
      io::InputLocation w = lineAt(j);
      w.column = t.column;
      double v = 0.0;
      const NumberStatus st = parseReal(t.text, v);
      if (st != NumberStatus::Ok)
        throw io::InputError(w, what + ", field " + field, e,
                             shown(t.text) + (c == 0 ? hintFor(l) : "") +
                                 (st == NumberStatus::LoneSign
                                      ? " (a sign apart from its number; --lenient joins it)"
                                      : ""));
      checkReflectance(v, w, what, field, t.text);
      s[static_cast<std::size_t>(k)] = v;
    }
    next_ = j + 1;
  }
  return s;
}

// Lenient (CGL-E10): numbers flow over lines until 33 are read, stopping at a
// line that begins a record, a line that is not numbers, or the ambience
// descriptor; a short vector is padded (CGL-E2, CGL-E3).
Spectrum Reader::lenientColourVector(const std::string& what, Section section) {
  Spectrum s{};
  std::vector<double> values;
  std::vector<int> perLine;
  std::size_t first = lines_.size();
  for (;;) {
    if (values.size() == kSpectrumSamples) break;
    const std::size_t j = nextContent(next_);
    if (j >= lines_.size() || j >= boundary_ || beginsRecord(j, section)) break;
    const Line& l = lines_[j];
    int here = 0;
    for (const auto& t : l.tokens) {
      if (values.size() == kSpectrumSamples) break;
      double v = 0.0;
      if (parseReal(t.text, v) != NumberStatus::Ok) break;
      io::InputLocation w = lineAt(j);
      w.column = t.column;
      checkReflectance(v, w, what, "colour-vector sample " + std::to_string(values.size() + 1),
                       t.text);
      values.push_back(v);
      ++here;
    }
    if (here == 0) break;
    if (first == lines_.size()) first = j;
    perLine.push_back(here);
    next_ = j + 1;
  }
  if (values.empty()) {
    const std::size_t j = nextContent(next_);
    if (j >= lines_.size())
      throw io::InputError(lineAt(lines_.size() - 1), what + ", field colour-vector",
                           "33 real numbers", "end of file");
    notARecord(j, what + ", field colour-vector", "33 real numbers");
  }
  if (values.size() < kSpectrumSamples) {
    s = padColourVector(values, perLine, first, what);
  } else {
    std::copy(values.begin(), values.end(), s.begin());
    if (!(perLine.size() == 4 && perLine[0] == 10 && perLine[1] == 10 && perLine[2] == 10))
      repair(lines_[first].number, what + ": colour-vector read over " +
                                       std::to_string(perLine.size()) +
                                       " lines, not the 10/10/10/3 layout (CGL-E10)");
  }
  return s;
}

// A short colour-vector, padded: the 10/10/10/3 layout kept where only rows
// among the first three are short, each short row's last value repeated at
// its end (CGL-E3); otherwise the last value repeated to sample 33 (CGL-E2).
Spectrum Reader::padColourVector(const std::vector<double>& values, const std::vector<int>& perLine,
                                 std::size_t first, const std::string& what) {
  Spectrum s{};
  const int missing = kSpectrumSamples - static_cast<int>(values.size());
  std::vector<double> out;
  std::string how;
  int shortfall = 0;
  if (perLine.size() == 4 && perLine[3] == 3) {
    for (int r = 0; r < 3; ++r) shortfall += std::max(0, 10 - perLine[static_cast<std::size_t>(r)]);
  }
  if (perLine.size() == 4 && perLine[3] == 3 && shortfall == missing &&
      std::all_of(perLine.begin(), perLine.begin() + 3, [](int c) { return c <= 10; })) {
    std::size_t k = 0;
    for (int r = 0; r < 4; ++r) {
      const int c = perLine[static_cast<std::size_t>(r)];
      for (int i = 0; i < c; ++i) out.push_back(values[k++]);
      for (int i = c; i < kColourRows[r]; ++i) out.push_back(out.back());
      if (c < kColourRows[r])
        how += (how.empty() ? "" : "; ") + std::string("row ") + std::to_string(r + 1) + " has " +
               std::to_string(c) + " of " + std::to_string(kColourRows[r]) +
               " numbers: its last value repeated at its end";
    }
    how += " (CGL-E3)";
  } else {
    out = values;
    while (out.size() < kSpectrumSamples) out.push_back(values.back());
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", values.back());
    how = "the last value (" + std::string(buf) + ") repeated to sample 33" +
          (values.size() <= 3 ? std::string(": a flat spectrum") : std::string()) + " (CGL-E2)";
  }
  std::copy(out.begin(), out.end(), s.begin());
  repair(lines_[first].number, what + ": colour-vector of " + std::to_string(values.size()) +
                                   " numbers, not 33; padded: " + how);
  return s;
}

void Reader::surface(int n) {
  const std::string base = "surface " + std::to_string(n);
  const std::size_t j = header(base);
  const Line& l = lines_[j];
  std::string name = base;
  if (l.tokens.size() >= 3) name += " (" + l.tokens[1].text + " " + l.tokens[2].text + ")";
  if (!isCount(l.tokens[0].text))
    notARecord(j, base + ", field count",
               "'" + std::to_string(n) +
                   " (lambert|phong|cook) (textured|normal) reflect refract "
                   "index'");
  Record r(*this, j, name, Section::Surfaces);
  r.count("the surface number " + std::to_string(n) +
              " (surfaces are numbered consecutively from 1; the first record counts " +
              std::to_string(scene_.numbers.surfaces) + ")",
          n);
  SurfaceRecord s;
  s.where = lineAt(j);
  const std::string model = r.keyword("model", modelKeywords());
  s.model = model == "lambert" ? ShadingModel::Lambert
            : model == "phong" ? ShadingModel::Phong
                               : ShadingModel::Cook;
  const std::string kind = r.keyword("textured|normal", {"textured", "normal"});
  s.textured = kind == "textured";
  if (s.model == ShadingModel::Cook && s.textured)
    throw io::InputError(s.where, name + ", field textured|normal",
                         "normal (there is no textured Cook form, Appendix 1 section 8)",
                         "'textured'");
  s.reflect = r.realIn("reflect", 0.0, 1.0, "a real number 0.0-1.0 (k_r; CGL-Q3)");
  s.refract = r.realIn("refract", 0.0, 1.0, "a real number 0.0-1.0 (k_t; CGL-Q3)");
  s.index = r.realIn("index", 0.0, std::numeric_limits<double>::max(),
                     "a real number 0.0 or more (the refractive index; present even if unused)");
  if (s.refract > 0.0 && !(s.index > 0.0))
    throw io::InputError(s.where, name + ", field index",
                         "a refractive index above 0.0 for a transparent surface (refract > 0)",
                         shown("0"));
  done(r);

  auto advise = [&](const io::InputLocation& w, const std::string& field, double v, double lo,
                    double hi) {
    if (v < lo || v > hi) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s, %s %g is outside the range %g-%g the manual advises",
                    name.c_str(), field.c_str(), v, lo, hi);
      warn(w, std::string(buf) + " (Appendix 1 section 8; CGL-Q3)");
    }
  };
  const double big = std::numeric_limits<double>::max();
  // The coefficients line.
  {
    std::size_t k = header(name + ", coefficients");
    const Line& cl = lines_[k];
    if (lenient_ && s.model == ShadingModel::Lambert && s.textured && !cl.tokens.empty() &&
        !isReal(cl.tokens[0].text) &&
        (cl.tokens[0].text[0] == '/' || cl.tokens[0].text == "last" ||
         (cl.tokens.size() >= 3 && isReal(cl.tokens[1].text) && isReal(cl.tokens[2].text)))) {
      s.diffuse = 7.0;
      repair(cl.number, name +
                            ": no diffuse line before the texture line; diffuse 7.0 assumed, "
                            "the value of the document's Figure 59 (CGL-E9)");
    } else {
      Record c(*this, k, name, Section::Surfaces);
      const std::string lo = "a real number 0.0 or more";
      std::string hint;
      if (!cl.tokens.empty() && !isReal(cl.tokens[0].text) && s.textured &&
          s.model == ShadingModel::Lambert)
        hint = " (the document's Figure 2 omits this line; --lenient assumes 7.0)";
      if (s.model == ShadingModel::Cook) {
        s.diffuse = c.realIn("diffuse", 0.0, big, lo + " (advised 0.0-1.0)");
        advise(lineAt(k), "diffuse", s.diffuse, 0.0, 1.0);
      } else {
        const Token& t = c.take("diffuse", lo);
        double v = 0.0;
        if (parseReal(t.text, v) != NumberStatus::Ok || v < 0.0)
          c.fail(t, "diffuse", lo + " (advised 0.0-20.0)", shown(t.text) + hint);
        s.diffuse = v;
        advise(lineAt(k), "diffuse", s.diffuse, 0.0, 20.0);
        if (s.model == ShadingModel::Phong) {
          s.specular = c.realIn("specular", 0.0, big, lo + " (advised 0.0-20.0)");
          advise(lineAt(k), "specular", s.specular, 0.0, 20.0);
          s.exponent = c.realIn("exponent", 0.0, big, lo + " (advised 10.0-100.0)");
          advise(lineAt(k), "exponent", s.exponent, 10.0, 100.0);
        }
      }
      done(c);
    }
  }
  if (s.textured) {
    const std::size_t k = header(name + ", texture");
    Record t(*this, k, name, Section::Surfaces);
    const Token& path = t.take("pathname|last", "a texture pathname or 'last'");
    if (path.text == "last") {
      if (lastTexture_.empty())
        t.fail(path, "pathname|last",
               "a texture pathname ('last' means the texture of an earlier textured surface, and "
               "there is none)",
               "'last'");
      s.texture = lastTexture_;
      s.textureLast = true;
      s.textureWhere = lastTextureWhere_;
    } else {
      double v;
      if (parseReal(path.text, v) == NumberStatus::Ok)
        t.fail(path, "pathname|last", "a texture pathname or 'last'", shown(path.text));
      s.textureWhere = t.at(path);
      s.texture = path.text;
      lastTexture_ = s.texture;
      lastTextureWhere_ = t.at(path);
    }
    const double lo = std::numeric_limits<double>::min();
    s.umod = t.realIn("umod", lo, big, "a real number above 0.0 (the repeat count in u)");
    s.vmod = t.realIn("vmod", lo, big, "a real number above 0.0 (the repeat count in v)");
    done(t);
  } else {
    s.colour = colourVector(name, Section::Surfaces);
  }
  if (s.model == ShadingModel::Cook) {
    const std::size_t k = header(name + ", specular m");
    Record c(*this, k, name, Section::Surfaces);
    s.specular = c.realIn("specular", 0.0, big, "a real number 0.0 or more (advised 0.0-1.0)");
    advise(lineAt(k), "specular", s.specular, 0.0, 1.0);
    s.m = c.realIn("m", std::numeric_limits<double>::min(), big,
                   "a real number above 0.0 (the rms facet slope; advised 0.1-1.0)");
    advise(lineAt(k), "m", s.m, 0.1, 1.0);
    done(c);
    for (int a = 0; a < kFresnelAngles; ++a)
      s.fresnel.push_back(colourVector(name + ", fresnel colour-vector " + std::to_string(a + 1) +
                                           " of " + std::to_string(kFresnelAngles),
                                       Section::Surfaces));
  }
  scene_.surfaces.push_back(std::move(s));
}

void Reader::ambience() {
  const std::size_t j = header("ambience descriptor");
  Record r(*this, j, "ambience descriptor", Section::Ambience);
  auto& a = scene_.ambience;
  a.where = lineAt(j);
  {
    const Line& l = lines_[j];
    if (!l.tokens.empty() && !isReal(l.tokens[0].text) && !hintFor(l).empty())
      notARecord(j, "ambience descriptor, field k_a", "a real number 0.0 or more");
  }
  a.ka = r.realIn("k_a", 0.0, std::numeric_limits<double>::max(),
                  "a real number 0.0 or more (the ambient-reflection constant, advised 0.0-0.001)");
  if (a.ka > 0.001)
    warn(a.where,
         "ambience k_a is above the 0.0-0.001 the manual advises (Appendix 1 section "
         "10; CGL-Q3)");
  done(r);
  a.colour = colourVector("ambience descriptor", Section::Ambience);
}

void Reader::light(int n) {
  const std::string base = "light " + std::to_string(n);
  const std::size_t j = header(base);
  const Line& l = lines_[j];
  std::string name = base;
  if (l.tokens.size() >= 2) name += " (" + l.tokens[1].text + ")";
  if (!isCount(l.tokens[0].text))
    notARecord(j, base + ", field count",
               "'" + std::to_string(n) + " (infinity|inscene) x y z dw'");
  Record r(*this, j, name, Section::Lights);
  r.count("the light number " + std::to_string(n) +
              " (lights are numbered consecutively from 1; the first record counts " +
              std::to_string(scene_.numbers.lights) + ")",
          n);
  LightRecord L;
  L.where = lineAt(j);
  const std::string kind = r.keyword("infinity|inscene", lightKeywords());
  L.kind = kind == "infinity" ? LightKind::Infinity : LightKind::InScene;
  L.xyz[0] = r.real("x");
  L.xyz[1] = r.real("y");
  L.xyz[2] = r.real("z");
  if (L.kind == LightKind::Infinity && L.xyz == Vec3{0, 0, 0})
    throw io::InputError(L.where, name + ", field x y z",
                         "a direction to the light other than (0, 0, 0)", "(0, 0, 0)");
  L.dw = r.realIn("dw", 0.0, std::numeric_limits<double>::max(),
                  "a real number 0.0 or more (the solid angle, advised 0.0001-0.005)");
  if (L.dw < 0.0001 || L.dw > 0.005)
    warn(L.where, name +
                      ": dw outside the 0.0001-0.005 the manual calls useful (Appendix 1 "
                      "section 11; CGL-Q15)");
  done(r);
  L.colour = colourVector(name, Section::Lights);
  scene_.lights.push_back(L);
}

}  // namespace prime::cgl::detail
