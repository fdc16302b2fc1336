// The CGL scene-description file reader (Sweeney 1985, Appendix 1). The
// choices the manual leaves open and the repairs of the lenient reader are in
// docs/cgl/deviations.md (ids CGL-E1 to CGL-E10, CGL-Q1 to CGL-Q15, CGL-D1 to CGL-D3), the
// format for users in docs/cgl/scene-format.md.
#include "legacy_io/cgl/scene_file.h"

#include <sstream>

#include "legacy_io/cgl/scene_reader.h"
#include "legacy_io/common/input_file.h"

namespace prime::cgl {

namespace detail {

SceneFile Reader::read() {
  scene_.path = display_;
  numbersOfThings();
  const auto& n = scene_.numbers;
  for (int k = 0; k < n.programParameters; ++k) programParameter(k);
  for (int k = 0; k < n.displayParameters; ++k) displayParameter(k);
  for (int k = 1; k <= n.vertices; ++k) vertex(k);
  if (lenient_) boundary_ = findAmbienceBoundary();
  for (int k = 1; k <= n.surfaces; ++k) surface(k);
  boundary_ = std::numeric_limits<std::size_t>::max();
  ambience();
  for (int k = 1; k <= n.lights; ++k) light(k);
  for (int k = 1; k <= n.nodes; ++k) node(k);
  if (!orphans_.empty()) {
    const std::size_t o = orphans_.front();
    notARecord(o, "scene nodes",
               "no more lines (the parameters on this line belong to no node's header)");
  }
  const std::size_t rest = nextContent(next_);
  if (rest < lines_.size())
    notARecord(rest, "end of the scene",
               "end of file (the first record counts " + std::to_string(n.nodes) +
                   " scene nodes, all read)");
  checkDag();
  if (scene_.program.given.brightness && scene_.program.given.background)
    warn({display_, scene_.numbers.where.line},
         "both brightness and background are given; the original program accepted only one of "
         "them, depending on -Dbackground (Appendix 1 section 5; CGL-Q14)");
  return std::move(scene_);
}

void Reader::numbersOfThings() {
  const std::size_t j = header("numbers-of-things");
  Record r(*this, j, "numbers-of-things", Section::First);
  auto& n = scene_.numbers;
  n.where = lineAt(j);
  const std::string e = "a count 0 or more";
  n.programParameters = static_cast<int>(
      r.integer("number-of-program-parameters", 0, 1000000, e + " (7 integers open the file)"));
  n.displayParameters = static_cast<int>(r.integer("number-of-display-parameters", 0, 1000000, e));
  n.vertices = static_cast<int>(r.integer("number-of-vertices", 0, 100000000, e));
  n.surfaces = static_cast<int>(r.integer("number-of-surface-descriptors", 0, 100000000, e));
  n.lights = static_cast<int>(r.integer("number-of-light-sources", 0, 100000000, e));
  n.nodes = static_cast<int>(r.integer("number-of-scene-nodes", 1, 100000000,
                                       "a count 1 or more (a scene has at least its root; "
                                       "CGL-Q10)"));
  n.root = static_cast<int>(
      r.integer("DAG-root-node", 1, n.nodes, "a scene-node number 1-" + std::to_string(n.nodes)));
  done(r);
}

void Reader::node(int n) {
  const std::string base = "scene node " + std::to_string(n);
  std::size_t j = header(base);
  // Lines printed before the header, belonging to no record: the lenient
  // reader keeps them for the next header short of fields (CGL-E8).
  for (;;) {
    const Line& l = lines_[j];
    const bool recordLike = l.tokens.size() >= 2 && isCount(l.tokens[0].text) &&
                            std::isalpha(static_cast<unsigned char>(l.tokens[1].text[0])) &&
                            l.tokens[1].text != "x" && l.tokens[1].text != "y" &&
                            l.tokens[1].text != "z";
    if (recordLike || !lenient_) break;
    orphans_.push_back(j);
    next_ = j + 1;
    j = header(base);
  }
  const Line& l = lines_[j];
  std::string name = base;
  if (l.tokens.size() >= 2) name += " (" + l.tokens[1].text + ")";
  if (!isCount(l.tokens[0].text))
    notARecord(j, base + ", field count",
               "'" + std::to_string(n) + " keyword down right ...' (a scene node)");
  Record r(*this, j, name, Section::Nodes);
  r.count("the node number " + std::to_string(n) +
              " (scene nodes are numbered consecutively from 1; the first record counts " +
              std::to_string(scene_.numbers.nodes) + ")",
          n);
  NodeRecord d;
  d.number = n;
  d.where = lineAt(j);
  const std::string kw = r.keyword("keyword", nodeKeywords());
  const int nodes = scene_.numbers.nodes;
  const std::string link = "a scene-node number 0-" + std::to_string(nodes) + " (0 = none)";
  d.down = static_cast<int>(r.integer("down", 0, nodes, link));
  d.right = static_cast<int>(r.integer("right", 0, nodes, link));
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::min();
  // A reference into a table: 1..size, refused outright when the table is empty.
  auto reference = [&](const std::string& field, const char* table, int size) {
    const std::string e = size == 0
                              ? std::string("a ") + table + " number (the file has none)"
                              : std::string("a ") + table + " number 1-" + std::to_string(size);
    const int v = static_cast<int>(
        r.integer(field, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), e));
    if (v < 1 || v > size) r.fail(r.last(), field, e, shown(r.last().text));
    return v;
  };
  auto surface = [&] { return reference("surface-index", "surface", scene_.numbers.surfaces); };
  auto vertexRef = [&](const std::string& field) {
    return reference(field, "vertex", scene_.numbers.vertices);
  };
  if (kw == "translate" || kw == "scale") {
    d.kind = kw == "translate" ? NodeKind::Translate : NodeKind::Scale;
    d.xyz[0] = r.real("x");
    d.xyz[1] = r.real("y");
    d.xyz[2] = r.real("z");
    if (d.kind == NodeKind::Scale && (d.xyz[0] == 0.0 || d.xyz[1] == 0.0 || d.xyz[2] == 0.0)) {
      d.ignored = true;
      warn(d.where, name +
                        ": a scale factor is 0.0: warning, node ignored (Appendix 1 section "
                        "13; CGL-Q7)");
    }
  } else if (kw == "rotate") {
    d.kind = NodeKind::Rotate;
    d.axis = r.axis("axis");
    d.theta = r.real("theta", "a real number (degrees)");
  } else if (kw == "sphere") {
    d.kind = NodeKind::Sphere;
    d.surface = surface();
    d.xyz[0] = r.real("x");
    d.xyz[1] = r.real("y");
    d.xyz[2] = r.real("z");
    d.radius = r.realIn("radius", tiny, big, "a real number above 0.0");
    d.textureAxis1 = r.axis("texture axis 1");
    d.textureAxis2 = r.axis("texture axis 2");
    if (d.textureAxis1 == d.textureAxis2)
      throw io::InputError(d.where, name + ", field texture axis 2",
                           "an axis other than texture axis 1 (CGL-Q12)",
                           std::string("'") + d.textureAxis2 + "'");
  } else if (kw == "cylinder") {
    d.kind = NodeKind::Cylinder;
    d.surface = surface();
    d.radius = r.realIn("radius", tiny, big, "a real number above 0.0");
    d.vertices.push_back(vertexRef("v1"));
    d.vertices.push_back(vertexRef("v2"));
    if (d.vertices[0] == d.vertices[1])
      throw io::InputError(d.where, name + ", field v2",
                           "a vertex other than v1 (the axis runs from v1 to v2; CGL-Q12)",
                           shown(std::to_string(d.vertices[1])));
  } else if (kw == "polygon") {
    d.kind = NodeKind::Polygon;
    d.surface = surface();
    const int count = static_cast<int>(r.integer(
        "n", 3, 4, "3 or 4 (\"only triangles and rectangles\", Appendix 1 section 13; CGL-Q8)"));
    for (int v = 1; v <= count; ++v) d.vertices.push_back(vertexRef("v" + std::to_string(v)));
  } else if (kw == "fractal") {
    d.kind = NodeKind::Fractal;
    d.surface = surface();
    d.divisions = static_cast<int>(
        r.integer("divisions", 1, 10, "an integer 1-10 (the manual: 1-9; CGL-Q9)"));
    if (d.divisions == 10)
      warn(d.where, name +
                        ": 10 divisions, above the manual's 1-9 (Figure 18 claims 10; "
                        "CGL-Q9)");
    d.h = r.real("h", "a real number (advised 0.5-1.5)");
    if (d.h < 0.5 || d.h > 1.5)
      warn(d.where, name + ": h outside the 0.5-1.5 the manual advises (CGL-Q3)");
    d.offset = r.real("offset", "a real number (advised -1.0-1.0)");
    if (d.offset < -1.0 || d.offset > 1.0)
      warn(d.where, name + ": offset outside the -1.0-1.0 the manual advises (CGL-Q3)");
    d.seed = r.integer("seed", std::numeric_limits<std::int64_t>::min(),
                       std::numeric_limits<std::int64_t>::max(), "an integer");
    d.constrained = r.keyword("constrained|free", {"constrained", "free"}) == "constrained";
  } else if (kw == "spline") {
    d.kind = NodeKind::Spline;
    d.surface = surface();
    splineNode(r, d, name);
    scene_.nodes.push_back(std::move(d));
    return;
  } else if (kw == "box") {
    d.kind = NodeKind::Box;
  } else {
    d.kind = NodeKind::Dummy;
  }
  done(r);
  scene_.nodes.push_back(std::move(d));
}

// The DAG: no cycle along down and right links (shared subtrees allowed),
// walked iteratively so that a long chain cannot overflow the stack (CGL-D2);
// nodes the root cannot reach are reported as warnings (CGL-Q10).
// A spline node's fields after its surface (section 6.2: nu, the u end
// condition, nv, the v end condition, divisions, overlap), then its nu x nv
// control vertices, one a line, in groups of nu whose count restarts at 1.
void Reader::splineNode(Record& r, NodeRecord& d, const std::string& name) {
  auto end = [&](const std::string& field) {
    const std::string e = r.keyword(field, {"single", "double", "triple", "closed"});
    return e == "single"   ? EndCondition::Single
           : e == "double" ? EndCondition::Double
           : e == "triple" ? EndCondition::Triple
                           : EndCondition::Closed;
  };
  const std::string ne = "an integer 2-1000 (control vertices; CGL-Q9)";
  d.nu = static_cast<int>(r.integer("nu", 2, 1000, ne));
  d.uEnd = end("u end condition");
  d.nv = static_cast<int>(r.integer("nv", 2, 1000, ne));
  d.vEnd = end("v end condition");
  d.divisions = static_cast<int>(
      r.integer("divisions", 1, 64, "an integer 1-64 (sub-intervals per knot interval; CGL-Q9)"));
  d.overlap =
      r.realIn("overlap", 0.0, std::numeric_limits<double>::max(), "a real number 0.0 or more");
  done(r);
  for (int v = 0; v < d.nv; ++v)
    for (int u = 0; u < d.nu; ++u) {
      const std::string cname = name + ", control vertex " + std::to_string(u + 1) + " of group " +
                                std::to_string(v + 1) + " of " + std::to_string(d.nv);
      const std::size_t k = header(cname);
      if (!isCount(lines_[k].tokens[0].text) ||
          (lines_[k].tokens.size() >= 2 && anyKeyword(lines_[k].tokens[1].text)))
        notARecord(k, cname + ", field count",
                   "'" + std::to_string(u + 1) + " x y z' (the spline's " +
                       std::to_string(d.nu * d.nv) + " control vertices: " + std::to_string(d.nv) +
                       " groups of " + std::to_string(d.nu) + ")");
      Record c(*this, k, cname, Section::Nodes);
      c.count("the u count " + std::to_string(u + 1) +
                  " (it restarts at 1 in each group of nu = " + std::to_string(d.nu) + "; CGL-Q6)",
              u + 1);
      Vec3 p{};
      p[0] = c.real("x");
      p[1] = c.real("y");
      p[2] = c.real("z");
      d.controls.push_back(p);
      done(c);
    }
}

void Reader::checkDag() {
  const auto& nodes = scene_.nodes;
  const std::size_t count = nodes.size();
  std::vector<unsigned char> state(count + 1, 0);  // 0 new, 1 on the path, 2 done
  std::vector<std::pair<int, int>> stack;          // node, next link (0 down, 1 right, 2 done)
  const int root = scene_.numbers.root;
  stack.push_back({root, 0});
  state[static_cast<std::size_t>(root)] = 1;
  while (!stack.empty()) {
    auto& [node, link] = stack.back();
    if (link == 2) {
      state[static_cast<std::size_t>(node)] = 2;
      stack.pop_back();
      continue;
    }
    const NodeRecord& d = nodes[static_cast<std::size_t>(node - 1)];
    const int child = link == 0 ? d.down : d.right;
    const char* which = link == 0 ? "down" : "right";
    ++link;
    if (child == 0) continue;
    const auto c = static_cast<std::size_t>(child);
    if (state[c] == 2) continue;  // a shared subtree, already checked
    if (state[c] == 1) {
      std::vector<int> path;
      bool on = false;
      for (const auto& e : stack) {
        if (e.first == child) on = true;
        if (on) path.push_back(e.first);
      }
      path.push_back(child);
      std::string cycle;
      for (std::size_t k = 0; k < path.size(); ++k) {
        if (path.size() > 12 && k == 5) {
          cycle += "... (" + std::to_string(path.size() - 10) + " more) -> ";
          k = path.size() - 5;
        }
        cycle += std::to_string(path[k]) + (k + 1 < path.size() ? " -> " : "");
      }
      throw io::InputError(d.where, "scene node " + std::to_string(node) + ", field " + which,
                           "a node that does not lead back to node " + std::to_string(node) +
                               " (the scene nodes form a DAG)",
                           std::to_string(child) + ", closing the cycle " + cycle);
    }
    state[c] = 1;
    stack.push_back({child, 0});
  }
  std::vector<int> unreachable;
  for (std::size_t k = 1; k <= count; ++k)
    if (state[k] == 0) unreachable.push_back(static_cast<int>(k));
  if (!unreachable.empty()) {
    std::string list;
    for (std::size_t k = 0; k < unreachable.size() && k < 10; ++k)
      list += (k ? ", " : "") + std::to_string(unreachable[k]);
    if (unreachable.size() > 10) list += ", ...";
    warn(nodes[static_cast<std::size_t>(unreachable[0] - 1)].where,
         std::to_string(unreachable.size()) + " scene node" +
             (unreachable.size() > 1 ? "s are" : " is") + " not reachable from the root node " +
             std::to_string(root) + ": " + list + " (CGL-Q10)");
  }
}

}  // namespace detail

