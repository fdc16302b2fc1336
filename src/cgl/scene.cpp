#include "src/cgl/scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>
#include <system_error>
#include <unordered_map>

#include "src/math/matrix.h"

namespace prime::cgl {

Ray Camera::primaryRay(double x, double y) const {
  const Vec3 d = start + xpath * (x - 256.0) + ypath * (y - 256.0);
  return {eye, normalized(d)};
}

namespace {

io::InputLocation fileOnly(const std::string& path) {
  io::InputLocation where;
  where.file = path;
  return where;
}

}  // namespace

Camera cameraOf(const DisplayParameters& display, const std::string& path) {
  const double sightLength = length(display.sight);
  if (!(sightLength > 0.0))
    throw io::InputError(fileOnly(path), "sight", "a non-zero viewing direction",
                         "the sight is the eye point itself");
  Camera cam;
  cam.eye = display.eye;
  cam.sight = display.sight * (1.0 / sightLength);
  // Appendix 1 section 6: the scan-line direction is up x sight.
  const Vec3 right = cross(display.up, cam.sight);
  if (!(length(right) > 0.0))
    throw io::InputError(fileOnly(path), "up", "an up vector not parallel to the sight",
                         "an up vector parallel to the sight (or zero)");
  cam.right = normalized(right);
  // CGL-Q40: up orthogonalised against the sight.
  cam.up = normalized(display.up - cam.sight * dot(display.up, cam.sight));
  cam.start = cam.sight * display.dist;
  cam.xpath = cam.right * (display.viewportWidth / 512.0);
  cam.ypath = cam.up * (display.viewportHeight / 512.0);
  return cam;
}

FreeCameraSettings freeCamera(const DisplayParameters& d) {
  FreeCameraSettings c;
  c.eye = d.eye;
  c.lookAt = d.eye + d.sight;
  c.up = d.up;
  c.fovY = 2.0 * std::atan(0.5 * d.viewportHeight / d.dist) * 180.0 / std::numbers::pi;
  c.width = c.height = 512;
  return c;
}

DisplayParameters displayOf(const FreeCameraSettings& c) {
  DisplayParameters d;
  d.eye = c.eye;
  d.sight = c.lookAt - c.eye;
  d.up = c.up;
  d.dist = 1.0;
  // D = s + (x - 256) (w / 512) r + (y - 256) (h / 512) u: H scanlines of
  // h / 512 each span 2 tan(fov / 2) at distance 1.
  d.viewportHeight = d.viewportWidth =
      512.0 * 2.0 * std::tan(0.5 * c.fovY * std::numbers::pi / 180.0) / c.height;
  return d;
}

namespace {

// Row-vector matrices (src/math/matrix.h: p' = p M).
Matrix4 translation(const Vec3& t) {
  Matrix4 m = identity4();
  for (int i = 0; i < 3; ++i) m[3][i] = t[i];
  return m;
}
Matrix4 scaling(const Vec3& s) {
  Matrix4 m = identity4();
  for (int i = 0; i < 3; ++i) m[i][i] = s[i];
  return m;
}
// CGL-Q41: `rotate a theta` is the right-handed rotation by -theta about a
// ("clockwise looking down the axis towards the origin", Appendix 1 section
// 9; the sign under which Figure 59's floor is seen from above). With
// phi = -theta and R the column-vector matrix, the row-vector matrix is R^T.
Matrix4 rotation(char axis, double thetaDegrees) {
  const double phi = -thetaDegrees * std::numbers::pi / 180.0;
  const double c = std::cos(phi), s = std::sin(phi);
  Matrix4 m = identity4();
  int i = 1, j = 2;  // the plane rotated: x about the axis (y, z), and so on
  if (axis == 'y') {
    i = 2;
    j = 0;
  } else if (axis == 'z') {
    i = 0;
    j = 1;
  }
  // Column-vector R: p_i' = c p_i - s p_j, p_j' = s p_i + c p_j; row-vector
  // m[row = source][column = destination].
  m[i][i] = c;
  m[j][i] = -s;
  m[i][j] = s;
  m[j][j] = c;
  return m;
}

void pad(Aabb& box) {
  // A little slack so that rounding in an intersection routine can never put
  // a hit outside its object's box (the box test then could skip it).
  for (int k = 0; k < 3; ++k) {
    const double slack = 1e-9 * (1.0 + std::max(std::fabs(box.lo[k]), std::fabs(box.hi[k])));
    box.lo[k] -= slack;
    box.hi[k] += slack;
  }
}

struct Item {
  Object object;
  std::vector<Item> contents;  // a box's, in list order
};

class Preprocessor {
 public:
  Preprocessor(const SceneFile& file, const BuildOptions& options, Scene& scene)
      : file_(file), options_(options), scene_(scene) {}

