#include "src/prime/pov/pov_export.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "legacy_io/common/output_file.h"
#include "legacy_io/prime/records.h"

namespace prime {

namespace fs = std::filesystem;

std::array<double, 12> povMatrix(const Matrix4& m) {
  std::array<double, 12> out{};
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 3; ++col) out[static_cast<std::size_t>(row * 3 + col)] = m[row][col];
  return out;
}

PovCamera povCamera(const CameraSettings& s) {
  const ListingCamera cam(s);  // validates the viewport, as prime trace does
  const double across = cam.numPixAcross(), down = cam.numPixDown();
  const double columns = cam.columns(), rows = cam.rows();
  PovCamera c;
  c.width = cam.columns();
  c.height = cam.rows();
  c.location = s.eye;
  for (int i = 0; i < 3; ++i) {
    const double a = s.windowRight[i] - s.windowLeft[i];  // the window's top edge, left to right
    const double d = -s.windowLeft[i];                    // its left edge, top to bottom (K23)
    // POV-Ray's ray for pixel (x, y) of a W x H image is
    //   direction + ((x + 0.5)/W - 0.5) * right + (0.5 - (y + 0.5)/H) * up,
    // so the listing's first and last rays (the window's corners) fall on pixel
    // centres when right spans W/(W-1) of the window's width, up H/(H-1) of its
    // height, and direction points at the window's centre.
    c.right[i] = a * columns / across;
    c.up[i] = -d * rows / down;
    c.direction[i] = s.windowLeft[i] + 0.5 * a + 0.5 * d - s.eye[i];
  }
  return c;
}

namespace {

bool affine(const Matrix4& m) {
  return m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
}

double finiteOr(double v, double fallback) {
  return std::isfinite(v) ? v : fallback;
}

std::uint8_t toByte(double v) {
  return channelByte(v);
}

// The unit primitive of type `t` in POV-Ray terms, without its closing brace.
std::string shapeOpen(io::PrimType t) {
  switch (t) {
    case io::PrimType::Sphere:
      return "sphere { <0, 0, 0>, 1";
    case io::PrimType::Cube:
      return "box { <0, 0, 0>, <1, 1, 1>";
    case io::PrimType::Cylinder:
      return "cylinder { <0, 0, 0>, <0, 0, 1>, 1";
    case io::PrimType::Cone:
      return "cone { <0, 0, 0>, 0, <0, 0, 1>, 1";
    case io::PrimType::Pyramid: {
      // Base y = 0 (x, z in 0..1), apex (0.5, 1, 0.5): five half-spaces, unit
      // normals pointing out. POV-Ray has no pyramid; this solid works in CSG.
      const double a = 1.0 / std::sqrt(5.0), b = 2.0 / std::sqrt(5.0);
      const std::string A = povNumber(a), B = povNumber(b);
      return "intersection {  // pyramid\n"
             "  plane { <0, -1, 0>, 0 }\n"
             "  plane { <0, " +
             A + ", -" + B +
             ">, 0 }  // front, z = y/2\n"
             "  plane { <" +
             B + ", " + A + ", 0>, " + B +
             " }  // right, x = 1 - y/2\n"
             "  plane { <0, " +
             A + ", " + B + ">, " + B +
             " }  // back, z = 1 - y/2\n"
             "  plane { <-" +
             B + ", " + A +
             ", 0>, 0 }  // left, x = y/2\n"
             "  bounded_by { box { <0, 0, 0>, <1, 1, 1> } }";
    }
  }
  return {};  // not reached: every PrimType is named above
}

std::string indentLines(const std::string& text, int indent) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line =
        text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    out += pad + line + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

struct ObjectLook {
  Vec3 diffuse{};                // D: the colour POV-Ray lights (ambient and diffuse)
  double transmit = 0;           // kST = 1 - kDT, clamped to 0..1
  std::string finish, interior;  // declared names ("" when not declared)
  bool transparent = false;
};

class Exporter {
 public:
  Exporter(const Scene& scene, const PovExportOptions& o) : scene_(scene), o_(o) {}

  PovExport run() {
    const PovCamera cam = povCamera(o_.camera);
    result_.width = cam.width;
    result_.height = cam.height;
    header(cam);
    for (const SceneObject& obj : scene_.objects) object(obj);
    result_.pov = out_.str();
    return std::move(result_);
  }