using detail::allDigits;
using detail::anyKeyword;
using detail::kBullet;
using detail::kMaxBytes;
using detail::Reader;

SceneFile readScene(const std::string& text, const std::string& display,
                    const ReadOptions& options) {
  // A ^Z ends the text (M41, every system's rule; readInputText has cut a
  // file's already).
  if (text.find(io::kDosEof) != std::string::npos) {
    std::string cut = text;
    io::endAtDosEof(cut);
    return readScene(cut, display, options);
  }
  if (text.size() > kMaxBytes)
    throw io::InputError(io::InputLocation{display, 1},
                         "larger than 64 MiB: not read as a CGL scene file (CGL-D2)");
  return Reader(text, display, options).read();
}

SceneFile readSceneFile(const std::string& path, const ReadOptions& options) {
  io::InputFileOptions input;
  input.maxBytes = kMaxBytes;  // CGL-D2
  input.what = "a CGL scene file";
  return readScene(io::readInputText(path, input), path, options);
}

bool looksLikeCgl(const std::string& text) {
  std::istringstream in(text.substr(0, 65536));
  std::string line;
  int seen = 0;
  while (std::getline(in, line) && seen < 200) {
    std::istringstream words(line);
    std::string first, second;
    if (!(words >> first)) continue;
    ++seen;
    if (seen == 1 && (first[0] == '*' || std::string_view(first).starts_with(kBullet) ||
                      std::string_view(first).starts_with("\\*")))
      return true;
    if (first[0] == '*' || std::string_view(first).starts_with(kBullet)) continue;
    if (!(words >> second)) continue;
    const bool count = allDigits(first) || first == "l";  // the OCR's 'l lambert' (CGL-E4)
    if (count && anyKeyword(second)) return true;
  }
  return false;
}

}  // namespace prime::cgl