  // Appends the objects of the subgraph at `number` in processing order.
  // Iterative (a chain of thousands of nodes overflowed the stack when each
  // node was a call) and counted: every node reached along every path is a
  // visit, and a DAG whose shared nodes multiply the paths (2^60 of them in
  // a 4 KB file) is refused at options.maxVisits, before the work.
  void process(int root, const Matrix4& m, std::vector<Item>& out) {
    struct Task {
      enum Kind { Visit, Own, CloseBox } kind;
      int number;
      Matrix4 m;
      std::vector<Item>* out;
      int depth;
      std::size_t inner;  // CloseBox: the box's contents in inner_
    };
    std::vector<Task> tasks;
    tasks.push_back({Task::Visit, root, m, &out, 0, 0});
    while (!tasks.empty()) {
      const Task t = tasks.back();
      tasks.pop_back();
      if (t.kind == Task::Visit) {
        if (t.number == 0) continue;
        if (t.number < 1 || t.number > static_cast<int>(file_.nodes.size()))
          throw io::InputError(fileOnly(file_.path), "node", "a node number of the file",
                               std::to_string(t.number));
        const NodeRecord& node = file_.nodes[static_cast<std::size_t>(t.number - 1)];
        if (t.depth > static_cast<int>(file_.nodes.size()))
          throw io::InputError(node.where, "down/right", "a DAG without cycles",
                               "a cycle through node " + std::to_string(t.number));
        if (++visits_ > options_.maxVisits)
          throw io::InputError(
              node.where, "down/right",
              "a DAG of at most " + std::to_string(options_.maxVisits) +
                  " node visits (a node shared by several parents is walked once per path)",
              "more: node " + std::to_string(t.number) + " is reached again after " +
                  std::to_string(options_.maxVisits) + " visits");
        // Appendix 1 section 9: right pointers before down pointers (the
        // right subgraph first, then the node's own work: pushed in reverse).
        tasks.push_back({Task::Own, t.number, t.m, t.out, t.depth, 0});
        tasks.push_back({Task::Visit, node.right, t.m, t.out, t.depth + 1, 0});
        continue;
      }
      const NodeRecord& node = file_.nodes[static_cast<std::size_t>(t.number - 1)];
      if (t.kind == Task::CloseBox) {
        std::vector<Item>& inner = inner_[t.inner];
        if (inner.empty()) continue;  // nothing to enclose: no box node
        Item box;
        box.object.kind = ObjectKind::Box;
        box.object.surface = -1;
        box.object.node = node.number;
        std::reverse(inner.begin(), inner.end());  // prepended: the first processed is last
        for (const Item& it : inner) box.object.box.add(it.object.box);
        box.contents = std::move(inner);
        t.out->push_back(std::move(box));
        ++scene_.boxes;
        count(node);
        continue;
      }
      // A node's transformation applies to its down subgraph only (CGL-Q42).
      const auto down = [&](const Matrix4& own) {
        Matrix4 child = own;  // p (own) (parent's): the node's own transform first
        matrixMul(child, t.m);
        tasks.push_back({Task::Visit, node.down, child, t.out, t.depth + 1, 0});
      };
      switch (node.kind) {
        case NodeKind::Translate:
          down(translation(node.xyz));
          break;
        case NodeKind::Scale:
          if (node.xyz[0] == 0.0 || node.xyz[1] == 0.0 || node.xyz[2] == 0.0) {
            scene_.warnings.push_back(io::describe(node.where) + ": scale node " +
                                      std::to_string(node.number) +
                                      " has a 0.0 component and is ignored (Appendix 1)");
            tasks.push_back({Task::Visit, node.down, t.m, t.out, t.depth + 1, 0});
          } else {
            down(scaling(node.xyz));
          }
          break;
        case NodeKind::Rotate:
          down(rotation(node.axis, node.theta));
          break;
        case NodeKind::Dummy:
          tasks.push_back({Task::Visit, node.down, t.m, t.out, t.depth + 1, 0});
          break;
        case NodeKind::Fractal:
          t.out->push_back(Item{fractal(node, t.m), {}});  // counted by its facets (CGL-Q128)
          ++scene_.primitives;
          tasks.push_back({Task::Visit, node.down, t.m, t.out, t.depth + 1, 0});  // CGL-Q42
          break;
        case NodeKind::Spline:
          t.out->push_back(Item{splineObject(node, t.m), {}});
          ++scene_.primitives;
          count(node);
          tasks.push_back({Task::Visit, node.down, t.m, t.out, t.depth + 1, 0});
          break;
        case NodeKind::Box: {
          // The contents first, then the box around them.
          inner_.emplace_back();
          const std::size_t inner = inner_.size() - 1;
          tasks.push_back({Task::CloseBox, t.number, t.m, t.out, t.depth, inner});
          tasks.push_back({Task::Visit, node.down, t.m, &inner_[inner], t.depth + 1, 0});
          break;
        }
        case NodeKind::Sphere:
        case NodeKind::Cylinder:
        case NodeKind::Polygon:
          t.out->push_back(Item{primitive(node, t.m), {}});
          ++scene_.primitives;
          count(node);
          // A primitive's down subgraph (not used by the document's files) is
          // processed with the primitive's own transformation (CGL-Q42).
          tasks.push_back({Task::Visit, node.down, t.m, t.out, t.depth + 1, 0});
          break;
      }
    }
  }