 private:
  void header(const PovCamera& cam) {
    const int level = std::clamp(o_.maxDepth + 1, 1, 256);
    out_ << "// " << (scene_.name.empty() ? std::string("PRIME scene") : scene_.name)
         << ", exported by `prime export-pov` as POV-Ray 3.7 scene language.\n"
         << "// Render at the listing's size, one ray per pixel:\n"
         << "//   povray +I<this file> +W" << cam.width << " +H" << cam.height
         << " -A File_Gamma=1.0 +FN\n"
         << "// from this file's directory (the texture maps are next to it).\n"
         << "// Geometry, CSG, camera rays, lights and recursion depth are exact; texture\n"
         << "// mapping is close; the finish only approximates Hall's model "
            "(docs/prime/pov-export.md).\n"
         << "#version 3.7;\n\n"
         << "global_settings {\n"
         << "  // PRIME's MaxDepth " << o_.maxDepth
         << " counts reflections after the primary ray; POV-Ray counts the primary ray too.\n"
         << "  max_trace_level " << level << "\n"
         << "  adc_bailout 0  // no adaptive depth cut-off, like the listing\n"
         << "  assumed_gamma 1\n"
         << "  ambient_light rgb " << povVector(scene_.ambient) << "  // IA of light/light.txt\n"
         << "}\n\n";
    out_ << "// The listing's camera: eye " << povVector(o_.camera.eye) << ", window top-left "
         << povVector(o_.camera.windowLeft) << ", top-right " << povVector(o_.camera.windowRight)
         << ",\n// bottom-left at the origin (K23); ray (row, column) of the listing goes through "
            "the\n"
         << "// centre of pixel (row, column). `right` follows the window's top edge, so world +x\n"
         << "// is to the right as on the 8514/A screen (no mirror despite POV-Ray's "
            "left-handedness).\n"
         << "camera {\n"
         << "  perspective\n"
         << "  location " << povVector(cam.location) << "\n"
         << "  direction " << povVector(cam.direction) << "\n"
         << "  right " << povVector(cam.right) << "\n"
         << "  up " << povVector(cam.up) << "\n"
         << "}\n\n"
         << "background { rgb " << povVector(scene_.background) << " }\n\n";
    if (!o_.shadows) {
      out_ << "// Point lights without distance fall-off; shadowless: the listing casts no shadow "
              "rays (K9).\n";
      for (const auto& l : scene_.lights)
        out_ << "light_source { " << povVector(l.pt) << " color rgb " << povVector(l.rgb)
             << " shadowless }\n";
    } else if (!(o_.lightRadius > 0.0)) {
      out_ << "// Point lights without distance fall-off, casting shadows (the thesis profile, "
              "T2).\n";
      for (const auto& l : scene_.lights)
        out_ << "light_source { " << povVector(l.pt) << " color rgb " << povVector(l.rgb) << " }\n";
    } else {
      // A disc of the radius facing the point lit (the thesis profile's
      // distributed light, T10): POV-Ray's circular, oriented area light.
      const double d = 2.0 * o_.lightRadius;
      out_ << "// Area lights: discs of radius " << o_.lightRadius
           << " facing the point lit, casting soft shadows (the thesis profile, T10).\n";
      for (const auto& l : scene_.lights)
        out_ << "light_source { " << povVector(l.pt) << " color rgb " << povVector(l.rgb)
             << " area_light <" << d << ", 0, 0>, <0, 0, " << d
             << ">, 9, 9 adaptive 1 jitter circular orient }\n";
    }
    out_ << "\n";
  }

