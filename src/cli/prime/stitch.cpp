// stitch's PRIME part: the graph file (--out) as rows of 16-bit indices,
// written with its companion (G7), whose settings come from a piece's.
#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/prime/graph_file.h"
#include "palette/prime/graph_info.h"
#include "src/cli/prime/commands.h"

namespace prime::cli {

namespace {

RowPicture readGraphRows(const std::string& path) {
  io::InputFileOptions options;
  options.what = "a graph file";
  options.maxBytes = std::uint64_t{1} << 32;
  const std::vector<std::uint8_t> bytes = io::readInputFile(path, options);
  const io::GraphFile g = io::graphFileFromBytes(bytes, path);  // checks it whole
  RowPicture p;
  p.head.assign(bytes.begin(), bytes.begin() + 6);  // graphType, numPixAcross, numPixDown
  p.rowBytes = static_cast<std::size_t>(g.width()) * 2;
  p.rows = g.height();
  p.pixels.assign(bytes.begin() + 6, bytes.end());
  return p;
}

void writeGraphRows(const std::string& path, const RowPicture& p, const std::string& piece) {
  // The companion: the piece's, describing the stitched bytes.
  io::InputFileOptions options;
  options.what = "a graph file's companion";
  const std::string infoPath = graphInfoPath(piece);
  GraphInfo info = parseGraphInfo(io::readInputText(infoPath, options), infoPath);
  std::vector<std::uint8_t> bytes = p.head;
  bytes.insert(bytes.end(), p.pixels.begin(), p.pixels.end());
  info.graphBytes = bytes.size();
  info.graphHash = graphHash(info.hashKind, bytes);
  io::OutputFile out(path);
  out.write(bytes);
  out.commit();
  writeGraphInfo(graphInfoPath(path), info);
}

constexpr PieceKind kGraph{readGraphRows, writeGraphRows};

}  // namespace

const PieceKind* pieceKind(const std::string& output) {
  return output == "--out" ? &kGraph : nullptr;
}

}  // namespace prime::cli
