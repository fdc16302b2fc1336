#include "src/prime/scene/scene_loader.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/obj_list.h"
#include "legacy_io/prime/prim_file.h"
#include "src/prime/geom/csg_program_1991.h"

namespace prime {

namespace fs = std::filesystem;
using io::InputError;

namespace {

// What a primitive number may be, with PrimFile's size: "a primitive number
// 0..4 (PrimFile has 5)", or that an empty PrimFile has none.
std::string primitiveNumbers(std::size_t count) {
  if (count == 0) return "a primitive number (PrimFile has no primitives)";
  return "a primitive number 0.." + std::to_string(count - 1) + " (PrimFile has " +
         std::to_string(count) + ")";
}

// M33: the text parsers refuse NaN and infinities, so a binary database
// holding one was not written by them: corrupt. A non-finite matrix element,
// hue or texel is refused where it is read, naming the record, the field and
// its byte, instead of tracing garbage with exit 0.
void checkFinite(double v, const std::string& file, std::uint64_t at, const std::string& field) {
  if (std::isfinite(v)) return;
  throw InputError({file, std::nullopt, at}, field,
                   "a finite number (the text inputs refuse NaN and infinities: the database is "
                   "corrupt; rebuild it with prime model)",
                   std::isnan(v) ? "NaN"
                   : v > 0       ? "+infinity"
                                 : "-infinity");
}

// Byte offsets of a Hue inside its record (records.h: eight Turbo C doubles).
void checkHue(const io::Hue& h, const std::string& file, std::uint64_t at,
              const std::string& record) {
  checkFinite(h.kDR, file, at + 0, record + " hue kDR");
  checkFinite(h.kDT, file, at + 8, record + " hue kDT");
  for (int c = 0; c < 3; ++c)
    checkFinite(h.fDR[static_cast<std::size_t>(c)], file, at + 16 + 8 * static_cast<unsigned>(c),
                record + " hue fDR[" + std::to_string(c) + "]");
  checkFinite(h.tT, file, at + 40, record + " hue tT");
  checkFinite(h.kRH, file, at + 48, record + " hue kRH");
  checkFinite(h.kTH, file, at + 56, record + " hue kTH");
  checkFinite(h.indx, file, at + 64, record + " hue indx");
}

// The transform and inverse of PrimFile record `n` (the primitive an
// object uses): 16 doubles each, after the type byte (and its pad byte in
// the word-aligned layout).
void checkPrimMatrices(const io::PrimRecord& p, int n, io::PrimLayout layout,
                       const std::string& file) {
  const bool packed = layout == io::PrimLayout::Packed;
  const std::uint64_t record =
      static_cast<std::uint64_t>(n) * (packed ? io::kPrimSizePacked : io::kPrimSizeAligned);
  const std::uint64_t first = record + (packed ? 1 : 2);
  for (int m = 0; m < 2; ++m)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        checkFinite(
            (m == 0 ? p.transform
                    : p.inverse)[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)],
            file, first + 128 * static_cast<unsigned>(m) + 8 * static_cast<unsigned>(4 * i + j),
            "PrimFile record " + std::to_string(n) + (m == 0 ? " transform[" : " inverse[") +
                std::to_string(i) + "][" + std::to_string(j) + "]");
}

std::string primLabel(int n, const ScenePrim& p) {
  return "primitive " + std::to_string(n) + " (" + io::primTypeName(p.type) + ")";
}

// Reads obj/O<n> and checks its CSG tree against the primitive table: every
// primitive it uses must have a type byte that names a type (io::primType).
SceneObject loadObject(const io::SceneDir& dir, int number,
                       const std::vector<io::PrimRecord>& prims, const std::string& listShown) {
  const fs::path path = dir.existingInput("obj", "O" + std::to_string(number),
                                          listShown + " (object " + std::to_string(number) + ")");
  const std::string shown = dir.display(path);
  const io::ObjFile f = io::objFileFromBytes(io::readFileBytes(path.string()), shown);
  SceneObject obj;
  obj.number = number;
  checkHue(f.header.hue, shown, 4, "ObjHeader");  // after numEntries and boundVol
  obj.hue = f.header.hue;
  obj.boundPrim = f.header.boundVol;
  const int n = static_cast<int>(f.entries.size());
  if (n == 0) throw InputError({shown, std::nullopt, 0}, "object has no entries");
  for (int i = 0; i < n; ++i) {
    const auto& e = f.entries[i];
    const std::uint64_t at = io::kObjHeaderSize + static_cast<std::uint64_t>(i) * io::kObjSize;
    const std::string field = "entry " + std::to_string(i);
    switch (e.op()) {
      case '+':
      case '-':
      case '&':
        for (int child : {e.l, e.r})
          if (child < 0 || child >= n)
            throw InputError({shown, std::nullopt, at}, field + " child",
                             "an entry number 0.." + std::to_string(n - 1), std::to_string(child));
        break;
      case 'P':
        if (e.l < 0 || e.l >= static_cast<int>(prims.size()))
          throw InputError({shown, std::nullopt, at}, field + " primitive",
                           primitiveNumbers(prims.size()), std::to_string(e.l));
        if (!io::primType(prims[e.l].type))
          throw InputError({shown, std::nullopt, at}, field + " primitive " + std::to_string(e.l),
                           "a primitive of type S, B, C, N or Y",
                           std::string("type byte ") +
                               std::to_string(static_cast<unsigned char>(prims[e.l].type)) +
                               " (a primitive copied by an O entry? errata K33; try `prime model "
                               "--copy-type-from-source`)");
        break;
      default:
        throw InputError({shown, std::nullopt, at}, field + " opcode", "+, -, & or P",
                         std::string("'") + e.op() + "'");
    }
    obj.entries.push_back({e.op(), e.l, e.r});
  }
  // The tree from entry 0 must not contain itself (CSG() would never return).
  std::vector<int> state(n, 0);
  std::vector<std::pair<int, int>> stack{{0, 0}};
  while (!stack.empty()) {
    auto& [i, phase] = stack.back();
    const auto& e = obj.entries[i];
    const bool op = e.op != 'P';
    if (phase == 0) state[i] = 1;
    if (op && phase < 2) {
      const int child = phase == 0 ? e.l : e.r;
      ++phase;
      if (state[child] == 1)
        throw InputError({shown, std::nullopt, std::nullopt}, "CSG tree", "a tree",
                         "a cycle through entry " + std::to_string(child));
      if (state[child] == 0) stack.push_back({child, 0});
      continue;
    }
    state[i] = 2;
    stack.pop_back();
  }
  if (obj.boundPrim != -1) {
    if (obj.boundPrim < 0 || obj.boundPrim >= static_cast<int>(prims.size()))
      throw InputError({shown, std::nullopt, 2}, "ObjHeader.boundVol",
                       "-1 or " + primitiveNumbers(prims.size()), std::to_string(obj.boundPrim));
    if (!io::primType(prims[obj.boundPrim].type))
      throw InputError(
          {shown, std::nullopt, 2},
          "bounding volume (primitive " + std::to_string(obj.boundPrim) + ")",
          "a primitive type S, B, C, N or Y",
          "type byte " + std::to_string(static_cast<unsigned char>(prims[obj.boundPrim].type)));
  }
  return obj;
}

SceneTexture loadMap(const io::SceneDir& dir, int number) {
  SceneTexture m;
  for (int c = 0; c < 3; ++c) {
    const fs::path path =
        dir.existingInput("map", io::mapFileName(number, c),
                          "map " + std::to_string(number) + ", whose _R file " +
                              dir.display(dir.find("map", io::mapFileName(number, 0))) + " exists");
    const io::MapFile f = io::mapFileFromBytes(io::readFileBytes(path.string()), dir.display(path));
    if (c > 0 && (f.header.uScale != m.uScale || f.header.vScale != m.vScale))
      throw InputError({dir.display(path), std::nullopt, 0}, "MapHeader",
                       "the same size as the _R file (" + std::to_string(m.uScale) + " x " +
                           std::to_string(m.vScale) + ")",
                       std::to_string(f.header.uScale) + " x " + std::to_string(f.header.vScale));
    m.uScale = f.header.uScale;
    m.vScale = f.header.vScale;
    for (std::size_t i = 0; i < f.texels.size(); ++i)
      checkFinite(f.texels[i], dir.display(path), io::kMapHeaderSize + 8 * i,
                  "texel " + std::to_string(i) + " (u " +
                      std::to_string(i % static_cast<std::size_t>(f.header.uScale)) + ", v " +
                      std::to_string(i / static_cast<std::size_t>(f.header.uScale)) + ")");
    m.channel[c] = f.texels;
  }
  m.constant = true;
  for (const auto& ch : m.channel)
    for (double t : ch) m.constant = m.constant && t == ch.front();
  return m;
}

}  // namespace