  ObjectLook look(const SceneObject& obj) {
    const io::Hue& h = obj.hue;
    ObjectLook L;
    const double kDR = finiteOr(h.kDR, 0.0), kDT = finiteOr(h.kDT, 0.0);
    const double kSR = 1.0 - kDR, kST = 1.0 - kDT;
    for (int c = 0; c < 3; ++c) {
      const double fDR = finiteOr(h.fDR[c], 0.0);
      L.diffuse[c] = std::max(0.0, kDR * fDR + kDT * (1.0 - fDR));
    }
    L.transmit = std::clamp(kST, 0.0, 1.0);
    L.transparent = L.transmit > 0.0;
    // F0 of the reflected term: the mean texel of the maps this object uses.
    const Vec3 f0 = meanMapColour(obj);
    const std::string n = std::to_string(obj.number);
    out_ << "// Object " << n << " (obj/O" << n << "): Hall hue kDR " << povNumber(h.kDR) << " kDT "
         << povNumber(h.kDT) << " fDR " << povVector({h.fDR[0], h.fDR[1], h.fDR[2]}) << " tT "
         << povNumber(h.tT) << " kRH " << povNumber(h.kRH) << " kTH " << povNumber(h.kTH)
         << " indx " << povNumber(h.indx) << ".\n"
         << "// Pigment: D = kDR*fDR + kDT*(1 - fDR) plus the texture map, transmit kST = 1 - "
            "kDT.\n";
    L.finish = "PrimeFinish" + n;
    out_ << "#declare " << L.finish << " = finish {\n"
         << "  ambient 1  // x pigment x IA: Hall's IA*(kDR*fDR + kDT*fDT)\n"
         << "  diffuse 1  // x pigment x light x cos: Hall's lit diffuse terms\n";
    if (kSR > 0.0 && h.kRH > 0.0)
      out_ << "  specular " << povNumber(kSR) << " roughness "
           << povNumber(std::clamp(1.0 / h.kRH, 1e-4, 1.0)) << " metallic  // kSR, (N.H)^kRH\n";
    if (kSR > 0.0) {
      Vec3 lo{}, hi{};
      for (int c = 0; c < 3; ++c) {
        hi[c] = std::max(0.0, kSR * scene_.ambient[c]);
        lo[c] = std::max(0.0, hi[c] * f0[c]);
      }
      out_ << "  // kSR * IA * FSR: F0 (the map's mean colour) facing, 1 at grazing, linear in 1 - "
              "cos\n"
           << "  reflection { rgb " << povVector(lo) << ", rgb " << povVector(hi)
           << " falloff 1 }\n";
    }
    out_ << "}\n";
    if (L.transparent) {
      L.interior = "PrimeInterior" + n;
      out_ << "#declare " << L.interior << " = interior {";
      if (std::isfinite(h.indx) && h.indx > 0.0) out_ << " ior " << povNumber(h.indx);
      if (std::isfinite(h.tT) && h.tT > 0.0 && h.tT < 1.0)
        out_ << " fade_distance " << povNumber(-1.0 / std::log(h.tT))
             << " fade_power 1001";  // exp(-d / fade_distance) = tT^d
      out_ << " }\n";
    }
    return L;
  }

  Vec3 meanMapColour(const SceneObject& obj) const {
    Vec3 sum{};
    int n = 0;
    for (const CsgEntry& e : obj.entries) {
      if (e.op != 'P' || e.l < 0 || e.l >= static_cast<int>(scene_.prims.size())) continue;
      if (const SceneTexture* t = scene_.map(scene_.prims[e.l].map[0][io::kOut])) {
        for (int c = 0; c < 3; ++c) {
          const auto& ch = t->channel[c];
          double s = 0.0;
          for (double v : ch) s += finiteOr(v, 0.0);
          sum[c] += ch.empty() ? 0.0 : s / static_cast<double>(ch.size());
        }
        ++n;
      }
    }
    if (n > 0)
      for (double& v : sum) v /= n;
    return sum;
  }

