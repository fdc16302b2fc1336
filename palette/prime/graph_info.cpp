#include "palette/prime/graph_info.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <new>
#include <sstream>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"

namespace prime {

std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes, std::uint64_t h) {
  for (std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

const char* graphHashName(GraphHashKind kind) {
  return kind == GraphHashKind::Xxh3_64 ? "xxh3-64" : "fnv1a64";
}

std::uint64_t graphHash(GraphHashKind kind, std::span<const std::uint8_t> bytes) {
  if (kind == GraphHashKind::Fnv1a64) return fnv1a64(bytes);
  return io::xxh3(bytes.data(), bytes.size());
}

std::string graphInfoPath(const std::string& graphPath) {
  return graphPath + ".info";
}

std::string formatGraphInfo(const GraphInfo& info) {
  std::ostringstream s;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(info.graphHash));
  s << "prime-graph-info 1\n"
    << "# beside a graph file: how prime view and prime export show it "
       "(docs/prime/file-formats.md)\n"
    << "graph " << info.graphBytes << " " << graphHashName(info.hashKind) << " " << hash << "\n"
    << "profile " << info.profile << "\n"
    << "screen " << info.screenWidth << " " << info.screenHeight << "\n"
    << "at " << info.at.left << " " << info.at.top << "\n";
  if (!info.inline_) {
    s << "palette " << info.palette.name << "\n";
  } else {
    s << "palette inline " << info.palette.description << "\n";
    for (std::size_t i = 0; i < info.palette.dac.size(); ++i) {
      const Dac6& e = info.palette.dac[i];
      s << "dac " << i << " " << int{e.r} << " " << int{e.g} << " " << int{e.b} << "\n";
    }
  }
  for (const auto& [key, value] : info.text) s << "text " << key << ": " << value << "\n";
  return s.str();
}

namespace {

std::vector<std::string> words(std::string_view line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) out.emplace_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

template <class T>
T number(const std::string& word, T lo, T hi, const io::InputLocation& where,
         const std::string& field, int base = 10) {
  T v{};
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v, base);
  if (ec != std::errc() || end != word.data() + word.size() || v < lo || v > hi)
    throw io::InputError(where, field,
                         "an integer " + std::to_string(lo) + ".." + std::to_string(hi),
                         "'" + word + "'");
  return v;
}

}  // namespace