 private:
  void count(const NodeRecord& node) {
    if (++made_ > options_.maxObjects)
      throw io::InputError(node.where, "scene nodes",
                           "at most " + std::to_string(options_.maxObjects) + " object nodes",
                           "more (shared subtrees instantiated once per path)");
  }

  int surfaceIndex(const NodeRecord& node) const {
    if (node.surface < 1 || node.surface > static_cast<int>(file_.surfaces.size()))
      throw io::InputError(node.where, "surface",
                           "a surface number 1.." + std::to_string(file_.surfaces.size()),
                           std::to_string(node.surface));
    return node.surface - 1;
  }

  Vec3 vertex(const NodeRecord& node, int n) const {
    if (n < 1 || n > static_cast<int>(file_.vertices.size()))
      throw io::InputError(node.where, "vertex",
                           "a vertex number 1.." + std::to_string(file_.vertices.size()),
                           std::to_string(n));
    return file_.vertices[static_cast<std::size_t>(n - 1)];
  }

  static Vec3 axisVector(char a) {
    if (a == 'y') return {0.0, 1.0, 0.0};
    if (a == 'z') return {0.0, 0.0, 1.0};
    return {1.0, 0.0, 0.0};
  }

  // Section 6: the control vertices through the current transformation,
  // then refinement and the box tree (src/cgl/spline.h).
  Object splineObject(const NodeRecord& node, const Matrix4& m) {
    Object o;
    o.kind = ObjectKind::Spline;
    o.node = node.number;
    o.surface = surfaceIndex(node);
    o.opaque = file_.surfaces[static_cast<std::size_t>(o.surface)].refract == 0.0;
    auto need = [&](int count, EndCondition end, const char* field) {
      // The parameter range (6.4.1) must hold at least one knot interval.
      const ParamRange r = parameterRange(count, end);
      if (!(r.max > r.min))
        throw io::InputError(node.where, field,
                             std::string("at least ") + (end == EndCondition::Single ? "3" : "2") +
                                 " control vertices for this end condition",
                             std::to_string(count));
    };
    need(node.nu, node.uEnd, "nu");
    need(node.nv, node.vEnd, "nv");
    if (node.divisions < 1)
      throw io::InputError(node.where, "divisions", "an integer >= 1",
                           std::to_string(node.divisions));
    if (static_cast<int>(node.controls.size()) != node.nu * node.nv)
      throw io::InputError(node.where, "control vertices",
                           std::to_string(node.nu * node.nv) + " (nu x nv)",
                           std::to_string(node.controls.size()));
    // The refined mesh (6.3.3) and its box tree, sized before any is made: a
    // few numbers (nu, nv, divisions) ask for gigabytes.
    const auto refined = [&](int n) {  // refinedLast (+5): the mesh's points in one direction
      return (static_cast<std::uint64_t>(n) + 1) * static_cast<std::uint64_t>(node.divisions) + 3;
    };
    const std::uint64_t points = refined(node.nu) * refined(node.nv);
    splineBytes_ += points * kSplineBytesPerPoint;
    if (points > (std::uint64_t{1} << 40) || splineBytes_ > options_.maxSplineBytes)
      throw io::InputError(
          node.where, "nu, nv, divisions",
          "refined meshes of at most " + std::to_string(options_.maxSplineBytes >> 20) +
              " MiB in the whole scene (section 6.3.3; about " +
              std::to_string(kSplineBytesPerPoint) + " bytes a refined point with its box tree)",
          std::to_string(node.nu) + " x " + std::to_string(node.nv) + " vertices at " +
              std::to_string(node.divisions) + " divisions: " + std::to_string(refined(node.nu)) +
              " x " + std::to_string(refined(node.nv)) + " points, " +
              std::to_string(splineBytes_ >> 20) + " MiB with the spline nodes before it");
    std::vector<Vec3> controls;
    controls.reserve(node.controls.size());
    for (const Vec3& c : node.controls) controls.push_back(pointMatrixMul(c, m));
    SplineSurface s = buildSpline(controls, node.nu, node.nv, node.uEnd, node.vEnd, node.divisions,
                                  node.overlap, !options_.modernSplines);
    s.node = node.number;
    if (options_.modernSplines) buildModernCells(s);
    // Newton's points lie on the surface, inside the control vertices' hull.
    o.box = s.hull;
    pad(o.box);
    o.spline = static_cast<int>(scene_.splines.size());
    scene_.splines.push_back(std::move(s));
    return o;
  }