  void object(const SceneObject& obj) {
    const ObjectLook L = look(obj);
    const Tree tree = treeOf(obj);
    // M32: an operator entry the tree uses more than once is written once,
    // as a #declare (one per side it is seen from), before the object; its
    // uses are `object { name }`. Declarations come children first (post-order).
    std::map<std::pair<int, int>, std::string> declared;  // (entry, inside) -> name
    std::vector<std::pair<int, int>> pending, all;
    auto nameOf = [&](int entry, int inside) {
      const auto key = std::make_pair(entry, inside);
      auto it = declared.find(key);
      if (it != declared.end()) return it->second;
      const std::string name = "PrimeO" + std::to_string(obj.number) + "_E" +
                               std::to_string(entry) + (inside ? "_In" : "");
      declared.emplace(key, name);
      pending.push_back(key);
      all.push_back(key);
      return name;
    };
    std::string body = csg(obj, L, tree, 0, 0, nameOf);
    std::map<std::pair<int, int>, std::string> text;
    while (!pending.empty()) {
      const auto [entry, inside] = pending.back();
      pending.pop_back();
      text[{entry, inside}] = csg(obj, L, tree, entry, inside, nameOf);
    }
    std::sort(all.begin(), all.end(), [&](const auto& a, const auto& b) {
      return std::make_pair(tree.rank[static_cast<std::size_t>(a.first)], a.second) <
             std::make_pair(tree.rank[static_cast<std::size_t>(b.first)], b.second);
    });
    for (const auto& key : all)
      out_ << "#declare " << declared[key] << " =  // entry " << key.first << " of object "
           << obj.number << ", used " << tree.refs[static_cast<std::size_t>(key.first)] << " times"
           << (key.second ? " (seen from inside)" : "") << "\n"
           << text[key];
    if (obj.boundPrim >= 0 && obj.boundPrim < static_cast<int>(scene_.prims.size())) {
      const ScenePrim& b = scene_.prims[obj.boundPrim];
      std::string bound =
          "bounded_by {  // the object's bounding volume, prim " + std::to_string(obj.boundPrim) +
          "\n" +
          indentLines(shapeOpen(b.type) + "\n  " + povMatrix(povMatrix(b.transform)) + "\n}", 2) +
          "}\n";
      // Insert before the root's closing brace (a shared root cannot be: the
      // root has no parent).
      const std::size_t close = body.rfind('}');
      body = body.substr(0, close) + indentLines(bound, 2) + body.substr(close);
    }
    out_ << body << "\n";
  }

  // The object's tree checked (entries in range, no cycle, known operators),
  // with each entry's position in post-order and its number of uses.
  struct Tree {
    std::vector<int> rank, refs;
  };
  Tree treeOf(const SceneObject& obj) const {
    const int n = static_cast<int>(obj.entries.size());
    auto fail = [&](const std::string& what) {
      throw std::invalid_argument("object " + std::to_string(obj.number) + ": " + what);
    };
    if (n == 0) fail("CSG entry 0 out of range");
    Tree t{std::vector<int>(static_cast<std::size_t>(n), -1),
           std::vector<int>(static_cast<std::size_t>(n), 0)};
    std::vector<char> onPath(static_cast<std::size_t>(n), 0);
    std::vector<std::pair<int, int>> stack{{0, 0}};
    int next = 0;
    onPath[0] = 1;
    while (!stack.empty()) {
      auto& [i, child] = stack.back();
      const CsgEntry& e = obj.entries[static_cast<std::size_t>(i)];
      if (e.op != 'P' && e.op != '+' && e.op != '-' && e.op != '&')
        fail("CSG entry " + std::to_string(i) + " has operator '" + e.op + "'");
      if (e.op != 'P' && child < 2) {
        const int c = child++ == 0 ? e.l : e.r;
        if (c < 0 || c >= n) fail("CSG entry " + std::to_string(c) + " out of range");
        if (onPath[static_cast<std::size_t>(c)]) fail("cyclic CSG tree");
        if (t.refs[static_cast<std::size_t>(c)]++ == 0) {
          onPath[static_cast<std::size_t>(c)] = 1;
          stack.emplace_back(c, 0);  // (`i`, `child` are not used after)
        }
        continue;
      }
      t.rank[static_cast<std::size_t>(i)] = next++;
      onPath[static_cast<std::size_t>(i)] = 0;
      stack.pop_back();
    }
    return t;
  }