Scene loadScene(const io::SceneDir& dir) {
  Scene scene;
  scene.name = dir.root().filename().string();
  if (scene.name.empty() || scene.name == ".")
    scene.name = fs::absolute(dir.root()).lexically_normal().filename().string();

  // Databases are read through existingInput too: no symbolic links.
  const fs::path primPath = dir.existingInput("prim", "PrimFile", "prime trace");
  const io::PrimFile primFile =
      io::primFileFromBytes(io::readFileBytes(primPath.string()), dir.display(primPath));
  for (const auto& p : primFile.prims) {
    ScenePrim sp;
    sp.type = io::primType(p.type).value_or(io::PrimType::Sphere);  // see ScenePrim::type
    sp.transform = p.transform;
    sp.inverse = p.inverse;
    for (int s = 0; s < io::kMaxSurface; ++s) sp.map[s] = {p.map[s][0], p.map[s][1]};
    sp.priority = p.priority;
    scene.prims.push_back(sp);
  }

  const fs::path listPath = dir.existingInput("obj", "List", "prime trace");
  const io::ObjList list =
      io::objListFromBytes(io::readFileBytes(listPath.string()), dir.display(listPath));
  for (int number : list.objects)
    scene.objects.push_back(loadObject(dir, number, primFile.prims, dir.display(listPath)));
  std::set<int> used;  // every primitive an object traces (leaf or bound)
  for (const auto& obj : scene.objects) {
    if (obj.boundPrim >= 0) used.insert(obj.boundPrim);
    for (const auto& e : obj.entries)
      if (e.op == 'P') used.insert(e.l);
  }
  for (int n : used)
    checkPrimMatrices(primFile.prims[static_cast<std::size_t>(n)], n, primFile.layout,
                      dir.display(primPath));

  // Every map that a primitive of a listed object can read must exist.
  std::set<int> mapsNeeded;
  for (const auto& obj : scene.objects)
    for (const auto& e : obj.entries) {
      if (e.op != 'P') continue;
      const ScenePrim& p = scene.prims[e.l];
      for (int s = 0; s < io::surfaceCount(p.type); ++s)
        for (int side = 0; side < 2; ++side) {
          const int m = p.map[s][side];
          const fs::path r = dir.find("map", io::mapFileName(m, 0));  // M40
          if (m < 0 || !fs::exists(r))
            throw InputError({dir.display(dir.root() / "obj" / ("O" + std::to_string(obj.number))),
                              std::nullopt, std::nullopt},
                             primLabel(e.l, p) + " surface " + std::to_string(s) +
                                 (side ? " inside" : " outside") + " map",
                             "a map added by AddMap (map/" + io::mapFileName(m, 0) + ")",
                             "map " + std::to_string(m) + ", which does not exist");
          mapsNeeded.insert(m);
        }
    }
  for (int m : mapsNeeded) {
    if (static_cast<int>(scene.maps.size()) <= m) scene.maps.resize(m + 1);
    scene.maps[m] = loadMap(dir, m);
  }

  const fs::path lightPath = dir.existingInput("light", "light.txt", "prime trace");
  io::TextReader in = io::TextReader::open(lightPath.string(), dir.display(lightPath));
  const io::LightText light = io::parseLightText(in);
  scene.ambient = light.ambient;
  scene.lights = light.lights;
  return scene;
}

