// stitch's CGL part: the RLE (--rle) and raw (--raw) frames, as rows of
// 512 words from the top.
#include <cstring>

#include "legacy_io/cgl/frame.h"
#include "src/cli/cgl/commands.h"

namespace prime::cli::cgl {

namespace {

using prime::cgl::Frame;

RowPicture rowsOf(const Frame& f) {
  RowPicture p;
  p.rowBytes = Frame::kSize * sizeof(std::uint32_t);
  p.rows = Frame::kSize;
  p.pixels.resize(p.rowBytes * Frame::kSize);
  std::memcpy(p.pixels.data(), f.words.data(), p.pixels.size());  // top scanline first
  return p;
}

Frame frameOf(const RowPicture& p) {
  Frame f;
  std::memcpy(f.words.data(), p.pixels.data(), p.pixels.size());
  return f;
}

RowPicture readRle(const std::string& path) {
  return rowsOf(prime::cgl::readRleFile(path));
}
void writeRle(const std::string& path, const RowPicture& p, const std::string&) {
  prime::cgl::writeRleFile(path, frameOf(p));
}
RowPicture readRaw(const std::string& path) {
  return rowsOf(prime::cgl::readRawFile(path));
}
void writeRaw(const std::string& path, const RowPicture& p, const std::string&) {
  prime::cgl::writeRawFile(path, frameOf(p));
}

constexpr PieceKind kRle{readRle, writeRle};
constexpr PieceKind kRaw{readRaw, writeRaw};

}  // namespace

const PieceKind* pieceKind(const std::string& output) {
  if (output == "--rle") return &kRle;
  if (output == "--raw") return &kRaw;
  return nullptr;
}

}  // namespace prime::cli::cgl