  // The text of entry `root` of the object's CSG tree, without recursion
  // (M31); `inside` is 1 when an odd number of '-' right operands lie on the
  // path from the object's root (the primitive shows its inside). A shared
  // operator entry below `root` becomes `object { nameOf(entry, inside) }`.
  // Indentation stops growing after kMaxIndent levels, so a deep chain's
  // text stays linear in its length.
  template <class NameOf>
  std::string csg(const SceneObject& obj, const ObjectLook& L, const Tree& tree, int root,
                  int inside, NameOf&& nameOf) {
    constexpr int kMaxIndent = 32;
    struct Item {
      int entry, inside, depth, stage;
    };
    std::string s;
    std::vector<Item> stack{{root, inside, 0, 0}};
    while (!stack.empty()) {
      Item& it = stack.back();
      const CsgEntry& e = obj.entries[static_cast<std::size_t>(it.entry)];
      const int indent = 2 * std::min(it.depth, kMaxIndent);
      const std::string tag = "  // entry " + std::to_string(it.entry);
      if (e.op != 'P' && it.entry != root && tree.refs[static_cast<std::size_t>(it.entry)] > 1) {
        s += std::string(static_cast<std::size_t>(indent), ' ') + "object { " +
             nameOf(it.entry, it.inside) + " }" + tag + "\n";
        stack.pop_back();
        continue;
      }
      if (e.op == 'P') {
        s += indentLines(primitive(e.l, L, it.inside == 1, tag), indent);
        stack.pop_back();
        continue;
      }
      const Item item = it;
      if (item.stage == 0) {
        // Roth's union keeps only the outer boundary: merge for see-through objects.
        const char* op = e.op == '+'   ? (L.transparent ? "merge" : "union")
                         : e.op == '-' ? "difference"
                                       : "intersection";
        s += std::string(static_cast<std::size_t>(indent), ' ') + op + " {" + tag + " " + e.op +
             " " + std::to_string(e.l) + " " + std::to_string(e.r) + "\n";
        it.stage = 1;
        stack.push_back({e.l, item.inside, item.depth + 1, 0});
      } else if (item.stage == 1) {
        it.stage = 2;
        stack.push_back({e.r, e.op == '-' ? 1 - item.inside : item.inside, item.depth + 1, 0});
      } else {
        s += std::string(static_cast<std::size_t>(indent), ' ') + "}\n";
        stack.pop_back();
      }
    }
    return s;
  }

  std::string primitive(int p, const ObjectLook& L, bool inside, const std::string& tag) {
    if (p < 0 || p >= static_cast<int>(scene_.prims.size()))
      throw std::invalid_argument("primitive " + std::to_string(p) + " does not exist");
    const ScenePrim& prim = scene_.prims[p];
    const int outMap = prim.map[0][io::kOut], inMap = prim.map[0][io::kIn];
    std::string s = shapeOpen(prim.type) + tag + ": prim " + std::to_string(p) + ", maps " +
                    std::to_string(outMap) + " out / " + std::to_string(inMap) + " in\n";
    if (prim.type == io::PrimType::Cube) {
      // Boxes carry every face's map in one uv_mapping atlas, so each face
      // gets its own map and PRIME's (u, v) (GetUVCube).
      std::array<int, 6> front{}, back{};
      for (std::size_t f = 0; f < 6; ++f) {
        front[f] = prim.map[f][inside ? io::kIn : io::kOut];
        back[f] = prim.map[f][inside ? io::kOut : io::kIn];
      }
      s += "  texture { " + boxPigment(front, L) + " finish { " + L.finish + " } }\n";
      if (back != front)
        s += "  interior_texture { " + boxPigment(back, L) + " finish { " + L.finish + " } }\n";
      return leafEnd(s, prim, L);
    }
    for (int surface = 1; surface < io::surfaceCount(prim.type); ++surface)
      if (prim.map[surface][io::kOut] != outMap || prim.map[surface][io::kIn] != inMap) {
        s += "  // surfaces use different maps; POV-Ray gets surface 0's on every face\n";
        break;
      }
    // A subtracted primitive shows its inside surface, which PRIME shades with
    // the In map (surfType In); POV-Ray shades it with `texture`.
    const int front = inside ? inMap : outMap, back = inside ? outMap : inMap;
    s += "  texture { " + pigment(front, prim.type, L) + " finish { " + L.finish + " } }\n";
    if (back != front)
      s += "  interior_texture { " + pigment(back, prim.type, L) + " finish { " + L.finish +
           " } }\n";
    return leafEnd(s, prim, L);
  }

  std::string leafEnd(std::string s, const ScenePrim& prim, const ObjectLook& L) {
    if (!L.interior.empty()) s += "  interior { " + L.interior + " }\n";
    s += "  " + povMatrix(povMatrix(prim.transform)) + "\n";
    if (!affine(prim.transform))
      s += "  // the matrix's fourth column is not (0, 0, 0, 1); POV-Ray ignores it\n";
    return s + "}\n";
  }