std::vector<std::string> staleDatabases(const io::SceneDir& dir) {
  std::vector<std::string> problems;
  // Found without regard to case, as the loader reads them (M40).
  const fs::path prim = dir.find("prim", "PrimFile"), list = dir.find("obj", "List");
  for (const auto& p : {prim, list})
    if (!fs::exists(p)) problems.push_back(dir.display(p) + " does not exist");
  if (!problems.empty()) return problems;
  const auto built = std::min(fs::last_write_time(prim), fs::last_write_time(list));
  for (const char* sub : {"", "prim", "bound", "obj", "obj/Copy", "map"}) {
    const fs::path d = dir.find(sub, ".");
    if (!fs::is_directory(d)) continue;
    for (const auto& e : fs::directory_iterator(d)) {
      const auto name = e.path().filename().string();
      std::string lowerName = name;
      for (char& c : lowerName) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      const bool input = e.is_regular_file() && lowerName.size() > 4 &&
                         lowerName.compare(lowerName.size() - 4, 4, ".txt") == 0;
      if (input && lowerName != "light.txt" && fs::last_write_time(e.path()) > built)
        problems.push_back(dir.display(e.path()) + " is newer than the databases");
    }
  }
  return problems;
}

std::vector<std::string> sharedSubtreeWarnings(const Scene& scene) {
  std::vector<std::string> out;
  const std::size_t budget = Csg1991Options{}.maxVisits;
  for (const SceneObject& obj : scene.objects) {
    const std::optional<std::uint64_t> visits = csgExpandedVisits(obj.entries);
    if (!visits || *visits <= kLargeExpansion) continue;
    const bool capped = *visits >= CsgProgram1991::kExpansionCap;
    out.push_back("object " + std::to_string(obj.number) + " (obj/O" + std::to_string(obj.number) +
                  "): its " + std::to_string(obj.entries.size()) +
                  " CSG entries share subtrees; walked per reference they are " +
                  (capped ? std::string("over 2^62") : std::to_string(*visits)) +
                  " entry visits per ray. The modern profile evaluates each shared subtree once "
                  "per ray; the 1991 profile walks every reference as the listing did" +
                  (*visits > budget ? " and stops the render with an error (more than " +
                                          std::to_string(budget) + " visits)"
                                    : ", slowly"));
  }
  return out;
}

}  // namespace prime
