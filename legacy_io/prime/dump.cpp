#include "legacy_io/prime/dump.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "legacy_io/prime/graph_file.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/obj_list.h"
#include "legacy_io/prime/prim_file.h"

namespace prime::io {

std::optional<DatabaseKind> kindFromFileName(const std::string& path) {
  // Without regard to case (M40): a DOS disk's PRIMFILE, LIST, O1, MAP1_R.MAP.
  std::string name = std::filesystem::path(path).filename().string();
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (name == "primfile") return DatabaseKind::PrimFile;
  if (name == "list") return DatabaseKind::ObjList;
  // DOS keeps eight characters of a name without an extension: GRAPH_SC.
  if (name == "graph_scr" || name == "graph_sc") return DatabaseKind::GraphFile;
  // The names the docs give graph files written with --out, and an aborted
  // trace's .partial.
  const std::string ext = std::filesystem::path(name).extension().string();
  if (ext == ".scr" || ext == ".graph" || ext == ".gr" || ext == ".partial")
    return DatabaseKind::GraphFile;
  if (std::regex_match(name, std::regex("o[0-9]+"))) return DatabaseKind::ObjFile;
  if (std::regex_match(name, std::regex("map[0-9]+_[rgb]\\.map"))) return DatabaseKind::MapFile;
  return std::nullopt;
}

std::optional<DatabaseKind> kindFromName(const std::string& word) {
  if (word == "prim") return DatabaseKind::PrimFile;
  if (word == "obj") return DatabaseKind::ObjFile;
  if (word == "list") return DatabaseKind::ObjList;
  if (word == "map") return DatabaseKind::MapFile;
  if (word == "graph") return DatabaseKind::GraphFile;
  return std::nullopt;
}

static std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

static void matrix(std::ostringstream& os, const char* name, const Matrix4& m) {
  os << "    " << name << ":\n";
  for (const auto& row : m) {
    os << "      [";
    for (int j = 0; j < 4; ++j) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%14.8g", row[j]);
      os << buf << (j < 3 ? " " : "");
    }
    os << "]\n";
  }
}

static std::string dumpPrims(const std::string& path) {
  const PrimFile f = readPrimFile(path);
  std::ostringstream os;
  os << path << ": PrimFile, " << f.prims.size() << " record(s), "
     << (f.layout == PrimLayout::Packed ? "byte-packed (291 bytes each)"
                                        : "word-aligned (292 bytes each, Turbo C -a)")
     << "\n";
  for (std::size_t i = 0; i < f.prims.size(); ++i) {
    const auto& p = f.prims[i];
    os << "prim " << i << ": type '" << (p.type >= 32 && p.type < 127 ? p.type : '?') << "' ("
       << primTypeName(p.type) << "), priority " << p.priority << ", indx " << num(p.indx) << "\n";
    os << "    maps (out/in):";
    for (int s = 0; s < kMaxSurface; ++s) os << " " << p.map[s][kOut] << "/" << p.map[s][kIn];
    os << "   (" << surfaceCount(p.type) << " surface(s) used)\n";
    matrix(os, "transform", p.transform);
    matrix(os, "inverse", p.inverse);
  }
  return os.str();
}

static std::string opcodeText(const ObjRecord& e) {
  std::string s;
  for (char c : e.opCode) {
    if (c == 0) break;
    s += (c >= 32 && c < 127) ? c : '?';
  }
  return s;
}