  // The pigment of map `mapNum` on a primitive of type `type`: the object's
  // diffuse colour D plus the map, with transmit kST.
  std::string pigment(int mapNum, io::PrimType type, const ObjectLook& L) {
    const std::string t = povNumber(L.transmit);
    const SceneTexture* tex = scene_.map(mapNum);
    if (tex == nullptr || tex->constant) {
      Vec3 c = L.diffuse;
      if (tex != nullptr)
        for (int k = 0; k < 3; ++k)
          if (!tex->channel[k].empty()) c[k] += std::max(0.0, finiteOr(tex->channel[k][0], 0.0));
      return "pigment { rgbt <" + povNumber(c[0]) + ", " + povNumber(c[1]) + ", " +
             povNumber(c[2]) + ", " + t + "> }" +
             (tex == nullptr ? " /* map " + std::to_string(mapNum) + " missing */" : "");
    }
    // PRIME's (u, v) against POV-Ray's image coordinates (v = 0 is the image's
    // bottom row, so the files are written with texel row 0 at the bottom):
    //   sphere   u = longitude/pi about z from +x to +y (the map twice round),
    //            v = 0 at z = -1: spherical map_type 1 after swapping y and z,
    //            of an image holding the map twice side by side (exact);
    //   cylinder and cone bodies: u = longitude/2pi about z, v = z: cylindrical
    //            map_type 2 after swapping y and z (exact; caps approximate);
    //   pyramid: planar map_type 0 with u = x, v = 1 - y, a projection (its
    //            faces' bilinear GetUVPoly has no POV-Ray equivalent);
    //   box:     see boxPigment.
    std::string mapType, transform;
    const bool sphere = type == io::PrimType::Sphere;
    if (sphere || type == io::PrimType::Cylinder || type == io::PrimType::Cone) {
      mapType = sphere ? "1" : "2";
      transform = "matrix <1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0>";
    } else {
      mapType = "0";
      transform = "matrix <1, 0, 0, 0, -1, 0, 0, 0, 1, 0, 1, 0>";
    }
    const std::string image = "image_map { png \"" + imageFile(mapNum, *tex, sphere) +
                              "\" gamma 1 map_type " + mapType + " transmit all " + t + " }";
    if (L.diffuse == Vec3{0.0, 0.0, 0.0}) return "pigment { " + image + " " + transform + " }";
    // POV-Ray pigments multiply; `average` with these weights adds:
    // (1 * 1001 D + 1000 * map) / 1001 = D + 0.999 map.
    const Vec3 d = L.diffuse * 1001.0;
    return "pigment { average pigment_map { [1 rgbt <" + povNumber(d[0]) + ", " + povNumber(d[1]) +
           ", " + povNumber(d[2]) + ", " + t + ">] [1000 " + image + "] } " + transform + " }";
  }

  // The six faces' maps (by PRIME surface number) in one image laid out as
  // POV-Ray 3.7's box uv_mapping expects (Box::UVCoord): a cross of 4 x 3
  // cells, u along the columns, v up the rows. Exact: on every face POV-Ray's
  // cell coordinates (s, t) and GetUVCube's (u, v) differ only in direction.
  std::string boxPigment(const std::array<int, 6>& faceMaps, const ObjectLook& L) {
    const SceneTexture* first = scene_.map(faceMaps[0]);
    if (std::all_of(faceMaps.begin(), faceMaps.end(), [&](int m) { return m == faceMaps[0]; }) &&
        (first == nullptr || first->constant))
      return pigment(faceMaps[0], io::PrimType::Cube, L);
    const std::string t = povNumber(L.transmit);
    const std::string image =
        "image_map { png \"" + boxAtlas(faceMaps) + "\" gamma 1 transmit all " + t + " }";
    if (L.diffuse == Vec3{0.0, 0.0, 0.0}) return "pigment { uv_mapping " + image + " }";
    const Vec3 d = L.diffuse * 1001.0;
    return "pigment { uv_mapping average pigment_map { [1 rgbt <" + povNumber(d[0]) + ", " +
           povNumber(d[1]) + ", " + povNumber(d[2]) + ", " + t + ">] [1000 " + image + "] } }";
  }

