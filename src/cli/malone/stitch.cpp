// stitch's Malone part: the PPM (P6) that --ppm writes, as rows, read and
// written by Malone's own PPM code (legacy_io/malone/ppm.h): its bytes are
// exact (a byte b read as b / 255 is written back as b).
#include "legacy_io/common/output_file.h"
#include "legacy_io/malone/ppm.h"
#include "src/cli/malone/commands.h"

namespace prime::cli::malone {

namespace {

RowPicture readPpmRows(const std::string& path) {
  const RgbImage raster = prime::malone::readPpm(path);
  // The header ppmBytes writes, then the rows: the header is what is left
  // before width x height x 3 bytes.
  const std::vector<std::uint8_t> bytes = prime::malone::ppmBytes(raster);
  RowPicture p;
  p.rowBytes = static_cast<std::size_t>(raster.width) * 3;
  p.rows = raster.height;
  const std::size_t head = bytes.size() - p.rowBytes * static_cast<std::size_t>(p.rows);
  p.head.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(head));
  p.pixels.assign(bytes.begin() + static_cast<std::ptrdiff_t>(head), bytes.end());
  return p;
}

void writePpmRows(const std::string& path, const RowPicture& p, const std::string&) {
  io::OutputFile out(path);
  out.write(p.head);
  out.write(p.pixels);
  out.commit();
}

constexpr PieceKind kPpm{readPpmRows, writePpmRows};

}  // namespace

const PieceKind* pieceKind(const std::string& output) {
  return output == "--ppm" ? &kPpm : nullptr;
}

}  // namespace prime::cli::malone