static std::string dumpObj(const std::string& path) {
  const ObjFile f = readObjFile(path);
  std::ostringstream os;
  const Hue& h = f.header.hue;
  os << path << ": object file, " << f.header.numEntries << " entr"
     << (f.header.numEntries == 1 ? "y" : "ies") << ", bounding volume "
     << (f.header.boundVol == -1 ? std::string("none")
                                 : "prim " + std::to_string(f.header.boundVol))
     << "\n";
  os << "hue: kDR " << num(h.kDR) << "  kDT " << num(h.kDT) << "  fDR " << num(h.fDR[0]) << " "
     << num(h.fDR[1]) << " " << num(h.fDR[2]) << "  tT " << num(h.tT) << "  kRH " << num(h.kRH)
     << "  kTH " << num(h.kTH) << "  indx " << num(h.indx) << "\n";
  os << "entries:\n";
  for (std::size_t i = 0; i < f.entries.size(); ++i) {
    const auto& e = f.entries[i];
    os << "  " << i << ": '" << opcodeText(e) << "' l " << e.l << " r " << e.r << "\n";
  }
  os << "CSG tree:\n";
  // Depth first with an explicit stack (a chain of 32767 entries must not
  // overflow the call stack). An operator entry reached a second time (the
  // tree is a DAG) is shown once, then named: printing it again for every
  // path to it would take time exponential in the file's size.
  const int n = static_cast<int>(f.entries.size());
  std::vector<char> onPath(f.entries.size(), 0), shown(f.entries.size(), 0);
  struct Frame {
    int entry, depth, childrenPushed;
  };
  std::vector<Frame> stack;
  if (n > 0) stack.push_back({0, 0, -1});
  while (!stack.empty()) {
    Frame& fr = stack.back();
    const int i = fr.entry, depth = fr.depth;
    if (fr.childrenPushed >= 0) {  // an operator whose line is printed
      const auto& e = f.entries[i];
      if (fr.childrenPushed < 2) {
        const int child = fr.childrenPushed++ == 0 ? e.l : e.r;
        stack.push_back({child, depth + 1, -1});
      } else {
        onPath[i] = 0;
        stack.pop_back();
      }
      continue;
    }
    stack.pop_back();
    // Indentation shows the depth; past 32 levels the depth is written instead.
    if (depth <= 32)
      os << std::string(2 + 2 * depth, ' ');
    else
      os << std::string(2 + 2 * 32, ' ') << "(depth " << depth << ") ";
    if (i < 0 || i >= n) {
      os << "<entry " << i << " out of range>\n";
      continue;
    }
    const auto& e = f.entries[i];
    const char op = e.op();
    if (op == 'P') {
      os << "prim " << e.l << "\n";
      continue;
    }
    if (onPath[i]) {
      os << "<cycle back to entry " << i << ">\n";
      continue;
    }
    const char* name = op == '+'   ? "union"
                       : op == '-' ? "difference"
                       : op == '&' ? "intersection"
                                   : nullptr;
    if (!name) {
      os << "'" << opcodeText(e) << "' (not an operator) l " << e.l << " r " << e.r << "\n";
      continue;
    }
    if (shown[i]) {
      os << name << " (" << op << "): entry " << i << ", shown above\n";
      continue;
    }
    os << name << " (" << op << ")\n";
    onPath[i] = shown[i] = 1;
    stack.push_back({i, depth, 0});
  }
  return os.str();
}

static std::string dumpList(const std::string& path) {
  const ObjList f = readObjList(path);
  std::ostringstream os;
  os << path << ": object list, " << f.objects.size() << " object(s):";
  for (auto n : f.objects) os << " " << n;
  os << "\n";
  return os.str();
}

static std::string dumpMap(const std::string& path, int maxRows) {
  const MapFile f = readMapFile(path);
  std::ostringstream os;
  os << path << ": texture map channel, " << f.header.uScale << " x " << f.header.vScale
     << " texels (u across, v down; texel (u,v) at index u + uScale*v)\n";
  const auto [lo, hi] = std::minmax_element(f.texels.begin(), f.texels.end());
  os << "range: " << num(*lo) << " .. " << num(*hi) << "\n";
  for (int v = 0; v < std::min<int>(f.header.vScale, maxRows); ++v) {
    os << "  v " << v << ":";
    for (int u = 0; u < std::min<int>(f.header.uScale, 16); ++u)
      os << " " << num(f.texels[u + f.header.uScale * v]);
    if (f.header.uScale > 16) os << " ...";
    os << "\n";
  }
  if (f.header.vScale > maxRows) os << "  ... (" << f.header.vScale - maxRows << " more rows)\n";
  return os.str();
}

static std::string dumpGraph(const std::string& path, int maxRows) {
  const GraphFile f = readGraphFile(path);
  std::ostringstream os;
  os << path << ": graph file, graphType " << f.graphType
     << (f.graphType == 1   ? " (IBM8514HI)"
         : f.graphType == 0 ? " (VGA/DETECT)"
                            : "")
     << ", header " << f.numPixAcross << " x " << f.numPixDown << ", " << f.width() << " x "
     << f.height() << " pixels stored"
     << (f.inclusive ? " (the listing's inclusive loops: one more each way than the header)"
                     : " (exact)")
     << "\n";
  std::map<int, long> histogram;
  for (auto p : f.pixels) ++histogram[p];
  os << "distinct indices: " << histogram.size() << "\n";
  std::vector<std::pair<long, int>> byCount;
  for (auto [idx, n] : histogram) byCount.emplace_back(n, idx);
  std::sort(byCount.rbegin(), byCount.rend());
  os << "most used:";
  for (std::size_t i = 0; i < std::min<std::size_t>(byCount.size(), 12); ++i)
    os << " " << byCount[i].second << "(" << byCount[i].first << ")";
  os << "\n";
  for (int y = 0; y < std::min(f.height(), maxRows); ++y) {
    os << "  row " << y << ":";
    for (int x = 0; x < std::min(f.width(), 24); ++x) os << " " << f.at(x, y);
    if (f.width() > 24) os << " ...";
    os << "\n";
  }
  return os.str();
}

std::string dumpDatabase(const std::string& path, DatabaseKind kind, int maxRows) {
  switch (kind) {
    case DatabaseKind::PrimFile:
      return dumpPrims(path);
    case DatabaseKind::ObjFile:
      return dumpObj(path);
    case DatabaseKind::ObjList:
      return dumpList(path);
    case DatabaseKind::MapFile:
      return dumpMap(path, maxRows);
    case DatabaseKind::GraphFile:
      return dumpGraph(path, maxRows);
  }
  return {};
}

}  // namespace prime::io