GraphInfo parseGraphInfo(std::string_view text, const std::string& fileName) {
  GraphInfo info;
  bool seen[5] = {false, false, false, false, false};  // graph profile screen at palette
  int dacLines = 0;
  int lineNo = 0;
  bool header = false;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (header && line.substr(0, 5) == "text ") {  // taken whole, '#' included
      const std::size_t colon = line.find(": ", 5);
      if (colon == std::string_view::npos || colon == 5)
        throw io::InputError({fileName, lineNo}, "text", "'text KEYWORD: VALUE'",
                             "'" + std::string(line) + "'");
      info.text.emplace_back(std::string(line.substr(5, colon - 5)),
                             std::string(line.substr(colon + 2)));
      if (pos > text.size()) break;
      continue;
    }
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    const std::vector<std::string> w = words(line);
    if (w.empty()) {
      if (pos > text.size()) break;
      continue;
    }
    const io::InputLocation at{fileName, lineNo};
    if (!header) {
      if (w.size() != 2 || w[0] != "prime-graph-info" || w[1] != "1")
        throw io::InputError(at, "first line", "'prime-graph-info 1'",
                             "'" + std::string(line) + "'");
      header = true;
      continue;
    }
    const auto count = [&](std::size_t n, const char* form) {
      if (w.size() != n)
        throw io::InputError(at, w[0], std::string("'") + form + "'",
                             std::to_string(w.size() - 1) + " values");
    };
    const auto once = [&](int k) {
      if (seen[k])
        throw io::InputError(at, w[0], "at most one '" + w[0] + "' line", "a second one");
      seen[k] = true;
    };
    if (w[0] == "graph") {
      once(0);
      count(4, "graph BYTES xxh3-64 HASH");
      info.graphBytes = number<std::uint64_t>(w[1], 0, ~0ull, at, "graph size");
      if (w[2] == "xxh3-64")
        info.hashKind = GraphHashKind::Xxh3_64;
      else if (w[2] == "fnv1a64")  // the companions written before G12
        info.hashKind = GraphHashKind::Fnv1a64;
      else
        throw io::InputError(at, "graph hash", "'xxh3-64' or 'fnv1a64'", "'" + w[2] + "'");
      if (w[3].size() != 16)
        throw io::InputError(at, "graph hash", "16 hexadecimal digits", "'" + w[3] + "'");
      info.graphHash = number<std::uint64_t>(w[3], 0, ~0ull, at, "graph hash", 16);
    } else if (w[0] == "profile") {
      once(1);
      count(2, "profile NAME");
      info.profile = w[1];
    } else if (w[0] == "screen") {
      once(2);
      count(3, "screen WIDTH HEIGHT");
      info.screenWidth = number<int>(w[1], 1, 16384, at, "screen width");
      info.screenHeight = number<int>(w[2], 1, 16384, at, "screen height");
    } else if (w[0] == "at") {
      once(3);
      count(3, "at X Y");
      info.at.left = number<int>(w[1], -16384, 16384, at, "at x");
      info.at.top = number<int>(w[2], -16384, 16384, at, "at y");
    } else if (w[0] == "palette") {
      once(4);
      if (w.size() < 2)
        throw io::InputError(at, "palette", "a palette name or 'inline'", "nothing");
      if (w[1] == "inline") {
        info.inline_ = true;
        std::string description;
        for (std::size_t i = 2; i < w.size(); ++i) description += (i > 2 ? " " : "") + w[i];
        info.palette.name = fileName;
        info.palette.description = description;
      } else {
        count(2, "palette NAME");
        const std::optional<Palette> p = findBuiltinPalette(w[1]);
        if (!p)
          throw io::InputError(at, "palette", "listing, plate3, vga or inline", "'" + w[1] + "'");
        info.palette = *p;
      }
    } else if (w[0] == "dac") {
      if (!info.inline_)
        throw io::InputError(at, "dac", "dac lines only after 'palette inline'", "'dac'");
      count(5, "dac INDEX R G B");
      const int index = number<int>(w[1], 0, 255, at, "dac index");
      if (index != dacLines)
        throw io::InputError(at, "dac index", "entry " + std::to_string(dacLines) + " (in order)",
                             std::to_string(index));
      Dac6& e = info.palette.dac[static_cast<std::size_t>(index)];
      e.r = number<std::uint8_t>(w[2], 0, 63, at, "dac red");
      e.g = number<std::uint8_t>(w[3], 0, 63, at, "dac green");
      e.b = number<std::uint8_t>(w[4], 0, 63, at, "dac blue");
      ++dacLines;
    } else {
      throw io::InputError(at, "keyword", "graph, profile, screen, at, palette, dac or text",
                           "'" + w[0] + "'");
    }
    if (pos > text.size()) break;
  }
  const io::InputLocation whole{fileName};
  if (!header) throw io::InputError(whole, "first line", "'prime-graph-info 1'", "an empty file");
  const char* names[5] = {"graph", "profile", "screen", "at", "palette"};
  for (int k = 0; k < 5; ++k)
    if (!seen[k])
      throw io::InputError(whole, names[k], std::string("a '") + names[k] + "' line", "none");
  if (info.inline_ && dacLines != 256)
    throw io::InputError(whole, "dac", "256 dac lines after 'palette inline'",
                         std::to_string(dacLines));
  return info;
}

void writeGraphInfo(const std::string& path, const GraphInfo& info) {
  io::OutputFile out(path);
  out.write(formatGraphInfo(info));
  out.commit();
}

FoundGraphInfo findGraphInfo(const std::string& graphPath,
                             std::span<const std::uint8_t> graphBytes) {
  FoundGraphInfo found;
  const std::string path = graphInfoPath(graphPath);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return found;
  const std::string text = io::readInputText(path, {1u << 20, "a graph file's companion", ""});
  GraphInfo info = parseGraphInfo(text, path);
  if (info.graphBytes != graphBytes.size() ||
      info.graphHash != graphHash(info.hashKind, graphBytes)) {
    found.stale = path + " describes another graph file (size or hash differ): ignored";
    return found;
  }
  found.info = std::move(info);
  return found;
}

}  // namespace prime