  Object primitive(const NodeRecord& node, const Matrix4& m) const {
    Object o;
    o.node = node.number;
    o.surface = surfaceIndex(node);
    o.opaque = file_.surfaces[static_cast<std::size_t>(o.surface)].refract == 0.0;
    switch (node.kind) {
      case NodeKind::Sphere:
        // Section 2.1: the centre is transformed, the radius and the texture
        // axes are not.
        o.kind = ObjectKind::Sphere;
        o.c = pointMatrixMul(node.xyz, m);
        o.r = node.radius;
        o.r2 = node.radius * node.radius;
        o.a1 = axisVector(node.textureAxis1);
        o.a2 = axisVector(node.textureAxis2);
        o.box.add(o.c - Vec3{o.r, o.r, o.r});
        o.box.add(o.c + Vec3{o.r, o.r, o.r});
        break;
      case NodeKind::Cylinder: {
        // Section 3.1: the end points are transformed, the radius is not.
        if (node.vertices.size() != 2)
          throw io::InputError(node.where, "cylinder", "two vertex numbers",
                               std::to_string(node.vertices.size()));
        o.kind = ObjectKind::Cylinder;
        o.a = pointMatrixMul(vertex(node, node.vertices[0]), m);
        const Vec3 b = pointMatrixMul(vertex(node, node.vertices[1]), m);
        o.p = b - o.a;
        o.pp = dot(o.p, o.p);
        if (!(o.pp > 0.0))
          throw io::InputError(node.where, "cylinder", "two distinct end points",
                               "both end points at the same place");
        o.r = node.radius;
        o.r2 = node.radius * node.radius;
        // Section 3.1: A1 = P x (0,0,1), or P x (0,1,0) when P is parallel
        // to z; normalised (CGL-Q47).
        Vec3 a1 = cross(o.p, {0.0, 0.0, 1.0});
        if (!(length(a1) > 0.0)) a1 = cross(o.p, {0.0, 1.0, 0.0});
        o.a1 = normalized(a1);
        for (const Vec3& e : {o.a, b}) {
          o.box.add(e - Vec3{o.r, o.r, o.r});
          o.box.add(e + Vec3{o.r, o.r, o.r});
        }
        break;
      }
      case NodeKind::Polygon: {
        const int n = static_cast<int>(node.vertices.size());
        if (n != 3 && n != 4)
          throw io::InputError(node.where, "polygon",
                               "3 or 4 vertices (triangles and rectangles only, section 4.1)",
                               std::to_string(n));
        o.kind = ObjectKind::Polygon;
        std::array<Vec3, 4> v{};
        for (int k = 0; k < n; ++k) {
          v[k] = pointMatrixMul(vertex(node, node.vertices[static_cast<std::size_t>(k)]), m);
          o.box.add(v[k]);
        }
        // Section 4.1: N_Ek = E2 - alpha E1 with E1 = V1 - V0, E2 = V2 - V0,
        // the other edges "by permuting the points" (CGL-Q43): edge k runs
        // from V_k to V_k+1 and is normal towards V_k+2 (indices mod n), so
        // a rectangle's fourth edge is V3 -> V0 seen from V1.
        o.edges = n;
        for (int k = 0; k < n; ++k) {
          const Vec3& p0 = v[k];
          const Vec3 e1 = v[(k + 1) % n] - p0;
          const Vec3 e2 = v[(k + 2) % n] - p0;
          const double ee = dot(e1, e1);
          if (!(ee > 0.0))
            throw io::InputError(node.where, "polygon", "distinct vertices",
                                 "vertices " + std::to_string(k + 1) + " and " +
                                     std::to_string((k + 1) % n + 1) + " at the same place");
          o.en[k] = e2 - e1 * (dot(e1, e2) / ee);
          o.d[k] = dot(o.en[k], p0);
        }
        // N = N_E1 x N_E2 (unit: Table 4's N), the plane point V0.
        const Vec3 normal = cross(o.en[0], o.en[1]);
        if (!(length(normal) > 0.0))
          throw io::InputError(node.where, "polygon", "a polygon with area", "collinear vertices");
        o.n = normalized(normal);
        o.v0 = v[0];
        o.e1 = v[1] - v[0];
        o.ne1 = o.en[0];
        o.umin = o.vmin = std::numeric_limits<double>::infinity();
        o.umax = o.vmax = -std::numeric_limits<double>::infinity();
        for (int k = 0; k < n; ++k) {
          const Vec3 q = v[k] - o.v0;
          const double u = dot(q, o.e1) / dot(o.e1, o.e1);
          const double w = dot(q, o.ne1) / dot(o.ne1, o.ne1);
          o.umin = std::min(o.umin, u);
          o.umax = std::max(o.umax, u);
          o.vmin = std::min(o.vmin, w);
          o.vmax = std::max(o.vmax, w);
        }
        break;
      }
      default:
        break;
    }
    pad(o.box);
    return o;
  }