  std::string boxAtlas(const std::array<int, 6>& faceMaps) {
    if (auto it = atlases_.find(faceMaps); it != atlases_.end()) return it->second;
    int cw = 1, ch = 1;
    for (int m : faceMaps)
      if (const SceneTexture* tex = scene_.map(m)) {
        cw = std::max(cw, tex->uScale);
        ch = std::max(ch, tex->vScale);
      }
    struct Cell {
      int surface, col, row;  // PRIME surface; POV-Ray cell, row 0 at the bottom
      bool flipU, flipV;      // u = 1 - s, v = 1 - t
    };
    static constexpr Cell kCells[6] = {
        {3, 0, 1, true, true},    // x = 0: s = z, t = y;      u = 1 - z, v = 1 - y
        {1, 2, 1, true, true},    // x = 1: s = 1 - z, t = y;  u = z, v = 1 - y
        {5, 1, 0, false, false},  // y = 0: s = x, t = z;      u = x, v = z
        {4, 1, 2, false, false},  // y = 1: s = x, t = 1 - z;  u = x, v = 1 - z
        {0, 3, 1, true, true},    // z = 0: s = 1 - x, t = y;  u = x, v = 1 - y
        {2, 1, 1, true, true},    // z = 1: s = x, t = y;      u = 1 - x, v = 1 - y
    };
    Image8 img;
    img.width = 4 * cw;
    img.height = 3 * ch;
    img.rgb.assign(static_cast<std::size_t>(img.width) * img.height * 3, 0);
    for (const Cell& cell : kCells) {
      const SceneTexture* tex = scene_.map(faceMaps[static_cast<std::size_t>(cell.surface)]);
      if (tex == nullptr) continue;
      for (int j = 0; j < ch; ++j)
        for (int i = 0; i < cw; ++i) {
          const double s = (i + 0.5) / cw, t = (j + 0.5) / ch;
          const double u = cell.flipU ? 1.0 - s : s, v = cell.flipV ? 1.0 - t : t;
          const int tu = std::min(tex->uScale - 1, static_cast<int>(u * tex->uScale));
          const int tv = std::min(tex->vScale - 1, static_cast<int>(v * tex->vScale));
          const std::size_t texel =
              tex->constant ? 0
                            : static_cast<std::size_t>(tu) + static_cast<std::size_t>(tex->uScale) *
                                                                 static_cast<std::size_t>(tv);
          const int x = cell.col * cw + i, yTop = img.height - 1 - (cell.row * ch + j);
          for (std::size_t c = 0; c < 3; ++c) {
            const auto& chn = tex->channel[c];
            img.rgb[(static_cast<std::size_t>(yTop) * img.width + x) * 3 + c] =
                toByte(texel < chn.size() ? chn[texel] : 0.0);
          }
        }
    }
    const std::string name = o_.imageStem + "_box" + std::to_string(atlases_.size() + 1) + ".png";
    result_.images.push_back({name, std::move(img)});
    atlases_.emplace(faceMaps, name);
    return name;
  }

  std::string imageFile(int mapNum, const SceneTexture& tex, bool twice) {
    const auto key = std::make_pair(mapNum, twice);
    if (auto it = files_.find(key); it != files_.end()) return it->second;
    const std::string name =
        o_.imageStem + "_map" + std::to_string(mapNum) + (twice ? "_sphere" : "") + ".png";
    Image8 img;
    img.width = tex.uScale * (twice ? 2 : 1);
    img.height = tex.vScale;
    img.rgb.assign(static_cast<std::size_t>(img.width) * img.height * 3, 0);
    for (int row = 0; row < img.height; ++row)
      for (int col = 0; col < img.width; ++col) {
        const std::size_t texel =
            static_cast<std::size_t>(col % tex.uScale) +
            static_cast<std::size_t>(tex.uScale) * static_cast<std::size_t>(img.height - 1 - row);
        for (int c = 0; c < 3; ++c) {
          const auto& ch = tex.channel[c];
          const double v = texel < ch.size() ? ch[texel] : 0.0;  // a short map reads 0.0 (E51)
          img.rgb[(static_cast<std::size_t>(row) * img.width + col) * 3 + c] = toByte(v);
        }
      }
    result_.images.push_back({name, std::move(img)});
    files_.emplace(key, name);
    return name;
  }

  const Scene& scene_;
  PovExportOptions o_;
  std::ostringstream out_;
  PovExport result_;
  std::map<std::pair<int, bool>, std::string> files_;
  std::map<std::array<int, 6>, std::string> atlases_;
};

}  // namespace

PovExport exportPov(const Scene& scene, const PovExportOptions& options) {
  return Exporter(scene, options).run();
}

void writePovExport(const PovExport& exported, const fs::path& povFile) {
  // All or none: a full disk at the last texture leaves no earlier one behind.
  const fs::path dir = povFile.parent_path();
  io::OutputSet files;
  for (const PovImage& img : exported.images)
    writePng(files.add((dir / img.fileName).string()), img.image);
  files.add(povFile.string()).write(exported.pov);
  files.commit();
}

}  // namespace prime
