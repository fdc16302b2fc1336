// The graph file's companion (docs/prime/file-formats.md, G7-G11): a small
// text file beside every graph file the port writes, `graph_scr.info` beside
// `graph_scr` (the graph file's name plus ".info"), recording what the graph
// file cannot: the screen and the place the picture was drawn at, the palette
// its indices mean (a built-in name, or the 256 DAC entries of a quantized
// render), the profile, and the graph file's size and hash (XXH3, 64 bits;
// FNV-1a in companions written before G12) so that a companion left beside
// another graph file is recognised. The graph file itself stays byte-exact.
//
//   prime-graph-info 1
//   graph 537606 xxh3-64 8f3c0d1e2a4b5c6d
//   profile 1991
//   screen 1024 768
//   at 675 0
//   palette listing                      or: palette inline DESCRIPTION...
//   dac 0 0 0 0                          with `inline` only: 256 lines
//   ...                                  INDEX R G B, 0..63, in index order
//   text Software: prime 1.0.0           what made the picture: the PNGs'
//   text Scene: plate2                   tEXt chunks, KEYWORD: VALUE, one a
//   ...                                  line, taken whole ('#' included)
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "legacy_io/common/digest.h"
#include "palette/prime/palettes.h"
#include "palette/prime/screen.h"

namespace prime {

// The hash a companion records of its graph file's bytes (G7, G12): XXH3
// (64 bits, seed 0, libxxhash) is written; FNV-1a (64 bits), which the port
// wrote before, is still read.
enum class GraphHashKind { Xxh3_64, Fnv1a64 };
const char* graphHashName(GraphHashKind kind);  // "xxh3-64", "fnv1a64": the file's word
std::uint64_t graphHash(GraphHashKind kind, std::span<const std::uint8_t> bytes);

// XXH3 (64 bits, seed 0) of bytes handed over piece by piece, in order: the
// same as graphHash(Xxh3_64, all of them). The shared core's.
using Xxh3Stream = io::Xxh3Stream;

struct GraphInfo {
  std::uint64_t graphBytes = 0;  // the graph file's size
  GraphHashKind hashKind = GraphHashKind::Xxh3_64;
  std::uint64_t graphHash = 0;   // of its bytes, by hashKind
  std::string profile = "1991";  // one word
  int screenWidth = Screen::kWidth, screenHeight = Screen::kHeight;
  Placement at;
  Palette palette;       // name: a built-in name, or the inline table's description
  bool inline_ = false;  // the DAC entries are in the file (a quantized render)
  // What made the picture (the render's provenance; none in older files).
  std::vector<std::pair<std::string, std::string>> text;
};

// FNV-1a, 64 bits. `h` continues a hash: fnv1a64(b, fnv1a64(a)) is the hash
// of a followed by b.
inline constexpr std::uint64_t kFnv1a64Offset = 0xcbf29ce484222325ull;
std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes, std::uint64_t h = kFnv1a64Offset);
std::string graphInfoPath(const std::string& graphPath);  // graphPath + ".info"

std::string formatGraphInfo(const GraphInfo& info);
// Every mistake is an io::InputError naming the file, the line and the field.
GraphInfo parseGraphInfo(std::string_view text, const std::string& fileName);
// Written through io::OutputFile (a temporary renamed into place).
void writeGraphInfo(const std::string& path, const GraphInfo& info);

// What `prime view` and `prime export` find beside a graph file: nothing
// (no companion), or the companion if it describes these bytes. A companion
// that describes other bytes (a graph file replaced by another program) is
// ignored with a warning in `stale`; a damaged one is an io::InputError.
struct FoundGraphInfo {
  std::optional<GraphInfo> info;
  std::string stale;  // non-empty: why the companion there was not used
};
FoundGraphInfo findGraphInfo(const std::string& graphPath,
                             std::span<const std::uint8_t> graphBytes);

}  // namespace prime