  // Section 5: the surface is built from the node and the current
  // transformation; the object node keeps the texture frame and the tree's
  // root box, the scene the tree.
  Object fractal(const NodeRecord& node, const Matrix4& m) {
    Object o;
    o.kind = ObjectKind::Fractal;
    o.node = node.number;
    o.surface = surfaceIndex(node);
    const SurfaceRecord& surface = file_.surfaces[static_cast<std::size_t>(o.surface)];
    o.opaque = surface.refract == 0.0;
    if (node.divisions < 1 || node.divisions > 10)  // the reader's range (CGL-Q9)
      throw io::InputError(node.where, "divisions", "1..10", std::to_string(node.divisions));
    // CGL-Q128: every facet counts against BuildOptions::maxObjects, so that
    // a shared fractal node instantiated on many paths cannot exhaust memory.
    const long facets = 1L << (2 * node.divisions);
    if (made_ + facets > options_.maxObjects)
      throw io::InputError(node.where, "fractal",
                           "at most " + std::to_string(options_.maxObjects) +
                               " object nodes and fractal facets in the scene",
                           "more (this surface has " + std::to_string(facets) + " facets)");
    made_ += facets;
    FractalParams p;
    p.divisions = node.divisions;
    p.h = node.h;
    p.offset = node.offset;
    p.seed = node.seed;
    p.constrained = node.constrained;
    FractalSurface f = buildFractal(p, m);
    if (surface.textured && !f.textureFrame)
      throw io::InputError(node.where, "fractal",
                           "a textured fractal whose transformed triangle is not edge-on to the "
                           "y axis (section 5.3: the x and z equations need a solution)",
                           "the triangle lies in a plane containing the y axis");
    o.v0 = f.v0;
    o.e1 = f.e1;
    o.ne1 = f.ne1;
    o.umin = f.umin;
    o.umax = f.umax;
    o.vmin = f.vmin;
    o.vmax = f.vmax;
    o.box = f.root();
    pad(o.box);
    o.fractal = static_cast<int>(scene_.fractals.size());
    scene_.fractals.push_back(std::move(f));
    return o;
  }

