// stitch's Malone part: the PPM (P6) that --ppm writes, as rows.
#include <cctype>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "src/cli/malone/commands.h"

namespace prime::cli::malone {

namespace {

RowPicture readPpmRows(const std::string& path) {
  io::InputFileOptions options;
  options.what = "a PPM piece";
  options.maxBytes = std::uint64_t{1} << 34;
  const std::vector<std::uint8_t> bytes = io::readInputFile(path, options);
  // P6, width, height, maxval, each after white space, then one white space.
  std::size_t at = 0;
  int fields[3] = {0, 0, 0};
  auto bad = [&](const std::string& what) {
    throw io::InputError({path, std::nullopt, at}, "PPM header", what, "something else");
  };
  if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] != '6') bad("P6");
  at = 2;
  for (int& f : fields) {
    while (at < bytes.size() && std::isspace(bytes[at])) ++at;
    if (at >= bytes.size() || !std::isdigit(bytes[at])) bad("a number");
    while (at < bytes.size() && std::isdigit(bytes[at]) && f < 100000000)
      f = f * 10 + (bytes[at++] - '0');
  }
  if (at >= bytes.size() || !std::isspace(bytes[at]) || fields[2] != 255) bad("maxval 255");
  ++at;
  RowPicture p;
  p.head.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
  p.rowBytes = static_cast<std::size_t>(fields[0]) * 3;
  p.rows = fields[1];
  if (bytes.size() - at != p.rowBytes * static_cast<std::size_t>(p.rows))
    throw io::InputError({path, std::nullopt, bytes.size()}, "pixels",
                         std::to_string(p.rowBytes * static_cast<std::size_t>(p.rows)) + " bytes",
                         std::to_string(bytes.size() - at) + " bytes");
  p.pixels.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end());
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