  const SceneFile& file_;
  const BuildOptions& options_;
  Scene& scene_;
  long made_ = 0;
  long visits_ = 0;
  std::uint64_t splineBytes_ = 0;        // the refined meshes made so far
  std::deque<std::vector<Item>> inner_;  // the boxes' contents (a deque: they do not move)
};

// Iterative, and each box's contents moved out before its item goes (a
// recursive flatten, or destructor, would go as deep as boxes nest).
void flatten(std::vector<Item>& items, std::vector<Object>& out) {
  struct Open {
    std::vector<Item> items;
    std::size_t next;
    std::size_t box;  // its box in `out`, or npos for the top level
  };
  std::vector<Open> open;
  open.push_back({std::move(items), 0, std::string::npos});
  while (!open.empty()) {
    if (open.back().next == open.back().items.size()) {
      if (const std::size_t at = open.back().box; at != std::string::npos) {
        out[at].skip = static_cast<int>(out.size());
        pad(out[at].box);
      }
      open.pop_back();
      continue;
    }
    Item& it = open.back().items[open.back().next++];
    const std::size_t at = out.size();
    out.push_back(it.object);
    if (it.object.kind == ObjectKind::Box) {
      std::vector<Item> contents = std::move(it.contents);
      open.push_back({std::move(contents), 0, at});
    }
  }
}

bool sameIgnoringCase(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

std::string baseName(const std::string& written) {
  return std::filesystem::path(written).filename().string();
}

// Loads a surface's texture map into scene.textures and returns its index.
// A map already loaded (the same file, or the same supplied map) is not
// loaded again: its index is returned (6 MB of texels each; a scene naming
// one map on a few hundred surfaces took gigabytes).
int loadTexture(const SurfaceRecord& rec, const std::string& scenePath, const BuildOptions& options,
                Scene& scene, std::map<std::string, int>& loaded) {
  const std::string base = baseName(rec.texture);
  auto convert = [&](const Frame& frame, const std::string& where) {
    Texture tex;
    tex.path = where;
    tex.texels.resize(frame.words.size());
    // A texel's spectrum depends on its colour only: each colour is converted
    // once (a map holds few colours; the same numbers as converting every texel).
    // A texel the colour of the one before it (a run: most of a map) copies it.
    std::unordered_map<std::uint32_t, std::array<double, 3>> converted;
    for (std::size_t i = 0; i < frame.words.size(); ++i) {
      const std::uint32_t w = frame.words[i] & 0xffffffu;
      if (i > 0 && w == (frame.words[i - 1] & 0xffffffu)) {
        tex.texels[i] = tex.texels[i - 1];
        continue;
      }
      auto it = converted.find(w);
      if (it == converted.end()) {
        const Spectrum s = rgbToSpectrum(Rgb8{redOf(w), greenOf(w), blueOf(w)}, options.phosphors);
        std::array<double, 3> three{};
        for (int k = 0; k < 3; ++k) three[static_cast<std::size_t>(k)] = s[Texture::kSamples[k]];
        it = converted.emplace(w, three).first;
      }
      tex.texels[i] = it->second;
    }
    return tex;
  };
  // The map `key` names, loaded by `load` only the first time.
  auto once = [&](const std::string& key, auto&& load) {
    const auto found = loaded.find(key);
    if (found != loaded.end()) return found->second;
    scene.textures.push_back(load());
    return loaded[key] = static_cast<int>(scene.textures.size()) - 1;
  };
  // CGL-D41: supplied maps, the path as written (relative to the scene's
  // directory), then the base name in the scene's directory, its textures/
  // and each texture directory the user names. CGL-D62: nothing outside
  // those directories is opened (an absolute path, a "..", a symbolic link
  // out of them): a scene cannot make prime read, render or quote any other
  // file of the machine.
  for (const auto& supplied : options.textures) {
    const std::string& name = supplied.first;
    if (name == base || name == rec.texture)
      return once("(supplied) " + name,
                  [&] { return convert(supplied.second, "(supplied) " + name); });
  }
  namespace fs = std::filesystem;
  const fs::path sceneDir = fs::path(scenePath).parent_path();
  struct Candidate {
    fs::path path, root;  // the file, and the directory it must stay in
  };
  std::vector<Candidate> candidates;
  const fs::path written = fs::path(rec.texture).lexically_normal();
  if (written.is_relative() && !written.empty() && *written.begin() != "..")
    candidates.push_back({sceneDir / written, sceneDir});
  const bool plain = !base.empty() && base != "." && base != "..";
  const auto byBase = [&](const fs::path& dir) {
    if (!plain) return;
    candidates.push_back({dir / base, dir});
    candidates.push_back({dir / (base + ".rle"), dir});
  };
  byBase(sceneDir);
  byBase(sceneDir / "textures");
  for (const std::string& dir : options.textureDirs) byBase(fs::path(dir));
  for (const Candidate& c : candidates) {
    std::error_code ec;
    if (!fs::is_regular_file(c.path, ec)) continue;
    // Through symbolic links too: the file itself must be inside its root.
    const fs::path real = fs::weakly_canonical(c.path, ec);
    const fs::path root = fs::weakly_canonical(c.root.empty() ? fs::path(".") : c.root, ec);
    const fs::path rel = real.lexically_relative(root);
    if (ec || rel.empty() || *rel.begin() == "..")
      throw io::InputError(rec.textureWhere.file.empty() ? rec.where : rec.textureWhere, "texture",
                           "a texture map inside the scene's directory or a --textures "
                           "directory (CGL-D62)",
                           "'" + rec.texture + "', which " + c.path.string() +
                               " leads outside it (a symbolic link)");
    return once(real.string(),
                [&] { return convert(readRleFile(c.path.string()), c.path.string()); });
  }
  std::vector<std::string> looked;  // each place once, in the order tried
  for (const Candidate& c : candidates)
    if (std::find(looked.begin(), looked.end(), c.path.string()) == looked.end())
      looked.push_back(c.path.string());
  std::string places;
  for (const std::string& p : looked) places += (places.empty() ? "" : ", ") + p;
  // A copy whose names changed case (a DOS disk's TEXTURES/CHECKER.RLE):
  // CGL's names are case-sensitive, as on the VAX; the message says so.
  std::string otherCase;
  for (const Candidate& c : candidates) {
    if (!otherCase.empty()) break;
    fs::path at = c.root.empty() ? fs::path(".") : c.root;
    bool found = true;
    const fs::path rel = c.root.empty() ? c.path : c.path.lexically_relative(c.root);
    for (const fs::path& part : rel) {
      std::error_code ec;
      fs::path match;
      for (fs::directory_iterator d(at, ec), stop; !ec && d != stop; d.increment(ec))
        if (sameIgnoringCase(d->path().filename().string(), part.string())) match = d->path();
      if (match.empty()) {
        found = false;
        break;
      }
      at = match;
    }
    if (found) otherCase = at.string();
  }
  const bool outside = !(written.is_relative() && !written.empty() && *written.begin() != "..");
  throw io::InputError(
      rec.textureWhere.file.empty() ? rec.where : rec.textureWhere, "texture",
      "a run-length-encoded texture map",
      "no file for '" + rec.texture + "'" +
          (outside ? " (the path as written leads outside the scene's directory "
                     "and is not opened, CGL-D62)"
                   : "") +
          (places.empty() ? "" : "; looked in " + places) +
          (otherCase.empty() ? ""
                             : "; " + otherCase +
                                   " differs only in case (CGL's names are case-sensitive: "
                                   "rename it, or write the name as it is)") +
          (options.textureDirs.empty()
               ? " (prime's --textures DIR looks for the base name in DIR too)"
               : ""));
}

}  // namespace

Scene buildScene(const SceneFile& file, const BuildOptions& options) {
  Scene scene;
  scene.path = file.path;
  scene.camera = cameraOf(file.display, file.path);

  // Surfaces (section 9.4), with their textures (section 10).
  int lastTexture = -1;
  std::map<std::string, int> loadedTextures;  // by the file's real path
  for (std::size_t i = 0; i < file.surfaces.size(); ++i) {
    const SurfaceRecord& rec = file.surfaces[i];
    Surface s;
    s.model = rec.model;
    s.kr = rec.reflect;
    s.kt = rec.refract;
    s.index = rec.index;
    s.kd = rec.diffuse;
    s.ks = rec.specular;
    s.e = rec.exponent;
    s.colour = rec.colour;
    s.umod = rec.umod;
    s.vmod = rec.vmod;
    s.number = static_cast<int>(i + 1);
    if (rec.model == ShadingModel::Cook) {  // section 9.9 (CGL-D42 no longer refuses it)
      s.m = rec.m;
      s.fresnel = rec.fresnel;
      if (s.fresnel.size() != static_cast<std::size_t>(kFresnelAngles))
        throw io::InputError(rec.where, "fresnel colour-vectors",
                             std::to_string(kFresnelAngles) + " colour-vectors",
                             std::to_string(s.fresnel.size()));
    }
    if (rec.textured) {
      if (rec.textureLast) {
        // Appendix 1 section 8: `last` is the previous textured surface's map.
        if (lastTexture < 0)
          throw io::InputError(rec.where, "texture", "a textured surface before `last`",
                               "`last` on the first textured surface");
        s.texture = lastTexture;
      } else {
        s.texture = loadTexture(rec, file.path, options, scene, loadedTextures);
      }
      lastTexture = s.texture;
    }
    scene.surfaces.push_back(s);
  }

  // Lights (section 9.3): an infinity light's direction is normalised.
  for (const LightRecord& rec : file.lights) {
    Light l;
    l.inScene = rec.kind == LightKind::InScene;
    if (l.inScene) {
      l.xyz = rec.xyz;
    } else {
      if (!(length(rec.xyz) > 0.0))
        throw io::InputError(rec.where, "direction", "a non-zero direction to the light", "0 0 0");
      l.xyz = normalized(rec.xyz);
    }
    l.dw = rec.dw;
    l.intensity = rec.colour;
    for (int k = 0; k < kSpectrumSamples; ++k) l.intensityDw[k] = rec.colour[k] * rec.dw;
    scene.lights.push_back(l);
  }

  // Ambience (section 9.6): k_a pi I_a as one colour-vector.
  for (int k = 0; k < kSpectrumSamples; ++k)
    scene.ambient[k] = file.ambience.ka * std::numbers::pi * file.ambience.colour[k];

  // The object list (sections 1.2 and 7.2).
  std::vector<Item> items;
  if (file.numbers.root != 0) {
    Preprocessor pre(file, options, scene);
    pre.process(file.numbers.root, identity4(), items);
  }
  std::reverse(items.begin(), items.end());  // prepended: the first processed is last
  flatten(items, scene.objects);
  return scene;
}

std::string describeObjects(const Scene& scene) {
  std::ostringstream out;
  std::vector<int> ends;  // the skip of every open box
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    while (!ends.empty() && static_cast<int>(i) >= ends.back()) ends.pop_back();
    const Object& o = scene.objects[i];
    out << std::string(2 * ends.size(), ' ') << i << ": " << kindName(o.kind) << " (node " << o.node
        << ")";
    if (o.kind == ObjectKind::Box)
      out << ", " << (o.skip - static_cast<int>(i) - 1) << " object nodes inside";
    else
      out << ", surface " << (o.surface + 1) << (o.opaque ? "" : ", transparent");
    if (o.kind == ObjectKind::Fractal) {
      const FractalSurface& f = scene.fractals[static_cast<std::size_t>(o.fractal)];
      out << ", " << f.divisions << " divisions, " << f.facets.size() << " facets, "
          << f.boxes.size() << " boxes, " << f.bytes() << " bytes";
    }
    out << "\n";
    if (o.kind == ObjectKind::Box) ends.push_back(o.skip);
  }
  return out.str();
}

}  // namespace prime::cgl
